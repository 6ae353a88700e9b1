// Game-like scenes.
//   platformer  a small level and a scripted player: run, jump, land
//   crowd       many small movers among tiles, ~30% solid; the world grows with their number
#include <algorithm>
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

}  // namespace

void registerGameScenes(SceneRegistry& r) {
  r.add(platformer());
  r.add(crowd());
}

}  // namespace tv::sim::detail
