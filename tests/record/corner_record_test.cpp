// Corner correction (tv/corner.hpp) and contact tracking (tv/contact.hpp) in a recorded game:
// a nudged jump is made of World calls (check, anyOverlap, moves), each recorded as the game made
// it, so the recording replays bit for bit; the contact tracker's own query is not one of the
// game's calls and leaves the recording as it would be without it. After the moves, a
// cornerNudge call says they were a corner correction (which ceiling, where, how far), so that
// a replay — and the debugger watching it — shows the nudge as what it is; the replay checks it
// against the replayed world.

#include <zlib.h>

#include <gtest/gtest.h>

#include <cstring>
#include <optional>
#include <vector>

#include "recording_kit.hpp"
#include "tv/contact.hpp"
#include "tv/corner.hpp"
#include "tv/record/recorder.hpp"
#include "tv/record/replay.hpp"
#include "tv/world.hpp"

namespace {

using tv::ItemId;

//   +---------------------+
//   |  ceiling {16,0,32,8} |      three bodies jump into it every 20 frames, one clipping its
//   +---------------------+      left end, one its right end, one its middle; gravity brings
//   floor {0, 100, 80, 8}         them back to the floor
TEST(CornerRecording, NudgedJumpsReplayBitForBit) {
  tv::World world(16);
  world.add({16, 0, 32, 8});
  world.add({0, 100, 80, 8});
  tv::Recorder rec(tv::RecorderOptions{8});
  world.attach(rec);
  const ItemId bodies[] = {world.add({10.25, 88, 8, 12}), world.add({45.5, 88, 8, 12}),
                           world.add({28, 88, 8, 12})};
  double vy[3] = {0, 0, 0};
  int nudges = 0;
  tv::Contacts contacts;
  for (int frame = 0; frame < 80; ++frame) {
    for (int i = 0; i < 3; ++i) {
      if (frame % 20 == 0) vy[i] = -30;
      vy[i] += 2.5;
      const tv::Rect r = world.rect(bodies[i]);
      const tv::CornerMove m = tv::moveCornered(world, bodies[i], {r.x, r.y + vy[i]});
      nudges += m.nudged;
      for (const tv::Collision& c : m.collisions)
        if (c.normal.y != 0) vy[i] = 0;
      (void)contacts.update(world, bodies[i], {}, m.collisions);
    }
    rec.frame();
  }
  EXPECT_EQ(nudges, 2) << "two bodies nudged at the first jump (then they stand clear of it)";
  const std::uint64_t hash = world.stateHash();
  rec.close();
  tv::Replay replay = tv::Replay::fromBytes(rec.bytes());
  const std::optional<tv::Divergence> div = replay.validate();
  ASSERT_FALSE(div) << div->report();
  EXPECT_EQ(replay.world().stateHash(), hash);
}

// One body jumping into a ceiling's left end, clipping it by 2 px (tests/core/corner_test.cpp):
//
//          +------------------------------+
//          |        ceiling {16, 0, 32, 8}  |
//       +--+-----------------------------+
//       |b |   body {10, 40, 8, 12} jumps to y 0: it meets the ceiling at (10, 8), 2 px under
//       +--+   its left end, and is nudged to x 8; a second body {28, 40, 8, 12} under the middle
//              stops (no nudge)
struct NudgedJump {
  explicit NudgedJump(double maxNudge) {
    world.attach(rec);
    const ItemId body = world.add({10, 40, 8, 12});
    const ItemId middle = world.add({28, 40, 8, 12});
    rec.label(body, "jumper", "player");
    rec.label(middle, "stopper", "player");
    rec.frame();
    tv::CornerOptions o;
    o.maxNudge = maxNudge;
    made = tv::moveCornered(world, body, {10, 0}, o);
    (void)tv::moveCornered(world, middle, {28, 0}, o);
    rec.frame();
    rec.close();
    bytes = rec.bytes();
  }
  tv::World world{16};
  ItemId ceiling = world.add({16, 0, 32, 8});
  tv::Recorder rec{tv::RecorderOptions{8}};
  tv::CornerMove made;
  std::vector<std::uint8_t> bytes;
};

std::vector<tv::CallInfo> nudgeCalls(const tv::Replay& r) {
  std::vector<tv::CallInfo> out;
  for (std::uint64_t f = 0; f < r.frames(); ++f)
    for (const tv::CallInfo& c : r.calls(f))
      if (c.kind == tv::CallKind::cornerNudge) out.push_back(c);
  return out;
}

TEST(CornerRecording, ANudgeIsRecordedAsItsOwnCallAfterTheMovesThatMadeIt) {
  NudgedJump g(4);
  ASSERT_TRUE(g.made.nudged);
  tv::Replay replay = tv::Replay::fromBytes(g.bytes);
  const std::vector<tv::CallInfo> nudges = nudgeCalls(replay);
  ASSERT_EQ(nudges.size(), 1u) << "one nudge: the body under the middle was not nudged";
  const tv::CallInfo& n = nudges[0];
  EXPECT_EQ(n.item, (ItemId{1, 0}));
  EXPECT_EQ(n.nudge.hit.other, g.ceiling);
  EXPECT_EQ(n.nudge.hit.touch, g.made.nudge.hit.touch);
  EXPECT_EQ(n.nudge.hit.touch, (tv::Vec2{10, 8}));
  EXPECT_EQ(n.nudge.dx, -2.0);
  EXPECT_EQ(n.nudge.hit.otherRect, (tv::Rect{16, 0, 32, 8}));
  EXPECT_EQ(n.start, (tv::Rect{10, 8, 8, 12})) << "the body where it met the corner";
  EXPECT_EQ(n.position, (tv::Vec2{8, 8})) << "where the nudge put it";
  EXPECT_EQ(n.summary, "moveCornered jumper: nudged -2 round the corner of item 0.0 at (10, 8)");
  // After the World calls that made it: check, anyOverlap and three moves of the same body.
  const std::vector<tv::CallInfo> frame = replay.calls(n.frame);
  ASSERT_GE(n.index, 5u);
  const tv::CallKind before[] = {tv::CallKind::check, tv::CallKind::anyOverlap,
                                 tv::CallKind::move, tv::CallKind::move, tv::CallKind::move};
  for (std::uint32_t k = 0; k < 5; ++k) EXPECT_EQ(frame[n.index - 5 + k].kind, before[k]) << k;
  EXPECT_EQ(tv::callRole(tv::CallKind::cornerNudge), tv::CallRole::note);
  EXPECT_EQ(tv::callWords(tv::CallKind::cornerNudge), "moveCornered");
  // Per item: the jumper was nudged once, the other never.
  for (const tv::RecordedItem& i : replay.items()) {
    EXPECT_EQ(i.nudges, i.label == "jumper" ? 1u : 0u) << i.label;
  }
  const std::optional<tv::Divergence> d = replay.validate();
  ASSERT_FALSE(d) << d->report();
  const std::optional<tv::Divergence> traced = replay.validate({}, tv::Replay::Tracing::on);
  ASSERT_FALSE(traced) << traced->report();
}

TEST(CornerRecording, NegativeControlWithoutCorrectionTheSameGameRecordsNoNudge) {
  NudgedJump g(0);
  EXPECT_FALSE(g.made.nudged);
  tv::Replay replay = tv::Replay::fromBytes(g.bytes);
  EXPECT_TRUE(nudgeCalls(replay).empty());
  for (const tv::RecordedItem& i : replay.items()) EXPECT_EQ(i.nudges, 0u) << i.label;
}

// The replay checks a nudge against the replayed world: a dx edited on disk (a tool's bug, a
// file from a game whose ceiling differs) is a divergence at that call, naming it.
TEST(CornerRecording, ANudgeEditedOnDiskDivergesAtItsCall) {
  NudgedJump g(4);
  const tv::Replay clean = tv::Replay::fromBytes(g.bytes);
  const tv::CallInfo n = nudgeCalls(clean).at(0);
  // The call: kind byte (15 + same item), kind varint 1, ceiling zigzag, the group's code byte
  // (touch.y on the ceiling's bottom: no bytes; touch.x and dx each a float32 or float64).
  std::vector<std::uint8_t> file = g.bytes;
  const std::size_t at = static_cast<std::size_t>(n.offset);
  ASSERT_EQ(file[at] & 0x0F, 0x0F);
  ASSERT_EQ(file[at + 1], 1);
  const std::uint8_t codes = file[at + 3];
  ASSERT_EQ(codes & 3, 0) << "touch.y is the ceiling's bottom";
  const auto width = [](unsigned code) { return code == 2 ? 4u : code == 3 ? 8u : 0u; };
  const std::size_t dxAt = at + 4 + width((codes >> 2) & 3u);
  ASSERT_EQ((codes >> 4) & 3u, 2u) << "dx -2 is a float32";
  float dx = 0;
  std::memcpy(&dx, &file[dxAt], 4);
  ASSERT_EQ(dx, -2.0f);
  dx = -3.0f;
  std::memcpy(&file[dxAt], &dx, 4);
  tvtest::fixChecksum(file, dxAt);
  tv::Replay tampered = tv::Replay::fromBytes(file);
  EXPECT_EQ(nudgeCalls(tampered).at(0).nudge.dx, -3.0);
  const std::optional<tv::Divergence> d = tampered.validate();
  ASSERT_TRUE(d);
  EXPECT_EQ(d->kind, tv::CallKind::cornerNudge);
  EXPECT_EQ(d->what, "corner nudge dx");
  EXPECT_EQ(d->expected, "-3");
  EXPECT_EQ(d->got, "-2");
}

// Files written before the call existed (version 1.2) still open and replay.
TEST(CornerRecording, AVersion12FileWithoutNudgesStillReplays) {
  NudgedJump g(0);
  std::vector<std::uint8_t> file = g.bytes;
  ASSERT_TRUE(file.size() > 32 && file[10] == 3) << "written as 1.3";
  file[10] = 2;
  tvtest::put32(file, 28, static_cast<std::uint32_t>(::crc32(0, file.data(), 28)));
  tv::Replay old = tv::Replay::fromBytes(file);
  const std::optional<tv::Divergence> d = old.validate();
  ASSERT_FALSE(d) << d->report();
}

}  // namespace
