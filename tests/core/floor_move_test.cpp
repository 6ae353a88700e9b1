// Moves on floors: bodies held on a floor by gravity push into it every tick, and walkers slide
// along it across tile seams — the moves a short move's one read of its box serves. Each must
// end where the reference ends (move_reference.hpp: every leg against every item) and report
// the same collisions, bit for bit, checked move by move (so a failure names the first move that
// differs). adaptive is continuous by another name; discrete, which teleports and pushes out, is
// the negative control that shows a hash over many ticks sees a difference in what is reported.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "move_reference.hpp"
#include "tv/mover.hpp"
#include "tv/sim/rng.hpp"

namespace tv {
namespace {

// FNV-style mixing of the exact bits of everything a move reports.
class ResultHash {
 public:
  void add(const MoveResult& r) {
    feed(r.position);
    feed(r.collisions.size());
    for (const Collision& c : r.collisions) {
      feed((std::uint64_t{c.item.generation} << 32) | c.item.index);
      feed((std::uint64_t{c.other.generation} << 32) | c.other.index);
      feed((std::uint64_t{c.overlaps} << 1) | std::uint64_t{c.corner});
      feed(c.ti);
      feed(c.move);
      feed(c.normal);
      feed(c.touch);
      feed(c.itemRect);
      feed(c.otherRect);
      feed(std::uint64_t{c.response});
      feed(c.target);
    }
  }
  void feed(std::uint64_t v) { h_ = (h_ ^ v) * 0x100000001B3ull + 0x9E3779B97F4A7C15ull; }
  void feed(double v) { feed(std::bit_cast<std::uint64_t>(v)); }
  void feed(Vec2 v) {
    feed(v.x);
    feed(v.y);
  }
  void feed(const Rect& r) {
    feed(r.x);
    feed(r.y);
    feed(r.w);
    feed(r.h);
  }
  [[nodiscard]] std::uint64_t value() const { return h_; }

 private:
  std::uint64_t h_ = 0xcbf29ce484222325ull;
};

const std::vector<ResponseFn> kBuiltins = {&touchResponse, &crossResponse, &slideResponse,
                                           &bounceResponse, &onewayResponse};

// The bitwise difference between two results, or "" when they are the same.
std::string difference(const MoveResult& a, const MoveResult& b) {
  ResultHash ha, hb;
  ha.add(a);
  hb.add(b);
  if (ha.value() == hb.value()) return "";
  std::string s =
      "position (" + std::to_string(a.position.x) + ", " + std::to_string(a.position.y) + ") vs (" +
      std::to_string(b.position.x) + ", " + std::to_string(b.position.y) + "), collisions " +
      std::to_string(a.collisions.size()) + " vs " + std::to_string(b.collisions.size());
  for (std::size_t i = 0; i < a.collisions.size() && i < b.collisions.size(); ++i) {
    const Collision &p = a.collisions[i], &q = b.collisions[i];
    s += "; #" + std::to_string(i) + " other " + std::to_string(p.other.index) + "/" +
         std::to_string(q.other.index) + " ti " + std::to_string(p.ti) + "/" +
         std::to_string(q.ti) + " normal (" + std::to_string(p.normal.x) + "," +
         std::to_string(p.normal.y) + ")/(" + std::to_string(q.normal.x) + "," +
         std::to_string(q.normal.y) + ") target (" + std::to_string(p.target.x) + "," +
         std::to_string(p.target.y) + ")/(" + std::to_string(q.target.x) + "," +
         std::to_string(q.target.y) + ")";
  }
  return s;
}

// A floor of 48 separate 16 px tiles with a wall at each end, a two-tile block standing on it
// and a one-tile pit:
//
//   |#|                   ##                         |#|
//   |#|  [] ->   <- []    ##        []  ->           |#|   walls: 3 tiles high
//   |#|#######################  ################ ... |#|   y = 160
//                             ##                           the pit's bottom, 16 px lower
//
// Bodies of assorted sizes at dyadic sub-pixel positions (so every contact is exact) fall under
// gravity and walk at 0..300 px/s (up to 5 px a tick). They ignore each other, except that
// every fifth body crosses the others (reported, passed through) and every seventh only
// touches the block. After each move the velocity loses what points into a reported normal
// (slide), and a walker turns round at a wall or the block.
struct FloorScene {
  static constexpr double kTile = 16.0, kFloorY = 160.0, kGravity = 1800.0, kDt = 1.0 / 60.0;
  static constexpr int kTiles = 48, kPit = 30;

