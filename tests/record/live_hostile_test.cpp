// Specification of a receiver facing hostile peers. A live stream is untrusted bytes, as a file
// is: whatever a peer sends — not a game's hello, a tampered header, a bad checksum, a chunk
// that claims 2 GB, a chunk cut and then silence, nothing at all, bytes after the end, a flood —
// the receiver says what was wrong (a `refused` event), closes the connection, keeps no more
// than its bounds, and takes the next game as if nothing had happened.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "live_kit.hpp"
#include "recording_kit.hpp"
#include "tv/record/live.hpp"
#include "tv/record/recorder.hpp"
#include "tv/record/replay.hpp"

namespace {

using Bytes = std::vector<std::uint8_t>;
using tvtest::eventually;

// A small recording: a box dropped onto a floor, `frames` frames.
Bytes recording(int frames) {
  tv::World w(8);
  tv::Recorder rec(tv::RecorderOptions{8});
  w.add({0, 64, 256, 8});
  w.attach(rec);
  const tv::ItemId box = w.add({0, 0, 4, 4});
  rec.label(box, "box", "crate");
  for (int f = 0; f < frames; ++f) {
    (void)w.move(box, w.rect(box).position() + tv::Vec2{0.75, 1.5});
    rec.frame();
  }
  w.detach();
  return rec.bytes();
}

Bytes stream(const Bytes& file) {
  Bytes s = tvtest::gameHello();
  s.insert(s.end(), file.begin(), file.end());
  return s;
}

struct Receiver {
  tv::LiveReceiver rx;
  std::vector<tv::LiveEvent> seen;
  explicit Receiver(double stall = 10.0, std::uint64_t keepBytes = 256u << 20)
      : rx([&] {
          tv::LiveReceiverOptions o;
          o.address = "127.0.0.1:0";
          o.stallSeconds = stall;
          o.keepBytes = keepBytes;
          o.maxCells = 1 << 16;
          return o;
        }()) {}
  // The text of the first `refused` event to come (within 10 s), or "".
  std::string refusal() {
    std::string text;
    eventually([&] {
      for (tv::LiveEvent& e : rx.poll()) {
        if (e.kind == tv::LiveEvent::Kind::refused && text.empty()) text = e.text;
        seen.push_back(std::move(e));
      }
      return !text.empty();
    });
    return text;
  }
  // A good game still gets through, whole.
  bool takesAGoodGame() {
    const std::uint64_t run = rx.window().run;
    tvtest::RawPeer good(rx.port());
    const Bytes file = recording(5);
    if (!good.send(stream(file))) return false;
    return eventually([&] {
      const tv::LiveWindow w = rx.window();
      return w.run == run + 1 && w.closed && w.nextFrame == 6;
    });
  }
};

void expectRefused(Receiver& r, const Bytes& bytes, const std::string& why) {
  tvtest::RawPeer peer(r.rx.port());
  ASSERT_TRUE(peer.connected());
  peer.send(bytes);  // may fail half-way: the receiver may close first
  const std::string text = r.refusal();
  EXPECT_NE(text.find(why), std::string::npos) << text;
  EXPECT_TRUE(peer.closedByTheOtherSide());
  EXPECT_FALSE(r.rx.window().connected);
  EXPECT_TRUE(r.takesAGoodGame());
}

TEST(HostileStream, APeerThatIsNotAGameIsRefusedAtItsFirstBytes) {
  Receiver r;
  const std::string http = "GET / HTTP/1.1\r\nHost: x\r\n\r\n";
  expectRefused(r, Bytes(http.begin(), http.end()), "not a tunnelvision game");
}

TEST(HostileStream, ATamperedHeaderIsRefused) {
  Receiver r;
  Bytes s = stream(recording(3));
  s[16 + 14] ^= 0x40;  // the cell size, without its checksum made again
  expectRefused(r, s, "header checksum mismatch");
}

TEST(HostileStream, AChunkWithABadChecksumIsRefusedNamingTheFrame) {
  Receiver r;
  const Bytes file = recording(4);
  Bytes s = stream(file);
  const std::size_t chunk2 = tvtest::chunks(file)[2];
  s[16 + chunk2 + 9] ^= 1;
  expectRefused(r, s, "checksum mismatch in frame 2's chunk");
}

TEST(HostileStream, AChunkThatClaimsTwoGigabytesIsRefusedBeforeAnythingIsAllocated) {
  Receiver r;
  const Bytes all = stream(recording(2));
  Bytes s(all.begin(), all.begin() + 16 + 32);
  const Bytes head = {0xFF, 0xFF, 0xFF, 0x7F, 0, 0, 0, 0};
  s.insert(s.end(), head.begin(), head.end());
  expectRefused(r, s, "chunk length 2147483647 is over this receiver's limit");
}

TEST(HostileStream, ACountLargerThanItsChunkIsRefused) {
  // A frame whose query claims 10^6 found items in a chunk of a few bytes (checksum right).
  Receiver r;
  const Bytes file = recording(1);
  const std::vector<std::size_t> starts = tvtest::chunks(file);
  ASSERT_GE(starts.size(), 2u);
  const Bytes all = stream(file);
  Bytes s(all.begin(), all.begin() + 16 + static_cast<std::ptrdiff_t>(starts[1]));
  Bytes payload = {1, 0, 7, 0, 0xC0, 0x84, 0x3D};  // frame 1: queryPoint (0, 0), 10^6 found
  const auto n = static_cast<std::uint32_t>(payload.size());
  const auto crc = static_cast<std::uint32_t>(::crc32(0, payload.data(), n));
  for (int i = 0; i < 4; ++i) s.push_back(static_cast<std::uint8_t>(n >> (8 * i)));
  for (int i = 0; i < 4; ++i) s.push_back(static_cast<std::uint8_t>(crc >> (8 * i)));
  s.insert(s.end(), payload.begin(), payload.end());
  expectRefused(r, s, "found count 1000000 is more than");
}

TEST(HostileStream, AChunkCutShortAndThenSilenceIsDroppedAfterTheStallTime) {
  Receiver r(0.3);
  const Bytes file = recording(4);
  const std::size_t chunk3 = tvtest::chunks(file)[3];
  const Bytes all = stream(file);
  const Bytes s(all.begin(), all.begin() + 16 + static_cast<std::ptrdiff_t>(chunk3) + 8 + 2);
  expectRefused(r, s, "nothing for 0.3 s in the middle of frame 3's chunk");
}

TEST(HostileStream, APeerThatSaysNothingIsDroppedAfterTheStallTime) {
  Receiver r(0.3);
  expectRefused(r, {}, "nothing for 0.3 s in the middle of the game's hello (0 of 16 bytes)");
}

TEST(HostileStream, BytesAfterTheEndMarkAreRefused) {
  Receiver r;
  Bytes s = stream(recording(2));
  s.push_back(0);
  expectRefused(r, s, "1 bytes after the end mark");
}

TEST(HostileStream, AFloodOfGarbageIsRefusedAtOnce) {
  Receiver r;
  Bytes s = tvtest::gameHello();
  s.resize(8 << 20, 0xAB);
  expectRefused(r, s, "not a .tvrec file");
}

TEST(HostileStream, AFloodOfFramesIsKeptWithinTheBoundAndSaysWhatItDropped) {
  // 20000 frames as fast as a socket takes them, into a receiver that keeps 1 MiB.
  Receiver r(10.0, 1u << 20);
  const Bytes file = recording(20000);
  tvtest::RawPeer peer(r.rx.port());
  ASSERT_TRUE(peer.send(stream(file)));
  std::uint64_t largest = 0, dropped = 0;
  ASSERT_TRUE(eventually([&] {
    const tv::LiveWindow w = r.rx.window();
    largest = std::max(largest, w.bytes);
    for (const tv::LiveEvent& e : r.rx.poll()) {
      if (e.kind == tv::LiveEvent::Kind::dropped) dropped += e.count;
    }
    return w.closed && w.nextFrame == 20001;
  }));
  EXPECT_LE(largest, 1u << 20);
  EXPECT_GT(dropped, 10000u);
  const tv::LiveWindow w = r.rx.window();
  EXPECT_EQ(w.dropped, dropped);
  EXPECT_TRUE(w.frames.front()->keyframe);
  EXPECT_FALSE(tv::Replay::fromBytes(r.rx.file()).validate());
}

}  // namespace
