// Corner correction (tv/corner.hpp) and contact tracking (tv/contact.hpp) in a recorded game:
// a nudged jump is made of World calls (check, anyOverlap, moves), each recorded as the game made
// it, so the recording replays bit for bit; the contact tracker's own query is not one of the
// game's calls and leaves the recording as it would be without it.

#include <gtest/gtest.h>

#include <optional>

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

}  // namespace