  World world{32};
  std::vector<ItemId> bodies;
  std::vector<Vec2> velocity;
  std::vector<bool> isBody;
  ItemId block0, block1;

  explicit FloorScene(std::uint64_t seed, int count = 40) {
    for (int k = 0; k < kTiles; ++k) {
      const double y = k == kPit ? kFloorY + kTile : kFloorY;
      tile({k * kTile, y, kTile, kTile});
    }
    for (int k = 1; k <= 3; ++k) {
      tile({-kTile, kFloorY - k * kTile, kTile, kTile});
      tile({kTiles * kTile, kFloorY - k * kTile, kTile, kTile});
    }
    block0 = tile({20 * kTile, kFloorY - kTile, kTile, kTile});
    block1 = tile({20 * kTile, kFloorY - 2 * kTile, kTile, kTile});
    sim::Rng rng(seed);
    const double sizes[] = {6.0, 8.0, 10.5, 14.0};
    const double speeds[] = {0.0, 60.0, 120.0, 240.0, 300.0};
    for (int i = 0; i < count; ++i) {
      const double size = sizes[rng.below(4)];
      // Either standing on the floor already or dropped from up to 3 tiles above it.
      const double drop = rng.below(2) == 0 ? 0.0 : std::floor(rng.uniform(0, 48) * 16) / 16;
      const double x = std::floor(rng.uniform(kTile, (kTiles - 2) * kTile) * 64) / 64;
      const Rect r{x, kFloorY - size - drop, size, size};
      if (world.anyOverlap(r)) continue;  // inside the block or the pit's edge: not this one
      bodies.push_back(world.add(r));
      isBody.resize(bodies.back().index + 1, false);
      isBody[bodies.back().index] = true;
      const double speed = speeds[rng.below(5)];
      velocity.push_back({rng.below(2) == 0 ? speed : -speed, 0.0});
    }
  }

  ItemId tile(const Rect& r) {
    const ItemId id = world.add(r);
    isBody.resize(id.index + 1, false);
    return id;
  }

  [[nodiscard]] ResponseId respond(ItemId item, ItemId other) const {
    const bool otherIsBody = other.index < isBody.size() && isBody[other.index];
    if (otherIsBody) return item.index % 5 == 0 ? response::cross : response::ignore;
    if (item.index % 7 == 0 && (other == block0 || other == block1)) return response::touch;
    return response::slide;
  }

