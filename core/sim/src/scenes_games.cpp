// Game-like scenes.
//   platformer  a small level and a scripted player: run, jump, land
//   crowd       many small movers among tiles, ~30% solid; the world grows with their number
//   bump-crowd  bump.lua's own benchmark scene: movers sliding among random platforms
#include <algorithm>
#include <bit>
#include <cmath>
#include <numbers>
#include <string_view>

#include "scene_kit.hpp"
#include "tv/world.hpp"

namespace tv::sim::detail {
namespace {

// [SECTION] platformer ----------------------------------------------------------------------------
//
// The level ('#' solid, 'P' where players start; pits drop out of the level):

constexpr std::string_view kLevel[] = {
    "##########################################################",
    "#........................................................#",
    "#..............................######....................#",
    "#........................................................#",
    "#...................####...........................####..#",
    "#........................................................#",
    "#...........###..................................###.....#",
    "#.......................####.............................#",
    "#P.......................................................#",
    "#######....#########...##############...######....#######",
    "#######....#########...##############...######....#######",
};
constexpr std::size_t kLevelRows = std::size(kLevel);

// The script, per player: run in its direction; turn around on hitting a wall; jump whenever
// grounded on ticks where (tick + 17·player) % 45 == 0. A player that falls out of the level
// respawns at 'P'. `state`: bit 0 grounded, bit 1 facing left.
//   jumps, landings, respawns as named.

constexpr std::int32_t kGrounded = 1;
constexpr std::int32_t kFacingLeft = 2;

class PlatformerRules final : public SceneRules {
 public:
  PlatformerRules(double run, double jump, Vec2 start, double killY)
      : run_(run), jump_(jump), start_(start), killY_(killY) {}

  void control(TickContext& ctx) const override {
    for (Body& b : ctx.bodies) {
      b.velocity.x = (b.state & kFacingLeft) != 0 ? -run_ : run_;
      if ((b.state & kGrounded) != 0 && (ctx.tick + 17 * b.group) % 45 == 0) {
        b.velocity.y = -jump_;
        b.state &= ~kGrounded;
        ++ctx.counters.jumps;
      }
    }
  }

  void afterMove(TickContext& ctx, std::size_t i, Vec2,
                 std::span<const Collision> cols) const override {
    Body& b = ctx.bodies[i];
    for (const Collision& c : cols) {
      if (c.normal.x > 0.0) b.state &= ~kFacingLeft;
      if (c.normal.x < 0.0) b.state |= kFacingLeft;
    }
    // Grounded: not rising, and a solid right under the feet. Asked of the world, not of this
    // move's collisions, so a mover that did not touch the floor this tick (the pixel mover
    // carrying a sub-pixel remainder) still stands.
    const Rect feet{b.rect.x, b.rect.bottom(), b.rect.w, 1.0};
    const bool grounded =
        b.velocity.y >= 0.0 && ctx.world.anyOverlap(feet, b.item, [&ctx](ItemId, ItemId other) {
          return ctx.bodyOf(other) < 0 ? response::touch : response::ignore;
        });
    if (grounded && (b.state & kGrounded) == 0) ++ctx.counters.landings;
    b.state = grounded ? (b.state | kGrounded) : (b.state & ~kGrounded);
    if (b.rect.y > killY_) {
      ++ctx.counters.respawns;
      b.rect = b.rect.at(start_);  // the simulation moves the world's item to match
      b.velocity = {};
      b.state = 0;
    }
  }

