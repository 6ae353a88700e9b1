// Specification of the no-seam-snag guarantee (tv/world.hpp): walking along a floor made of
// separate tiles, or falling along a wall made of stacked tiles, never catches on the seams
// between them — for every body size, at any offset, at any tile scale.
//
//   1000 tiles, T wide, tops at y = o:
//          +------+ body (w x h), resting: bottom == o, walks right v per tick and is pushed
//          |      |      down g per tick (gravity) -> slides along the floor
//   -------+------+-------------------------------------------------------------
//   |  T   |  T   |  T   |  T   | ...  seams every T: no hit may have a horizontal normal
//   ----------------------------------------------------------------------------

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "tv/world.hpp"

namespace {

using tv::ItemId;
using tv::Rect;
using tv::Vec2;
using tv::World;

constexpr int kTiles = 1000;
constexpr int kSizes = 161;  // 8.0, 8.1, ..., 24.0

// Body i has height 8.0 + i/10 and width 8.0 + ((37 i) mod 161)/10: every height and every
// width occurs once across the 161 bodies, in shuffled pairs (37 is prime to 161).
double heightOf(int i) {
  return 8.0 + i / 10.0;
}
double widthOf(int i) {
  return 8.0 + ((37 * i) % kSizes) / 10.0;
}

struct Config {
  double offset;  // added to every coordinate
  double scale;   // 1 for 16-px tiles; 1/16 for 1-px tiles; 1/160 for 0.1-px tiles
  const char* name;
};

constexpr Config kConfigs[] = {
    {0.0, 1.0, "16 px tiles at offset 0"},          {1e6, 1.0, "16 px tiles at offset 1e6"},
    {1e9, 1.0, "16 px tiles at offset 1e9"},        {0.0, 1.0 / 16.0, "1 px tiles at offset 0"},
    {0.0, 1.0 / 160.0, "0.1 px tiles at offset 0"},  {1e6, 1.0 / 16.0, "1 px tiles at offset 1e6"},
    {1e9, 1.0 / 16.0, "1 px tiles at offset 1e9"},  {1e6, 1.0 / 160.0, "0.1 px tiles at offset 1e6"},
    {1e9, 1.0 / 160.0, "0.1 px tiles at offset 1e9"},
};

struct Walk {
  long wrongNormals = 0;  // hits whose normal is across the surface (a snag)
  long offSurface = 0;    // ticks that ended off the surface (the resting coordinate moved)
  bool reached = false;
  Vec2 end;
};

// A body of `size` (already scaled) rests on a floor of kTiles tiles and walks along it in
// direction `dir` (+1 right, -1 left), 2.5 px per tick while gravity pushes it 0.3 px per tick
// into the floor (both scaled). `raised` >= 0 lifts that tile's top by one ulp: a real step
// (see the control test).
Walk walkAlongFloor(const Config& c, Vec2 size, int dir, int raised = -1) {
  const double t = 16.0 * c.scale, o = c.offset;
  World world(4 * t);
  for (int k = 0; k < kTiles; ++k) {
    double top = o;
    if (k == raised) top = std::nextafter(top, -std::numeric_limits<double>::infinity());
    (void)world.add({o + k * t, top, t, t});
  }
  // From the second tile to the last one, or back.
  const double first = o + t, last = o + (kTiles - 1) * t - size.x;
  const double startX = dir > 0 ? first : last, endX = dir > 0 ? last : first;
  const ItemId body = world.add({startX, tv::placeBefore(o, size.y), size.x, size.y});
  const double v = dir * 2.5 * c.scale, g = 0.3 * c.scale;
  const double y0 = world.rect(body).y;
  const long maxTicks = std::lround((last - first) / std::fabs(v)) + 10;
  const auto arrived = [&](double x) { return dir > 0 ? x >= endX : x <= endX; };
  Walk w;
  for (long tick = 0; tick < maxTicks; ++tick) {
    const Vec2 p = world.rect(body).position();
    if (arrived(p.x)) break;
    const tv::MoveResult r = world.move(body, {p.x + v, p.y + g});
    for (const tv::Collision& col : r.collisions) w.wrongNormals += col.normal.x != 0.0;
    w.offSurface += r.position.y != y0;
  }
  w.end = world.rect(body).position();
  w.reached = arrived(w.end.x);
  return w;
}

// A body presses into a wall of kTiles stacked tiles (x from o to o + T) from the side `dir`
// points to (+1: the body is left of the wall and pushes right; -1: right of it, pushing left)
// and falls along it 2.5 px per tick, pressing `press` px per tick (both scaled; 0 = alongside).
Walk fallAlongWall(const Config& c, Vec2 size, int dir, double press) {
  const double t = 16.0 * c.scale, o = c.offset;
  World world(4 * t);
  for (int k = 0; k < kTiles; ++k) (void)world.add({o, o + k * t, t, t});
  const double x0 = dir > 0 ? tv::placeBefore(o, size.x) : o + t;
  const ItemId body = world.add({x0, o + t, size.x, size.y});
  const double v = 2.5 * c.scale, push = dir * press * c.scale;
  const double endY = o + (kTiles - 1) * t - size.y;
  const long maxTicks = std::lround((endY - o) / v) + 10;
  Walk w;
  for (long tick = 0; tick < maxTicks; ++tick) {
    const Vec2 p = world.rect(body).position();
    if (p.y >= endY) break;
    const tv::MoveResult r = world.move(body, {p.x + push, p.y + v});
    for (const tv::Collision& col : r.collisions) w.wrongNormals += col.normal.y != 0.0;
    w.offSurface += r.position.x != x0;
  }
  w.end = world.rect(body).position();
  w.reached = w.end.y >= endY;
  return w;
}

// Collects failures and reports the first few, naming the body and the configuration.
struct Failures {
  std::vector<std::string> lines;
  void check(const Walk& w, const Config& c, int i, Vec2 size) {
    if (w.wrongNormals == 0 && w.offSurface == 0 && w.reached) return;
    char buf[256];
    std::snprintf(buf, sizeof buf,
                  "%s: body %d (w %.17g, h %.17g): %ld snag hits, %ld ticks off the surface, "
                  "%s (ended at %.17g, %.17g)",
                  c.name, i, size.x, size.y, w.wrongNormals, w.offSurface,
                  w.reached ? "reached the end" : "did NOT reach the end", w.end.x, w.end.y);
    lines.emplace_back(buf);
  }
  ~Failures() {
    for (std::size_t k = 0; k < lines.size() && k < 10; ++k) ADD_FAILURE() << lines[k];
    if (lines.size() > 10) ADD_FAILURE() << "... and " << lines.size() - 10 << " more";
  }
};

Vec2 bodySize(const Config& c, int i) {
  return Vec2{widthOf(i), heightOf(i)} * c.scale;
}

TEST(Seam, WalkingRightAlongAFloorOfTilesNeverCatchesOnASeam) {
  Failures f;
  for (const Config& c : kConfigs) {
    for (int i = 0; i < kSizes; ++i)
      f.check(walkAlongFloor(c, bodySize(c, i), +1), c, i, bodySize(c, i));
  }
}

TEST(Seam, WalkingLeftAlongAFloorOfTilesNeverCatchesOnASeam) {
  Failures f;
  for (const Config& c : kConfigs) {
    for (int i = 0; i < kSizes; ++i)
      f.check(walkAlongFloor(c, bodySize(c, i), -1), c, i, bodySize(c, i));
  }
}

TEST(Seam, FallingWhilePressingIntoAWallOfTilesNeverCatchesOnASeam) {
  Failures f;
  for (const Config& c : kConfigs) {
    for (int i = 0; i < kSizes; ++i) {
      f.check(fallAlongWall(c, bodySize(c, i), +1, 0.3), c, i, bodySize(c, i));
      f.check(fallAlongWall(c, bodySize(c, i), -1, 0.3), c, i, bodySize(c, i));
    }
  }
}

TEST(Seam, FallingAlongsideAWallOfTilesTouchingItNeverHitsIt) {
  Failures f;
  for (const Config& c : kConfigs) {
    for (int i = 0; i < kSizes; i += 8) {
      f.check(fallAlongWall(c, bodySize(c, i), +1, 0.0), c, i, bodySize(c, i));
      f.check(fallAlongWall(c, bodySize(c, i), -1, 0.0), c, i, bodySize(c, i));
    }
  }
}

// The control: the counters above do see a snag when there is one. Tile 500's top raised by
// one ulp is a step the body's side runs into; it stops there.
TEST(Seam, AStepOfOneUlpIsARealStepAndStopsTheWalker) {
  for (const Config& c : {kConfigs[0], kConfigs[2], kConfigs[4]}) {
    for (const int dir : {+1, -1}) {
      const Walk w = walkAlongFloor(c, bodySize(c, 40), dir, 500);
      EXPECT_GT(w.wrongNormals, 0) << c.name << " dir " << dir;
      EXPECT_FALSE(w.reached) << c.name << " dir " << dir;
    }
  }
}

}  // namespace
