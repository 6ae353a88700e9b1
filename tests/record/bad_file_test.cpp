// Specification of a recording as untrusted input: every malformed, truncated, tampered or
// hostile file gets a tv::Error naming the byte offset, the frame and what is wrong — never a
// crash, never an allocation the file's size does not justify.

#include <zlib.h>

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <bit>
#include <filesystem>
#include <fstream>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "recording_kit.hpp"
#include "tv/error.hpp"
#include "tv/record/recorder.hpp"
#include "tv/record/replay.hpp"

namespace {

using Bytes = std::vector<std::uint8_t>;

// -- writing files by hand -------------------------------------------------------------------

void varint(Bytes& b, std::uint64_t v) {
  while (v >= 0x80) {
    b.push_back(static_cast<std::uint8_t>(v | 0x80));
    v >>= 7;
  }
  b.push_back(static_cast<std::uint8_t>(v));
}
void f64(Bytes& b, double v) {
  const auto u = std::bit_cast<std::uint64_t>(v);
  for (int i = 0; i < 8; ++i) b.push_back(static_cast<std::uint8_t>(u >> (8 * i)));
}
void str(Bytes& b, const std::string& s) {
  varint(b, s.size());
  b.insert(b.end(), s.begin(), s.end());
}

Bytes header(double cellSize = 16.0, std::uint16_t major = 1) {
  Bytes b = {'T', 'V', 'R', 'E', 'C', 0, '\r', '\n'};
  b.push_back(static_cast<std::uint8_t>(major));
  b.push_back(0);
  b.push_back(0);
  b.push_back(0);
  f64(b, cellSize);
  b.insert(b.end(), {64, 0, 0, 0, 0, 0, 0, 0});
  const auto crc = static_cast<std::uint32_t>(::crc32(0, b.data(), 28));
  for (int i = 0; i < 4; ++i) b.push_back(static_cast<std::uint8_t>(crc >> (8 * i)));
  return b;
}

void chunk(Bytes& file, const Bytes& payload) {
  const auto len = static_cast<std::uint32_t>(payload.size());
  const auto crc = static_cast<std::uint32_t>(::crc32(0, payload.data(), len));
  for (int i = 0; i < 4; ++i) file.push_back(static_cast<std::uint8_t>(len >> (8 * i)));
  for (int i = 0; i < 4; ++i) file.push_back(static_cast<std::uint8_t>(crc >> (8 * i)));
  file.insert(file.end(), payload.begin(), payload.end());
}

// Frame 0's payload opening: frame number, keyframe flag, a world of `rects` (each sent as four
// raw doubles), no free slots.
Bytes keyframe(const std::vector<tv::Rect>& rects, double cellSize = 16.0) {
  Bytes p;
  varint(p, 0);
  p.push_back(1);
  f64(p, cellSize);
  varint(p, rects.size());
  varint(p, rects.size());  // next add order
  varint(p, 4);
  for (const char* n : {"touch", "cross", "slide", "bounce"}) str(p, n);
  std::uint64_t order = 0;
  for (const tv::Rect& r : rects) {
    p.push_back(1);                 // alive, generation 0
    varint(p, order == 0 ? 0 : 2);  // zigzag(+1) after the first
    ++order;
    p.push_back(0xFF);  // four raw doubles
    f64(p, r.x);
    f64(p, r.y);
    f64(p, r.w);
    f64(p, r.h);
  }
  varint(p, 0);
  return p;
}

Bytes fileWith(const Bytes& frame0, const Bytes& frame1 = {}) {
  Bytes f = header();
  chunk(f, frame0);
  if (!frame1.empty()) chunk(f, frame1);
  f.insert(f.end(), {0, 0, 0, 0, 0x45, 0x4E, 0x44, 0x21});
  return f;
}

Bytes frame1(std::initializer_list<std::uint8_t> calls) {
  Bytes p;
  varint(p, 1);
  p.push_back(0);
  p.insert(p.end(), calls);
  return p;
}

// The error, opening and then validating (a file may be well-formed and still lie).
std::string errorOf(const Bytes& file, tv::ReplayOptions o = {}) {
  try {
    tv::Replay r = tv::Replay::fromBytes(file, o);
    (void)r.validate();
  } catch (const tv::Error& e) {
    return e.what();
  }
  return {};
}

#define EXPECT_ERROR(file, ...)                                                       \
  do {                                                                                \
    const std::string e = errorOf(file);                                              \
    for (const char* part : {__VA_ARGS__}) {                                          \
      EXPECT_NE(e.find(part), std::string::npos) << "'" << part << "' not in: " << e; \
    }                                                                                 \
  } while (0)

Bytes sample() {
  tvtest::Script s;
  s.framesToPlay = 8;
  return s.record();
}

// -- the specification ------------------------------------------------------------------------

TEST(BadFile, AHandMadeFileOfOneKeyframeOpens) {
  // The helpers below write valid files; each case then breaks one thing.
  const Bytes f = fileWith(keyframe({{0, 0, 16, 16}, {32, 0, 16, 16}}));
  EXPECT_EQ(errorOf(f), "");
  EXPECT_EQ(tv::Replay::fromBytes(f).world().count(), 2u);
}

TEST(BadFile, EmptyShortOrForeignFilesAreRefusedAtByteZero) {
  EXPECT_ERROR(Bytes{}, "byte 0", "shorter than the 32-byte header");
  EXPECT_ERROR(Bytes(31, 0), "byte 0", "shorter than the 32-byte header");
  Bytes png(64, 0);
  png[0] = 0x89;
  EXPECT_ERROR(png, "byte 0", "not a .tvrec file");
}

TEST(BadFile, AFutureVersionIsRefusedNamingIt) {
  Bytes f = header(16.0, 2);
  EXPECT_ERROR(f, "byte 8", "format version 2.0", "version 1.3");
}

TEST(BadFile, ABadHeaderChecksumOrCellSizeIsRefused) {
  Bytes f = fileWith(keyframe({}));
  f[13] ^= 1;  // cell size bits, without fixing the header CRC
  EXPECT_ERROR(f, "byte 28", "header checksum");
  Bytes nan = header(std::nan(""));
  EXPECT_ERROR(nan, "byte 12", "cell size nan");
}

TEST(BadFile, ABadChunkChecksumNamesTheChunkAndFrame) {
  Bytes f = sample();
  const std::vector<std::size_t> chunks = tvtest::chunks(f);
  ASSERT_GT(chunks.size(), 3u);
  f[chunks[2] + 12] ^= 0x40;
  const std::string at = "byte " + std::to_string(chunks[2]);
  EXPECT_ERROR(f, at.c_str(), "frame 2", "checksum mismatch");
  // Tolerant (the debugger): opens what is whole, says why it stopped.
  tv::ReplayOptions o;
  o.tolerant = true;
  tv::Replay r = tv::Replay::fromBytes(f, o);
  EXPECT_EQ(r.frames(), 2u);
  ASSERT_FALSE(r.warnings().empty());
  EXPECT_NE(r.warnings()[0].find("checksum mismatch"), std::string::npos);
  EXPECT_FALSE(r.validate());
  // A check of it covers frames 0..1 only, and the summary says where the damage is.
  EXPECT_EQ(r.summary().damagedAt, std::optional<std::uint64_t>(chunks[2]));
  EXPECT_EQ(r.summary().bytesRead, chunks[2]);
  EXPECT_FALSE(tv::Replay::fromBytes(sample()).summary().damagedAt);  // the whole file
}

TEST(BadFile, ATruncatedFileReplaysUpToItsLastWholeFrameWithAWarning) {
  const Bytes whole = sample();
  const std::vector<std::size_t> chunks = tvtest::chunks(whole);
  // Cut inside frame 5's chunk, as a game that crashed while writing it.
  const Bytes cut(whole.begin(), whole.begin() + static_cast<std::ptrdiff_t>(chunks[5] + 11));
  tv::Replay r = tv::Replay::fromBytes(cut);
  EXPECT_EQ(r.frames(), 5u);
  ASSERT_EQ(r.warnings().size(), 1u);
  EXPECT_NE(r.warnings()[0].find("frame 5"), std::string::npos) << r.warnings()[0];
  EXPECT_NE(r.warnings()[0].find("is cut"), std::string::npos) << r.warnings()[0];
  EXPECT_FALSE(r.validate());
  EXPECT_EQ(r.summary().damagedAt, std::optional<std::uint64_t>(chunks[5]));
  // Cut between chunks: no end mark, whole frames.
  const Bytes between(whole.begin(), whole.begin() + static_cast<std::ptrdiff_t>(chunks[5]));
  tv::Replay b = tv::Replay::fromBytes(between);
  EXPECT_EQ(b.frames(), 5u);
  ASSERT_EQ(b.warnings().size(), 1u);
  EXPECT_NE(b.warnings()[0].find("no end mark"), std::string::npos);
  EXPECT_FALSE(b.summary().damagedAt);  // nothing damaged: the game stopped without closing it
  // Nothing whole at all.
  const Bytes headerOnly(whole.begin(), whole.begin() + 32 + 5);
  EXPECT_ERROR(headerOnly, "no whole frame");
}

TEST(BadFile, BytesAfterTheEndMarkAreRefused) {
  Bytes f = fileWith(keyframe({}));
  f.push_back(7);
  EXPECT_ERROR(f, "1 bytes after the end mark");
}

TEST(BadFile, AnImpossibleCountIsRefusedBeforeAnythingIsAllocated) {
  // A keyframe claiming 10^12 slots in a chunk of a few dozen bytes.
  Bytes p;
  varint(p, 0);
  p.push_back(1);
  f64(p, 16.0);
  varint(p, 1000000000000ull);
  EXPECT_ERROR(fileWith(p), "frame 0", "keyframe slot count 1000000000000 is more than");
  // A found list of 2^40 items.
  Bytes q = frame1({7, 0});  // queryPoint at (P0 0, P0 0) ...
  varint(q, 1ull << 40);     // ... found count
  EXPECT_ERROR(fileWith(keyframe({}), q), "frame 1", "found count 1099511627776");
  // A chunk length of 2^31.
  Bytes huge = header();
  huge.insert(huge.end(), {0, 0, 0, 0x80, 0, 0, 0, 0});
  huge.resize(huge.size() + 128, 0);
  EXPECT_ERROR(huge, "byte 32", "chunk length 2147483648");
}

TEST(BadFile, NaNAndInfinityAreRefusedNamingTheField) {
  EXPECT_ERROR(fileWith(keyframe({{std::nan(""), 0, 16, 16}})), "frame 0", "slot rect is nan");
  EXPECT_ERROR(fileWith(keyframe({{0, 0, INFINITY, 16}})), "slot rect is inf");
  // An add whose x is -inf.
  Bytes a = frame1({0, 0xFF});
  f64(a, -INFINITY);
  EXPECT_ERROR(fileWith(keyframe({}), a), "frame 1", "add rect is -inf");
}

TEST(BadFile, AContactsCallWithAnUndefinedEventIsRefusedNamingIt) {
  // Two live items (slots 0 and 1); a contacts call of item 0 (kind 15, varint 0, item delta 0),
  // one event: its code byte, the other as a zigzag from item 0.
  const Bytes two = keyframe({{0, 0, 16, 16}, {16, 0, 16, 16}});
  EXPECT_ERROR(fileWith(two, frame1({0x0F, 0x00, 0x00, 0x01, 0x03, 0x02})), "frame 1",
               "contact event code 3 is not defined");
  EXPECT_ERROR(fileWith(two, frame1({0x0F, 0x00, 0x00, 0x01, 0x00, 0x00})),
               "a contact of an item with itself");
  // Slot 2 holds nothing: only an end may name an item no longer in the world.
  EXPECT_ERROR(fileWith(two, frame1({0x0F, 0x00, 0x00, 0x01, 0x40, 0x04, 0x00})),
               "not in the world that is not an end");
  EXPECT_ERROR(fileWith(two, frame1({0x0F, 0x00, 0x00, 0x01, 0x00, 0x04})), "contact other");
  EXPECT_ERROR(fileWith(two, frame1({0x0F, 0x00, 0x00, 0x7F})), "contact event count 127");
  EXPECT_EQ(errorOf(fileWith(two, frame1({0x0F, 0x00, 0x00, 0x01, 0x42, 0x04, 0x00}))), "")
      << "an end naming a removed item reads";
}

// A cornerNudge call by hand: body slot 0 {10, 40, 8, 12}, ceiling slot 1 {16, 0, 32, 8}; kind 15,
// varint 1, body delta 0, ceiling zigzag(+1), then a group: touch.y (code 0: the ceiling's
// bottom), touch.x and dx (code 3 each: raw doubles) — code byte 0x3C.
Bytes nudgeCall(double touchX, double dx, std::initializer_list<std::uint8_t> head = {0x0F, 0x01,
                                                                                     0x00, 0x02}) {
  Bytes p = frame1(head);
  p.push_back(0x3C);
  f64(p, touchX);
  f64(p, dx);
  return p;
}

TEST(BadFile, ACornerNudgeCallThatIsMalformedOrCutIsRefusedNamingWhere) {
  const Bytes world = keyframe({{10, 40, 8, 12}, {16, 0, 32, 8}});
  EXPECT_EQ(errorOf(fileWith(world, nudgeCall(10, -2))), "") << "the well-formed call reads";
  const tv::Replay r = tv::Replay::fromBytes(fileWith(world, nudgeCall(10, -2)));
  ASSERT_EQ(r.calls(1).size(), 1u);
  EXPECT_EQ(r.calls(1)[0].kind, tv::CallKind::cornerNudge);
  EXPECT_EQ(r.calls(1)[0].nudge.dx, -2.0);
  // Cut after each of its bytes from its kind on (the frame's own two bytes come first): the
  // missing part is named, in frame 1.
  const Bytes whole = nudgeCall(10, -2);
  for (std::size_t cut = 4; cut < whole.size(); ++cut) {
    const Bytes part(whole.begin(), whole.begin() + static_cast<std::ptrdiff_t>(cut));
    const std::string e = errorOf(fileWith(world, part));
    EXPECT_NE(e.find("frame 1"), std::string::npos) << cut << ": " << e;
    EXPECT_NE(e.find("cornerNudge"), std::string::npos) << cut << ": " << e;
  }
  EXPECT_ERROR(fileWith(world, nudgeCall(10, -2, {0x0F, 0x01, 0x00, 0x00})),
               "a corner nudge round the body itself");
  EXPECT_ERROR(fileWith(world, nudgeCall(10, -2, {0x0F, 0x01, 0x00, 0x04})), "frame 1",
               "cornerNudge ceiling: item index 2 was never issued");
  EXPECT_ERROR(fileWith(world, nudgeCall(10, -2, {0x0F, 0x01, 0x08, 0x02})),
               "cornerNudge body: item index 4 was never issued");
  EXPECT_ERROR(fileWith(world, nudgeCall(10, -2, {0x8F, 0x01, 0x00, 0x02})),
               "cornerNudge with undefined flags");
  EXPECT_ERROR(fileWith(world, nudgeCall(10, std::nan(""))), "frame 1", "cornerNudge is nan");
  EXPECT_ERROR(fileWith(world, nudgeCall(INFINITY, -2)), "cornerNudge is inf");
  EXPECT_ERROR(fileWith(world, nudgeCall(10, 0)), "dx 0", "no nudge");
  // Well-formed, but not what the world gives: a divergence at that call, not an error.
  tv::Replay lie = tv::Replay::fromBytes(fileWith(world, nudgeCall(10, -3)));
  const std::optional<tv::Divergence> d = lie.validate();
  ASSERT_TRUE(d);
  EXPECT_EQ(d->what, "corner nudge dx");
}

TEST(BadFile, UnknownCallKindsAndFlagsAreRefused) {
  const std::string at = "byte " + std::to_string(32 + 8 + keyframe({}).size() + 8 + 2);
  // Kinds from 15 on are 15 and a varint: 15 + 2 is beyond the list.
  EXPECT_ERROR(fileWith(keyframe({}), frame1({0x0F, 0x02})), "frame 1", at.c_str(),
               "unknown call kind 17");
  EXPECT_ERROR(fileWith(keyframe({}), frame1({0x87})), "queryPoint with undefined flags");
  Bytes frameFlags;
  varint(frameFlags, 1);
  frameFlags.push_back(6);
  EXPECT_ERROR(fileWith(keyframe({}), frameFlags), "frame flags 6");
}

TEST(BadFile, IdsThatWereNeverIssuedAreRefused) {
  const Bytes world = keyframe({{0, 0, 16, 16}});
  // remove item delta +40 (zigzag 80): slot 40 does not exist.
  EXPECT_ERROR(fileWith(world, frame1({1, 80})), "frame 1", "item index 40 was never issued");
  // remove item 0 twice: the second names a removed item.
  EXPECT_ERROR(fileWith(world, frame1({1 | 0x10, 1 | 0x10})), "is not in the world");
  // a negative index
  EXPECT_ERROR(fileWith(world, frame1({1, 1})), "item index -1 was never issued");
}

TEST(BadFile, ImpossibleRecordedResultsAreRefused) {
  const Bytes world = keyframe({{0, 0, 16, 16}, {32, 0, 16, 16}});
  // A move of item 0 (same as previous: index 0) with one collision against itself.
  //   kind move|same, goal group all P1 (stay), result group P0 P0, 1 collision, other delta 0
  EXPECT_ERROR(fileWith(world, frame1({3 | 0x10, 0x05, 0x00, 1, 0, 0, 0, 0, 0, 0, 0})),
               "collision of an item with itself");
  // ... against item 1 with ti = 5, not overlapping.
  Bytes p = frame1({3 | 0x10, 0x05, 0x00, 1, 2, 2 << 2});
  p.insert(p.end(), {0x00, 0xF0 /* move P0 P0, ti raw */});
  f64(p, 5.0);
  EXPECT_ERROR(fileWith(world, p), "collision ti 5 is outside [0, 1]");
  // A batch that moves one item twice.
  EXPECT_ERROR(fileWith(world, frame1({12, 2, 0, 0x05, 0, 0x05, 0, 0, 0, 0})),
               "batch moves item 0 twice");
  // A filter answer naming an unregistered response.
  EXPECT_ERROR(fileWith(world, frame1({9 | 0x20 | 0x80, 0, 0x00, 2, 5, 9, 2})),
               "answer response 9 is not registered");
}

TEST(BadFile, HostileHugeRectsAreRefusedByTheCellBudgetNotAllocated) {
  // 1000 rects of 4096 × 4096 cells each (2^24, the most one item may span): 1.6·10^10 cells,
  // terabytes of cell entries. Refused by counting, before any world is built.
  std::vector<tv::Rect> rects(1000, tv::Rect{0, 0, 4096 * 16.0 - 1, 4096 * 16.0 - 1});
  EXPECT_ERROR(fileWith(keyframe(rects)), "frame 0", "budget of 4194304 cells");
  // The same through adds: a small world, then add after add of the largest rect.
  Bytes adds = frame1({});
  for (int i = 0; i < 1000; ++i) {
    adds.push_back(0);
    adds.push_back(i == 0 ? 0xFF : 0x00);  // then "same as the previous add" (P0 x? no: P1)
    if (i == 0) {
      f64(adds, 0);
      f64(adds, 0);
      f64(adds, 4096 * 16.0 - 1);
      f64(adds, 4096 * 16.0 - 1);
    }
  }
  const std::string e = errorOf(fileWith(keyframe({}), adds));
  EXPECT_NE(e.find("add would register"), std::string::npos) << e;
}

TEST(BadFile, AMoveThatWouldWalkBillionsOfCellsIsRefusedNotReplayedForHours) {
  // A tampered goal 10^15 px away: a replay would walk 6·10^13 cells.
  Bytes p = frame1({3 | 0x10 | 0x40, 0x07});  // move item 0, free; goal x raw, y unchanged
  f64(p, 1e15);
  EXPECT_ERROR(fileWith(keyframe({{0, 0, 16, 16}}), p), "frame 1", "move would visit about",
               "cells");
}

TEST(BadFile, AMissingFileIsNamed) {
  try {
    (void)tv::Replay::open("/nonexistent/recording.tvrec");
    FAIL();
  } catch (const tv::Error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/recording.tvrec"), std::string::npos);
  }
}

// A folder or a pipe given where a recording goes: named and refused, never read by a size it
// does not have. Negative control: the naive read (open, seek to the end, allocate tellg()
// bytes) asks a directory for its size and gets 2^63 - 1, which threw std::bad_alloc.
std::string openError(const std::string& path) {
  try {
    (void)tv::Replay::open(path);
  } catch (const tv::Error& e) {
    return e.what();
  }
  return "(opened)";
}

std::filesystem::path scratch(const char* name) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("tv-bad-file-" + std::to_string(::getpid()) + "-" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

TEST(BadFile, ADirectoryIsRefusedNamingItNotReadByItsSize) {
  const auto dir = scratch("dir");
  const auto named = dir / "adir.tvrec";  // a folder with a recording's name
  std::filesystem::create_directory(named);
  for (const std::string& path : {dir.string(), named.string()}) {
    const std::string e = openError(path);
    EXPECT_NE(e.find("cannot open '" + path + "': is a directory, not a recording"),
              std::string::npos)
        << e;
  }
  // The naive way: a directory opens as a stream and reports an impossible size.
  std::ifstream naive(named, std::ios::binary | std::ios::ate);
  if (naive) {
    EXPECT_TRUE(naive.tellg() < 0 || naive.tellg() > std::streamoff{1} << 40)
        << "a directory's size was " << naive.tellg();
  }
  std::filesystem::remove_all(dir);
}

TEST(BadFile, APipeIsRefusedNamingItRatherThanWaitedOn) {
  const auto dir = scratch("fifo");
  const std::string fifo = (dir / "game.tvrec").string();
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  // Nobody writes to it: an open for reading would block for ever.
  const std::string e = openError(fifo);
  EXPECT_NE(e.find("cannot open '" + fifo + "': a pipe (FIFO), not a recording file"),
            std::string::npos)
      << e;
  std::filesystem::remove_all(dir);
}

}  // namespace