 private:
  double run_, jump_;
  Vec2 start_;
  double killY_;
};

SceneSetup buildPlatformer(const Params& p) {
  const Common c = readCommon(p);
  const double t = c.tile;
  if (c.size >= 2 * t) {
    sceneFail("platformer", "size must be < 2 tiles (" + formatNumber(2 * t) +
                                ") to fit the level's corridors, but was " + formatNumber(c.size));
  }
  SceneSetup s;
  s.cellSize = c.cell;
  const double gravity = p.get("gravity");
  s.gravity = {0.0, gravity};
  Vec2 start;
  for (std::size_t row = 0; row < kLevelRows; ++row) {
    for (std::size_t col = 0; col < kLevel[row].size(); ++col) {
      const Vec2 at{c.offset + static_cast<double>(col) * t,
                    c.offset + static_cast<double>(row) * t};
      if (kLevel[row][col] == '#') s.solids.push_back({{at.x, at.y, t, t}});
      if (kLevel[row][col] == 'P') start = {at.x, at.y + t - c.size};
    }
  }
  for (std::int64_t i = 0; i < c.count; ++i) {
    Body b = makeBody({start.x, start.y, c.size, c.size}, BodyRole::player, kLayerPlayer,
                      kLayerSolid, response::slide, {}, static_cast<std::uint32_t>(i));
    b.falls = true;
    b.contacts = true;  // as a platformer reads its player's ground and touches
    s.bodies.push_back(b);
  }
  const double jump = std::sqrt(2.0 * gravity * 3.5 * t);  // clears 3.5 tiles
  const double killY = c.offset + static_cast<double>(kLevelRows + 4) * t;
  s.rules = std::make_shared<PlatformerRules>(c.speed, jump, start, killY);
  return s;
}

SceneDef platformer() {
  CommonDefaults d;
  d.speed = 150;
  d.size = 12;
  d.count = 1;
  d.maxCount = 64;
  d.speedMeaning = "running speed";
  d.sizeMeaning = "side of the player";
  d.countMeaning = "players (they do not meet; each jumps on its own beat)";
  SceneDef def;
  def.category = "Games";
  def.tagNames = {"tile"};
  def.name = "platformer";
  def.description = "a small level with a scripted player: run, jump, land, fall and respawn";
  def.params = commonParams(d);
  def.params.push_back(
      realParam("gravity", "px/s²", "downward acceleration", 1800, 0.0, 1e7, true));
  def.camera = [](const Params& p) {
    const Common c = readCommon(p);
    return Rect{c.offset, c.offset, static_cast<double>(kLevel[0].size()) * c.tile,
                static_cast<double>(kLevelRows + 1) * c.tile};
  };
  def.build = buildPlatformer;
  return def;
}

// [SECTION] crowd ---------------------------------------------------------------------------------
//
// A square of tiles, side max(16, ceil(sqrt(5·count))), walled all round, each inner tile solid
// with probability 0.3; `count` movers start centred in distinct free tiles with random
// directions at `speed`. They bounce off solids and each other.
//   overlaps  moves that ended inside a solid (a mover never starts in one)
//   hits      collisions with solids

class CrowdRules final : public SceneRules {
 public:
  void afterMove(TickContext& ctx, std::size_t i, Vec2,
                 std::span<const Collision> cols) const override {
    const Body& b = ctx.bodies[i];
    for (const Collision& c : cols) {
      if (ctx.bodyOf(c.other) < 0) ++ctx.counters.hits;
    }
    const bool inSolid = ctx.world.anyOverlap(b.rect, b.item, [&ctx](ItemId, ItemId other) {
      return ctx.bodyOf(other) < 0 ? response::touch : response::ignore;
    });
    if (inSolid) ++ctx.counters.overlaps;
  }
};

std::int64_t crowdSide(std::int64_t count) {
  return std::max<std::int64_t>(
      16, static_cast<std::int64_t>(std::ceil(std::sqrt(5.0 * static_cast<double>(count)))));
}

SceneSetup buildCrowd(const Params& p) {
  const Common c = readCommon(p);
  const double t = c.tile;
  if (c.size > t) {
    sceneFail("crowd", "size must be <= tile (" + formatNumber(t) +
                           ") so a mover fits a free tile, but was " + formatNumber(c.size));
  }
  const std::int64_t side = crowdSide(c.count);
  SceneSetup s;
  s.cellSize = c.cell;
  Rng rng(c.seed);
  std::vector<Vec2> free;
  for (std::int64_t y = 0; y < side; ++y) {
    for (std::int64_t x = 0; x < side; ++x) {
      const Vec2 at{c.offset + static_cast<double>(x) * t, c.offset + static_cast<double>(y) * t};
      const bool border = x == 0 || y == 0 || x == side - 1 || y == side - 1;
      if (border || rng.uniform() < 0.3) {
        s.solids.push_back({{at.x, at.y, t, t}});
      } else {
        free.push_back(at);
      }
    }
  }
  if (free.size() < static_cast<std::size_t>(c.count)) {
    sceneFail("crowd", "only " + std::to_string(free.size()) + " free tiles for count " +
                           std::to_string(c.count) + " (try another seed)");
  }
  for (std::size_t k = 0; k < static_cast<std::size_t>(c.count); ++k) {  // partial Fisher-Yates
    std::swap(free[k], free[k + rng.below(free.size() - k)]);
  }
  const double inset = (t - c.size) * 0.5;
  for (std::int64_t i = 0; i < c.count; ++i) {
    const Vec2 at = free[static_cast<std::size_t>(i)];
    const double a = 2.0 * std::numbers::pi * rng.uniform();
    s.bodies.push_back(makeBody({at.x + inset, at.y + inset, c.size, c.size}, BodyRole::crowd,
                                kLayerCrowd, kLayerSolid | kLayerCrowd, response::bounce,
                                Vec2{std::cos(a), std::sin(a)} * c.speed,
                                static_cast<std::uint32_t>(i)));
  }
  s.rules = std::make_shared<CrowdRules>();
  return s;
}

SceneDef crowd() {
  CommonDefaults d;
  d.speed = 120;
  d.size = 8;
  d.count = 200;
  d.cell = 32;
  d.speedMeaning = "speed of every mover";
  d.sizeMeaning = "side of a mover (at most one tile)";
  d.countMeaning = "movers; the world grows with them";
  SceneDef def;
  def.category = "Games";
  def.tagNames = {"tile"};
  def.name = "crowd";
  def.description = "many small movers bouncing among tiles ~30% solid; the world grows with them";
  def.params = commonParams(d);
  def.camera = [](const Params& p) {
    const Common c = readCommon(p);
    const double side =
        static_cast<double>(std::min<std::int64_t>(crowdSide(c.count), 48)) * c.tile;
    return Rect{c.offset, c.offset, side, side};
  };
  def.build = buildCrowd;
  return def;
}

// [SECTION] bump-crowd ----------------------------------------------------------------------------
//
// bump.lua's benchmark scene, so that our figures compare with the numbers its users know: a
// square world of tiles (2000 px a side up to 10^4 movers, 6320 px beyond: the same density) with
// a solid one-tile border, plus random horizontal platforms 3-12 tiles long (clipped inside the
// border) until 30% of the grid is solid, one item per tile. `count` movers at random free spots
// (overlapping no tile and no other mover), random directions, speeds uniform in
// [speed / 8, speed]. Each moves with `slide` and flips the velocity component of each
// collision normal it reports (a component already leaving the obstacle is kept). `meet` 0:
// movers ignore each other; 1: they slide against each other too.
//   hits  collisions with solids
//
// Flipping keeps each component's magnitude, so a mover's |vx| and |vy| are constants: built as
// floats, kept in `group` and `state` as their bits, and a collision sets the component to the
// magnitude with the sign of its normal — exactly what flipping does, after the slide response
// has zeroed the component that pointed into the obstacle.

constexpr std::string_view kMeet = "meet";

class BumpCrowdRules final : public SceneRules {
 public:
  void afterMove(TickContext& ctx, std::size_t i, Vec2,
                 std::span<const Collision> cols) const override {
    Body& b = ctx.bodies[i];
    const double ax = std::bit_cast<float>(b.group);
    const double ay = std::bit_cast<float>(static_cast<std::uint32_t>(b.state));
    for (const Collision& c : cols) {
      if (ctx.bodyOf(c.other) < 0) ++ctx.counters.hits;
      if (c.normal.x != 0.0) b.velocity.x = c.normal.x > 0.0 ? ax : -ax;
      if (c.normal.y != 0.0) b.velocity.y = c.normal.y > 0.0 ? ay : -ay;
    }
  }
};

double bumpCrowdSide(std::int64_t count) {
  return count > 10000 ? 6320.0 : 2000.0;
}

SceneSetup buildBumpCrowd(const Params& p) {
  const Common c = readCommon(p);
  const double t = c.tile;
  const auto side = static_cast<std::int64_t>(bumpCrowdSide(c.count) / t);
  if (side < 4)
    sceneFail("bump-crowd", "tile " + formatNumber(t) + " leaves fewer than 4 tiles a side");
  if (c.size >= t) {
    sceneFail("bump-crowd",
              "size must be < tile (" + formatNumber(t) + "), but was " + formatNumber(c.size));
  }
  SceneSetup s;
  s.cellSize = c.cell;
  Rng rng(c.seed);
  std::vector<std::uint8_t> solid(static_cast<std::size_t>(side * side), 0);
  std::int64_t solidCount = 0;
  const auto set = [&](std::int64_t x, std::int64_t y) {
    std::uint8_t& cell = solid[static_cast<std::size_t>(y * side + x)];
    if (cell == 0) ++solidCount;
    cell = 1;
  };
  for (std::int64_t k = 0; k < side; ++k) {
    set(k, 0);
    set(k, side - 1);
    set(0, k);
    set(side - 1, k);
  }
  const auto target = static_cast<std::int64_t>(std::ceil(0.3 * static_cast<double>(side * side)));
  const auto inner = static_cast<std::uint64_t>(side - 2);
  while (solidCount < target) {
    const auto length = 3 + static_cast<std::int64_t>(rng.below(10));
    const auto y = 1 + static_cast<std::int64_t>(rng.below(inner));
    const auto x0 = 1 + static_cast<std::int64_t>(rng.below(inner));
    for (std::int64_t x = x0; x < std::min(x0 + length, side - 1); ++x) set(x, y);
  }
  // The free spots are found against a world of the same cell size holding what is placed.
  World placed(c.cell);
  for (std::int64_t y = 0; y < side; ++y) {
    for (std::int64_t x = 0; x < side; ++x) {
      if (solid[static_cast<std::size_t>(y * side + x)] == 0) continue;
      const Rect r{c.offset + static_cast<double>(x) * t, c.offset + static_cast<double>(y) * t, t,
                   t};
      s.solids.push_back({r});
      (void)placed.add(r);
    }
  }
  const double lo = c.offset + t, hi = c.offset + static_cast<double>(side - 1) * t - c.size;
  const std::int64_t attempts = 1000 + 100 * c.count;
  for (std::int64_t tried = 0; static_cast<std::int64_t>(s.bodies.size()) < c.count; ++tried) {
    if (tried == attempts) {
      sceneFail("bump-crowd", "could not place " + std::to_string(c.count) +
                                  " movers (try a smaller count or size)");
    }
    const Rect r{rng.uniform(lo, hi), rng.uniform(lo, hi), c.size, c.size};
    if (placed.anyOverlap(r)) continue;
    (void)placed.add(r);
    const double angle = 2.0 * std::numbers::pi * rng.uniform();
    const double speed = rng.uniform(c.speed / 8.0, c.speed);
    const auto vx = static_cast<float>(std::cos(angle) * speed);
    const auto vy = static_cast<float>(std::sin(angle) * speed);
    const std::uint32_t mask = p.getInt(kMeet) != 0 ? kLayerSolid | kLayerCrowd : kLayerSolid;
    Body b = makeBody(r, BodyRole::crowd, kLayerCrowd, mask, response::slide, Vec2{vx, vy},
                      std::bit_cast<std::uint32_t>(std::fabs(vx)));
    b.state = static_cast<std::int32_t>(std::bit_cast<std::uint32_t>(std::fabs(vy)));
    s.bodies.push_back(b);
  }
  s.rules = std::make_shared<BumpCrowdRules>();
  return s;
}

SceneDef bumpCrowd() {
  CommonDefaults d;
  d.speed = 240;
  d.size = 8;
  d.count = 1000;
  d.cell = 32;
  d.speedMeaning = "fastest mover; speeds are uniform in [speed / 8, speed]";
  d.sizeMeaning = "side of a mover (less than a tile)";
  d.countMeaning = "movers; 2000 px world up to 10^4, 6320 px beyond";
  SceneDef def;
  def.category = "Games";
  def.tagNames = {"tile"};
  def.name = "bump-crowd";
  def.description = "bump.lua's benchmark: movers sliding among random platforms, 30% solid";
  def.params = commonParams(d);
  def.params.push_back(intParam(
      std::string(kMeet), "1: movers slide against each other; 0: they pass through", 0, 0, 1));
  def.camera = [](const Params& p) {
    const Common c = readCommon(p);
    const double side = std::min(bumpCrowdSide(c.count), 800.0);
    return Rect{c.offset, c.offset, side, side};
  };
  def.build = buildBumpCrowd;
  return def;
}

}  // namespace

void registerGameScenes(SceneRegistry& r) {
  r.add(platformer());
  r.add(crowd());
  r.add(bumpCrowd());
}

}  // namespace tv::sim::detail
