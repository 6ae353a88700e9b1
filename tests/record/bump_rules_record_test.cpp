// Specification: moves and checks made with bump.lua's rules (MoveSemantics::bump) record and
// replay bit for bit, traced or not — with every built-in response, overlapping starts, a user
// response whose legs go on or stop, and a move that ends against something it met before.

#include <gtest/gtest.h>

#include <vector>

#include "tv/record/recorder.hpp"
#include "tv/record/replay.hpp"
#include "tv/world.hpp"

namespace {

using tv::ItemId;
using tv::Rect;
using tv::Vec2;
namespace response = tv::response;

// A user response: lifts the item 2 above the contact; stops when the contact is below y 50.
tv::Leg lift(const tv::Collision& c, Vec2 goal) {
  tv::Leg l;
  l.start = c.touch;
  l.goal = {goal.x, c.touch.y - 2};
  l.stop = c.touch.y > 50;
  return l;
}

struct BumpGame {
  tv::World world{32};
  std::vector<ItemId> bodies;
  std::vector<Vec2> velocity;
  tv::ResponseId lifted = 0;
  // What the run exercised, so that the test means what its name says.
  int overlaps = 0, metAgain = 0, userLegs = 0, crossed = 0, touched = 0, bounced = 0;

  void build() {
    lifted = world.addResponse("lift", &lift);
    for (int x = 0; x < 24; ++x) world.add({x * 16.0, 200, 16, 16});  // a floor of tiles
    world.add({0, 0, 16, 200});
    world.add({200, 120, 16, 80});                 // a wall
    world.add({170, 140, 4, 60});                  // a thin cloud (crossed)
    world.add({300, 100, 16, 100});                // a slot 4 wide...
    world.add({320, 100, 16, 100});
    world.add({60, 100, 32, 64});                  // two blocks 2 apart...
    world.add({94, 100, 32, 64});
    bodies.push_back(world.add({88, 120, 8, 8}));  // ...with a body across them
    bodies.push_back(world.add({20, 20, 10, 13.7}));
    bodies.push_back(world.add({317, 150, 2, 2})); // ...with a fast ball in it
    bodies.push_back(world.add({150, 150, 6, 6}));
    for (std::size_t i = 0; i < bodies.size(); ++i) velocity.push_back({40.0 + 13.0 * static_cast<double>(i), -50.0});
    velocity[2] = {600, 0};
  }

  void frame(int f) {
    tv::MoveOptions o;
    o.semantics = tv::MoveSemantics::bump;
    for (std::size_t i = 0; i < bodies.size(); ++i) {
      const ItemId b = bodies[i];
      velocity[i].y += 500.0 / 60;
      const Rect at = world.rect(b);
      const Vec2 goal{at.x + velocity[i].x / 60, at.y + velocity[i].y / 60};
      const auto filter = [&, i](ItemId, ItemId other) {
        const Rect r = world.rect(other);
        if (r.w == 4) return response::cross;
        if (i == 2) return response::bounce;
        if (i == 3 && f % 3 == 0) return lifted;
        if (i == 3 && f % 3 == 1) return response::touch;
        return response::slide;
      };
      if (f % 7 == 3) (void)world.check(b, goal, filter, o);
      const tv::MoveResult m = world.move(b, goal, filter, o);
      for (std::size_t k = 0; k < m.collisions.size(); ++k) {
        const tv::Collision& c = m.collisions[k];
        overlaps += c.overlaps;
        userLegs += c.response == lifted;
        crossed += c.response == response::cross;
        touched += c.response == response::touch;
        bounced += c.response == response::bounce;
        for (std::size_t j = 0; j < k; ++j) metAgain += m.collisions[j].other == c.other;
        if (c.normal.x != 0) velocity[i].x = -velocity[i].x * (i == 2 ? 1.0 : 0.5);
        if (c.normal.y != 0) velocity[i].y = -velocity[i].y * 0.3;
      }
    }
  }
};

TEST(BumpRulesRecording, ReplaysBitForBitTracedAndUntraced) {
  BumpGame g;
  g.build();
  tv::Recorder rec(tv::RecorderOptions{8});
  g.world.attach(rec);
  for (int f = 0; f < 200; ++f) {
    g.frame(f);
    rec.frame();
  }
  rec.close();
  EXPECT_GT(g.overlaps, 0);
  EXPECT_GT(g.metAgain, 0);
  EXPECT_GT(g.userLegs, 0);
  EXPECT_GT(g.crossed, 0);
  EXPECT_GT(g.touched, 0);
  EXPECT_GT(g.bounced, 0);
  {
    tv::Replay replay = tv::Replay::fromBytes(rec.bytes());
    const std::optional<tv::Divergence> d = replay.validate();
    ASSERT_FALSE(d) << d->report();
    EXPECT_EQ(replay.world().stateHash(), g.world.stateHash());
  }
  // Traced, call by call: the trace observes, it changes nothing.
  tv::Replay traced = tv::Replay::fromBytes(rec.bytes());
  traced.seek(0, 0);
  tv::MoveTrace trace;
  std::size_t legs = 0;
  while (!traced.atEnd()) {
    trace.clear();
    const std::optional<tv::Divergence> d = traced.step(&trace);
    ASSERT_FALSE(d) << d->report();
    legs += trace.legs.size();
  }
  EXPECT_GT(legs, 800u);  // the moves were traced
}

}  // namespace
