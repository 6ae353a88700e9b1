// Contact events in a recording (FORMAT.md, the contacts call): every Contacts::update and forget
// of a recorded game is in the file with its events and the filter's answers; a replay recomputes
// them and compares them bit for bit, so an event edited on disk diverges at that call; and a
// file of the format before contacts and `oneway` (1.1) still reads.

#include <gtest/gtest.h>
#include <zlib.h>

#include <optional>
#include <string>
#include <vector>

#include "recording_kit.hpp"
#include "tv/contact.hpp"
#include "tv/record/recorder.hpp"
#include "tv/record/replay.hpp"
#include "tv/world.hpp"

namespace {

using tv::ItemId;
using tv::Vec2;

// A body walks right along two floor tiles, through a coin it crosses, and a crate it stood
// beside is removed under it (its contact ends naming an item no longer in the world):
//
//   [crate]+--+   (coin)
//          |b | ->  o
//   +--------------+--------------+
//   |    tile 0    |    tile 1    |
struct Walk {
  tv::World world{16};
  tv::Recorder rec{tv::RecorderOptions{4}};
  ItemId tile0, tile1, coin, crate, body;
  tv::Contacts contacts;
  std::vector<std::string> log;  // the game's own events, one line per update

  std::vector<std::uint8_t> play() {
    tile0 = world.add({0, 100, 64, 16});
    tile1 = world.add({64, 100, 64, 16});
    world.attach(rec);
    coin = world.add({40, 90, 4, 4});
    crate = world.add({0, 88, 4, 12});
    body = world.add({4, 88, 8, 12});
    rec.label(body, "body");
    const auto filter = [&](ItemId, ItemId other) {
      return other == coin ? tv::response::cross : tv::response::slide;
    };
    tv::ContactOptions o;
    o.filter = filter;
    for (int f = 0; f < 24; ++f) {
      const Vec2 p = world.rect(body).position();
      const tv::MoveResult r =
          world.move(body, {p.x + 3.25, p.y + (f % 3 == 0 ? 1.0 : 0.0)}, filter);
      std::string line;
      for (const tv::ContactEvent& e : contacts.update(world, body, o, r.collisions)) {
        line +=
            std::to_string(static_cast<int>(e.phase)) + ":" + std::to_string(e.other.index) + " ";
      }
      log.push_back(line);
      if (f == 2) world.remove(crate);
      rec.frame();
    }
    (void)contacts.forget(world, body);
    world.detach();
    return rec.bytes();
  }
};

TEST(ContactsRecording, EveryUpdateIsRecordedAndReplaysBitForBitFromAnyKeyframe) {
  Walk g;
  const std::vector<std::uint8_t> file = g.play();
  tv::Replay replay = tv::Replay::fromBytes(file);
  const std::optional<tv::Divergence> d = replay.validate();
  ASSERT_FALSE(d) << d->report();
  const std::optional<tv::Divergence> traced = replay.validate({}, tv::Replay::Tracing::on);
  ASSERT_FALSE(traced) << traced->report();
  // The calls list them, as the debugger shows them.
  std::size_t updates = 0, forgets = 0, begins = 0;
  for (std::uint64_t f = 0; f < replay.frames(); ++f) {
    for (const tv::CallInfo& c : replay.calls(f)) {
      if (c.kind != tv::CallKind::contacts) continue;
      (c.summary.rfind("Contacts::forget", 0) == 0 ? forgets : updates) += 1;
      if (c.summary.find("1 begin") != std::string::npos) ++begins;
    }
  }
  EXPECT_EQ(updates, 24u);
  EXPECT_EQ(forgets, 1u);
  EXPECT_GE(begins, 3u) << "tile 0 with the crate, the coin, tile 1";
  EXPECT_EQ(tv::callWords(tv::CallKind::contacts), "Contacts::update");
}

// What the debugger draws: each call's events as the game got them (CallInfo::contacts, the same
// lines as the game's log), and the ground the replay recomputes as it stands.
TEST(ContactsRecording, TheCallsCarryTheGamesEventsAndTheReplayKnowsTheGround) {
  Walk g;
  const std::vector<std::uint8_t> file = g.play();
  tv::Replay replay = tv::Replay::fromBytes(file);
  std::size_t k = 0;
  for (std::uint64_t f = 0; f < replay.frames(); ++f) {
    for (const tv::CallInfo& c : replay.calls(f)) {
      if (c.kind != tv::CallKind::contacts || c.summary.rfind("Contacts::forget", 0) == 0)
        continue;
      std::string line;
      for (const tv::ContactEvent& e : c.contacts) {
        EXPECT_EQ(e.item, g.body);
        line +=
            std::to_string(static_cast<int>(e.phase)) + ":" + std::to_string(e.other.index) + " ";
      }
      ASSERT_LT(k, g.log.size());
      EXPECT_EQ(line, g.log[k]) << "update " << k;
      ++k;
    }
  }
  EXPECT_EQ(k, g.log.size());
  // Before any update is replayed nothing is known; after one, the tile under the body.
  replay.seek(0, 0);
  EXPECT_FALSE(replay.ground(g.body).has_value());
  replay.seek(5);
  const std::optional<tv::Ground> ground = replay.ground(g.body);
  ASSERT_TRUE(ground.has_value());
  EXPECT_EQ(ground->kind, tv::GroundKind::ground);
  EXPECT_EQ(ground->item, g.tile0);
  EXPECT_FALSE(replay.ground(g.tile0).has_value()) << "a tile reads no contacts";
}

TEST(ContactsRecording, AnEventEditedOnDiskDivergesAtThatCall) {
  Walk g;
  std::vector<std::uint8_t> file = g.play();
  // Frame 5's update: a persist of tile 0 (the body walks on it) rewritten as a begin. The call
  // follows the body's move, so it names the same item: kind byte, kind varint, event count,
  // then the first event's code byte (phase in its low 2 bits).
  tv::Replay clean = tv::Replay::fromBytes(file);
  const std::vector<tv::CallInfo> calls = clean.calls(5);
  const tv::CallInfo* update = nullptr;
  for (const tv::CallInfo& c : calls)
    if (c.kind == tv::CallKind::contacts) update = &c;
  ASSERT_NE(update, nullptr);
  const std::size_t at = static_cast<std::size_t>(update->offset) + 3;
  ASSERT_EQ(file[at] & 3, 1) << "a persist";
  file[at] = static_cast<std::uint8_t>(file[at] & ~3);
  tvtest::fixChecksum(file, at);
  tv::Replay tampered = tv::Replay::fromBytes(file);
  const std::optional<tv::Divergence> d = tampered.validate();
  ASSERT_TRUE(d);
  EXPECT_EQ(d->frame, 5u);
  EXPECT_EQ(d->kind, tv::CallKind::contacts);
  EXPECT_EQ(d->what, "contact event 0");
  EXPECT_NE(d->expected.find("begin"), std::string::npos) << d->report();
  EXPECT_NE(d->got.find("persist"), std::string::npos) << d->report();
}

// What a writer of version 1.1 wrote for the same game: the header says 1.1 and each keyframe
// lists the four built-in responses of then (no "oneway"), its own after them.
std::vector<std::uint8_t> asVersion11(const std::vector<std::uint8_t>& in) {
  std::vector<std::uint8_t> out(in.begin(), in.begin() + 32);
  out[10] = 1;
  out[11] = 0;
  tvtest::put32(out, 28, static_cast<std::uint32_t>(::crc32(0, out.data(), 28)));
  const auto varint = [](const std::vector<std::uint8_t>& b, std::size_t& pos) {
    std::uint64_t v = 0;
    for (int shift = 0;; shift += 7) {
      const std::uint8_t byte = b[pos++];
      v |= std::uint64_t{byte & 0x7Fu} << shift;
      if (!(byte & 0x80)) return v;
    }
  };
  std::size_t end = 32;
  for (const std::size_t c : tvtest::chunks(in)) {
    const std::uint32_t len = tvtest::le32(in, c);
    std::vector<std::uint8_t> p(in.begin() + static_cast<std::ptrdiff_t>(c + 8),
                                in.begin() + static_cast<std::ptrdiff_t>(c + 8 + len));
    end = c + 8 + len;
    std::size_t pos = 0;
    (void)varint(p, pos);  // frame number
    if (p[pos++] & 1) {
      pos += 8;              // cell size
      (void)varint(p, pos);  // slots
      (void)varint(p, pos);  // next order
      const std::size_t countAt = pos;
      const std::uint64_t names = varint(p, pos);
      EXPECT_LT(names, 128u);
      for (std::uint64_t k = 0; k < names; ++k) {
        const std::size_t at = pos;
        const std::uint64_t n = varint(p, pos);
        pos += n;
        if (k == tv::response::oneway) {
          p.erase(p.begin() + static_cast<std::ptrdiff_t>(at),
                  p.begin() + static_cast<std::ptrdiff_t>(pos));
          pos = at;
        }
      }
      p[countAt] = static_cast<std::uint8_t>(names - 1);
    }
    const std::size_t at = out.size();
    out.resize(at + 8);
    tvtest::put32(out, at, static_cast<std::uint32_t>(p.size()));
    tvtest::put32(out, at + 4,
                  static_cast<std::uint32_t>(::crc32(0, p.data(), static_cast<uInt>(p.size()))));
    out.insert(out.end(), p.begin(), p.end());
  }
  out.insert(out.end(), in.begin() + static_cast<std::ptrdiff_t>(end), in.end());  // the end mark
  return out;
}

TEST(ContactsRecording, AFileOfVersion11WithItsOwnResponseStillReads) {
  // A game with a response of its own ("mine": id 4 in a 1.1 file, 5 since "oneway" took 4),
  // keyframes every 3 frames.
  tv::World world(16);
  (void)world.addResponse("mine", &tv::touchResponse);
  tv::Recorder rec{tv::RecorderOptions{3}};
  world.attach(rec);
  world.add({0, 100, 64, 16});
  const ItemId b = world.add({0, 0, 8, 8});
  for (int f = 0; f < 10; ++f) {
    world.move(b, world.rect(b).position() + Vec2{1, 15});
    rec.frame();
  }
  world.detach();
  const std::vector<std::uint8_t> v11 = asVersion11(rec.bytes());
  tv::Replay replay = tv::Replay::fromBytes(v11);
  const std::optional<tv::Divergence> d = replay.validate({}, tv::Replay::Tracing::on);
  ASSERT_FALSE(d) << d->report();
  EXPECT_EQ(replay.world().stateHash(), world.stateHash());
  EXPECT_EQ(replay.world().responseName(tv::response::oneway), "oneway");
  EXPECT_EQ(replay.world().responseName(5), "mine");
  // Negative control: the same bytes read as a 1.2 file name "mine" where "oneway" must be.
  std::vector<std::uint8_t> as12 = v11;
  as12[10] = 2;
  tvtest::put32(as12, 28, static_cast<std::uint32_t>(::crc32(0, as12.data(), 28)));
  try {
    (void)tv::Replay::fromBytes(as12).validate();
    FAIL() << "a 1.1 keyframe was read as 1.2";
  } catch (const tv::Error& e) {
    EXPECT_NE(std::string(e.what()).find("built-in response 4 is named 'mine'"), std::string::npos)
        << e.what();
  }
}

}  // namespace