  // One tick of body i: gravity, one move, and the velocity it leaves; with `ref`, the
  // reference's move from the same start first.
  MoveResult step(Mover& mover, std::size_t i, MoveTrace* trace = nullptr,
                  test::ReferenceResult* ref = nullptr) {
    Vec2& v = velocity[i];
    v.y += kGravity * kDt;
    const ItemId id = bodies[i];
    const Vec2 goal = world.rect(id).position() + v * kDt;
    const auto filter = [this](ItemId a, ItemId b) { return respond(a, b); };
    if (ref) *ref = test::referenceMove(world, id, world.rect(id), goal, filter, 64, kBuiltins);
    const MoveResult r = mover.move(world, id, goal, filter, trace);
    for (const Collision& c : r.collisions) {
      if (c.response == response::cross) continue;
      if (v.y * c.normal.y < 0.0) v.y = 0.0;
      if (v.x * c.normal.x < 0.0) v.x = -v.x;  // turn round at a wall or the block
    }
    return r;
  }
};

// Runs the scene with one mover and hashes every result and the final world.
std::uint64_t run(std::string_view mover, std::uint64_t seed, int ticks) {
  FloorScene s(seed);
  Mover m(parseMover(mover));
  ResultHash h;
  for (int t = 0; t < ticks; ++t) {
    for (std::size_t i = 0; i < s.bodies.size(); ++i) h.add(s.step(m, i));
  }
  h.feed(s.world.stateHash());
  return h.value();
}

TEST(FloorMoves, EveryMoveEqualsTheReferenceBitForBit) {
  for (const std::uint64_t seed : {1u, 2u, 3u}) {
    FloorScene s(seed);
    ASSERT_GT(s.bodies.size(), 25u) << "seed " << seed;
    Mover adaptive(parseMover("adaptive")), continuous(parseMover("continuous"));
    std::size_t resting = 0, walking = 0, sliding = 0;
    for (int t = 0; t < 400; ++t) {
      for (std::size_t i = 0; i < s.bodies.size(); ++i) {
        test::ReferenceResult ref;
        const MoveResult r = s.step(i % 2 ? adaptive : continuous, i, nullptr, &ref);
        const std::vector<Collision> c(r.collisions.begin(), r.collisions.end());
        ASSERT_EQ(difference({r.position, c}, {ref.position, ref.collisions}), "")
            << "seed " << seed << ", tick " << t << ", body " << i;
        if (!c.empty() && c.front().normal.y < 0.0) {
          ++sliding;
          if (c.front().move.x == 0.0) ++resting;
          if (c.front().move.x != 0.0) ++walking;
        }
      }
    }
    // The scene does what it says: most moves press into the floor, many of them walking.
    EXPECT_GT(resting, 1000u) << "seed " << seed;
    EXPECT_GT(walking, 4000u) << "seed " << seed;
    EXPECT_GT(sliding, 400u * s.bodies.size() / 2) << "seed " << seed;
  }
}

TEST(FloorMoves, AdaptiveIsContinuousByAnotherNameAndDiscreteDiffers) {
  const std::uint64_t continuous = run("continuous", 11, 900);
  EXPECT_EQ(run("adaptive", 11, 900), continuous);
  // The negative control: discrete teleports into the floor and pushes out, so it reports
  // overlaps (ti = minus the overlap area) where the sweep reports contacts at ti = 0.
  EXPECT_NE(run("discrete", 11, 900), continuous);
}

TEST(FloorMoves, DiscreteReportsAnOverlapWhereTheSweepReportsAContact) {
  // A 8x8 body resting on a tile, pulled 0.5 px into it:
  //
  //     [  ]      y 152..160
  //   ########    y 160..176
  World w(32);
  const ItemId floor = w.add({0, 160, 16, 16});
  const ItemId body = w.add({4, 152, 8, 8});
  for (const std::string_view name : {"adaptive", "continuous", "discrete"}) {
    w.update(body, Vec2{4, 152});
    Mover m(parseMover(name));
    const MoveResult r = m.move(w, body, {6, 152.5});
    ASSERT_EQ(r.collisions.size(), 1u) << name;
    EXPECT_EQ(r.position, (Vec2{6, 152})) << name;
    EXPECT_EQ(r.collisions[0].other, floor) << name;
    if (name == "discrete") {
      EXPECT_TRUE(r.collisions[0].overlaps);  // the negative control
      EXPECT_LT(r.collisions[0].ti, 0.0);
    } else {
      EXPECT_FALSE(r.collisions[0].overlaps) << name;
      EXPECT_EQ(r.collisions[0].ti, 0.0) << name;
      EXPECT_EQ(r.collisions[0].touch, (Vec2{4, 152})) << name;
      EXPECT_EQ(r.collisions[0].target, (Vec2{6, 152})) << name;
    }
  }
}

TEST(FloorMoves, AMoveTooShortToCarryTheEdgeOntoAFaceItTouchesIsNoHit) {
  // A 1024 px wide body whose right edge rests on a wall's face, after a push into it:
  //
  //   [body: x 0.5 .. 1024.5]|wall|
  //
  // then moved right by 2^-50: its x changes (0.5 has ulps of 2^-53) but its right edge,
  // 1024.5 + 2^-50, rounds back onto the face (ulps of 2^-42 there), so it never enters the
  // wall: no collision.
  for (const std::string_view name : {"continuous", "adaptive"}) {
    World w(32);
    const ItemId wall = w.add({1024.5, -8, 16, 32});
    const ItemId body = w.add({0.5, 0, 1024, 8});
    Mover m(parseMover(name));
    const MoveResult pushed = m.move(w, body, {1.5, 0});
    ASSERT_EQ(pushed.collisions.size(), 1u) << name;
    EXPECT_EQ(pushed.collisions[0].other, wall) << name;
    const Vec2 goal{0.5 + 0x1p-50, 0};
    ASSERT_EQ(w.rect(body).at(goal).right(), 1024.5);
    const MoveResult r = m.move(w, body, goal);
    EXPECT_TRUE(r.collisions.empty()) << name;
    EXPECT_EQ(r.position, goal) << name;
  }
}

TEST(FloorMoves, PressingIntoEveryFaceEqualsTheReference) {
  // A 10x10 body in a 48x48 room of 16 px tiles, first pushed onto one face, then pressed into
  // it while sliding along it, back and forth across the seams between two tiles:
  //
  //   ########
  //   #      #   the room's inside: x 0..48, y 0..48 (walls, floor and ceiling are tiles)
  //   #  []  #
  //   ########
  //
  // The start positions include -0.0 and +0.0 (the room's corner is at 0), where a rounding
  // that ignored the sign would show.
  const Vec2 into[] = {{0, 1}, {0, -1}, {1, 0}, {-1, 0}};
  for (const Vec2 dir : into) {
    for (const double at : {-0.0, 0.0, 7.25, 19.5}) {
      const auto play = [&](std::string_view name) {
        World w(32);
        for (int k = -1; k <= 3; ++k) {
          w.add({k * 16.0, -16, 16, 16});
          w.add({k * 16.0, 48, 16, 16});
          w.add({-16, k * 16.0, 16, 16});
          w.add({48, k * 16.0, 16, 16});
        }
        const bool alongX = dir.x == 0.0;
        const ItemId b = w.add(alongX ? Rect{at, 19, 10, 10} : Rect{19, at, 10, 10});
        Mover m(parseMover(name));
        for (int t = 0; t < 40; ++t) {
          // No slide (by -0.0, which keeps a -0.0 coordinate) while it is pushed on.
          const double slide = t < 3 ? -0.0 : (t / 10) % 2 == 0 ? 2.75 : -3.5;
          const Vec2 d = alongX ? Vec2{slide, dir.y * (t < 3 ? 20.0 : 0.5)}
                                : Vec2{dir.x * (t < 3 ? 20.0 : 0.5), slide};
          const Vec2 goal = w.rect(b).position() + d;
          const test::ReferenceResult ref =
              test::referenceMove(w, b, w.rect(b), goal, Filter{}, 64, kBuiltins);
          const MoveResult r = m.move(w, b, goal);
          const std::vector<Collision> c(r.collisions.begin(), r.collisions.end());
          ASSERT_EQ(difference({r.position, c}, {ref.position, ref.collisions}), "")
              << name << " " << dir.x << "," << dir.y << " at " << at << " tick " << t;
        }
      };
      play("adaptive");
      play("continuous");
    }
  }
}

TEST(FloorMoves, PressedIntoACornerAtMinusZeroPlacesLikeTheReference) {
  // A body at x = -0.0 against a wall whose right edge is +0.0 (equal, not the same bits),
  // resting on a floor tile added after the wall:
  //
  //   ##|[]      wall: x -16..+0.0; body: x -0.0..10
  //   ##|####    floor: y 48..64
  //
  // Pressed down and left at once, it touches both at ti = 0; the wall, added first, is the
  // collision, and its contact takes the wall's edge (+0.0), not the body's x (-0.0). The same
  // for a ceiling (its bottom +0.0, the body's y -0.0) against a wall.
  for (const bool ceiling : {false, true}) {
    const auto play = [&](std::string_view name) {
      World w(32);
      if (ceiling) {
        w.add({0, -16, 16, 16});  // the ceiling first: it wins the tie
        w.add({-16, 0, 16, 16});
      } else {
        w.add({-16, 32, 16, 16});  // the wall first
        w.add({0, 48, 16, 16});
      }
      const ItemId b = w.add(ceiling ? Rect{0, -0.0, 10, 10} : Rect{-0.0, 38, 10, 10});
      Mover m(parseMover(name));
      // A first push onto one face (by -0.0 along the other, which keeps its -0.0), then two
      // presses into the corner.
      const Vec2 first = ceiling ? Vec2{-0.5, -0.0} : Vec2{-0.0, 0.5};
      const Vec2 corner = ceiling ? Vec2{-0.5, -0.5} : Vec2{-0.5, 0.5};
      for (const Vec2 d : {first, corner, corner}) {
        const Vec2 goal = w.rect(b).position() + d;
        const test::ReferenceResult ref =
            test::referenceMove(w, b, w.rect(b), goal, Filter{}, 64, kBuiltins);
        const MoveResult r = m.move(w, b, goal);
        EXPECT_FALSE(r.collisions.empty()) << name;
        const std::vector<Collision> c(r.collisions.begin(), r.collisions.end());
        EXPECT_EQ(difference({r.position, c}, {ref.position, ref.collisions}), "")
            << name << (ceiling ? " ceiling" : " floor");
      }
    };
    play("adaptive");
    play("continuous");
  }
}

TEST(FloorMoves, ATraceChangesNothing) {
  FloorScene a(5), b(5);
  Mover traced(parseMover("adaptive")), plain(parseMover("adaptive"));
  MoveTrace trace;
  for (int t = 0; t < 120; ++t) {
    for (std::size_t i = 0; i < a.bodies.size(); ++i) {
      const MoveResult ra = a.step(traced, i, &trace);
      const std::vector<Collision> ca(ra.collisions.begin(), ra.collisions.end());
      ASSERT_EQ(difference({ra.position, ca}, b.step(plain, i)), "") << "tick " << t;
      if constexpr (kTraceCompiledIn) {
        ASSERT_EQ(trace.final, ra.position);
        ASSERT_EQ(trace.hits.size(), ca.size());
      }
    }
  }
  EXPECT_EQ(a.world.stateHash(), b.world.stateHash());
}

// Random tiles, bodies of random sizes, short and medium moves in every direction, and a filter
// that mixes every built-in response with a user's: the moves that stay in their box and those
// whose legs leave it (bounce, a user's response, long moves) all come out as the reference's.
TEST(FloorMoves, RandomScenesWithEveryResponseEqualTheReference) {
  const ResponseFn bump = [](const Collision& c, Vec2) -> Leg { return {c.touch, c.touch}; };
  for (const std::uint64_t seed : {21u, 22u, 23u, 24u}) {
    World world(32);
    std::vector<ItemId> bodies;
    sim::Rng rng(seed);
    const ResponseId user = world.addResponse("bump", bump);
    std::vector<ResponseFn> fns = kBuiltins;
    fns.push_back(bump);
    for (int i = 0; i < 120; ++i) {
      world.add({std::floor(rng.uniform(0, 30)) * 16, std::floor(rng.uniform(0, 30)) * 16, 16,
                 16});
    }
    for (int i = 0; i < 60; ++i) {
      const double w = std::floor(rng.uniform(2, 20) * 4) / 4,
                   h = std::floor(rng.uniform(2, 20) * 4) / 4;
      const Rect r{std::floor(rng.uniform(0, 480) * 8) / 8, std::floor(rng.uniform(0, 480) * 8) / 8,
                   w, h};
      if (world.anyOverlap(r)) continue;
      bodies.push_back(world.add(r));
    }
    const auto filter = [user](ItemId item, ItemId other) -> ResponseId {
      switch ((item.index * 7 + other.index * 3) % 11) {
        case 0:
          return response::ignore;
        case 1:
          return response::touch;
        case 2:
          return response::cross;
        case 3:
          return response::bounce;
        case 4:
          return user;
        default:
          return response::slide;
      }
    };
    Mover adaptive(parseMover("adaptive"));
    for (int t = 0; t < 200; ++t) {
      for (std::size_t i = 0; i < bodies.size(); ++i) {
        // Mostly short moves, often pressing straight down or sideways, sometimes long.
        const double scale = t % 20 < 15 ? 1.0 : 12.0;
        Vec2 d{rng.uniform(-3, 3) * scale, rng.uniform(-3, 3) * scale};
        if (rng.below(3) == 0) d.x = 0.0;
        if (rng.below(3) == 0) d.y = 0.5;
        d = {std::floor(d.x * 16) / 16, std::floor(d.y * 16) / 16};
        const Rect from = world.rect(bodies[i]);
        const Vec2 goal = from.position() + d;
        const test::ReferenceResult ref =
            test::referenceMove(world, bodies[i], from, goal, filter, 64, fns);
        const MoveResult r = adaptive.move(world, bodies[i], goal, filter);
        const std::vector<Collision> c(r.collisions.begin(), r.collisions.end());
        ASSERT_EQ(difference({r.position, c}, {ref.position, ref.collisions}), "")
            << "seed " << seed << ", tick " << t << ", body " << i;
      }
    }
  }
}

}  // namespace
}  // namespace tv
