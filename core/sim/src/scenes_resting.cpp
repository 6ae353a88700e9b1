// Contact scenes: bodies that must stay put, walk a seam, or stay inside a narrow gap.
//   rest-wall   a body pressed against a wall, standing on a floor, under gravity
//   rest-floor  bodies dropped onto a floor, resting under gravity
//   seam-walk   walking along a floor of 1000 separate tiles under gravity
//   bounce-gap  balls bouncing in a gap narrower than one tick's travel
#include <cmath>

#include "scene_kit.hpp"
#include "tv/world.hpp"

namespace tv::sim::detail {
namespace {

constexpr std::uint8_t kFloor = 1;
constexpr std::uint8_t kWall = 2;

ParamSpec gravityParam(double value) {
  return realParam("gravity", "px/s²", "downward acceleration of the bodies that fall", value, 0.0,
                   1e7, false);
}

std::uint32_t group(std::int64_t i) {
  return static_cast<std::uint32_t>(i);
}

// [SECTION] rest-wall -----------------------------------------------------------------------------
//
// One room per body; the body stands on the floor 1..3 px left of a wall and is pushed right at
// `speed` every tick:
//
//                 |##|
//        [body]-> |##|  wall: 3 tiles on the floor
//   ##############|##|  floor: 10 tiles
//
// Once the body has been stopped by the wall (a collision with a normal pointing left), it must
// never move again: `jitter` counts the ticks after that in which its position changed.

constexpr std::int32_t kPressed = 1;

class RestWallRules final : public SceneRules {
 public:
  explicit RestWallRules(double push) : push_(push) {}
  void control(TickContext& ctx) const override {
    for (Body& b : ctx.bodies) b.velocity.x = push_;
  }
  void afterMove(TickContext& ctx, std::size_t i, Vec2,
                 std::span<const Collision> cols) const override {
    Body& b = ctx.bodies[i];
    if ((b.state & kPressed) != 0 && b.rect.position() != ctx.previous[i]) ++ctx.counters.jitter;
    for (const Collision& c : cols) {
      if (c.normal.x < 0.0) b.state |= kPressed;
    }
  }

 private:
  double push_;
};

SceneSetup buildRestWall(const Params& p) {
  const Common c = readCommon(p);
  const double t = c.tile;
  SceneSetup s;
  s.cellSize = c.cell;
  s.gravity = {0.0, p.get("gravity")};
  const double roomHeight = t * (4.0 + std::ceil(c.size / t));
  Rng rng(c.seed);
  for (std::int64_t i = 0; i < c.count; ++i) {
    const double ox = c.offset;
    const double floorY = c.offset + static_cast<double>(i) * roomHeight + roomHeight - t;
    for (int k = 0; k < 10; ++k) s.solids.push_back({{ox + k * t, floorY, t, t}, kFloor});
    for (int k = 1; k <= 3; ++k) s.solids.push_back({{ox + 9 * t, floorY - k * t, t, t}, kWall});
    const double gap = 1.0 + 2.0 * rng.uniform();
    Body b =
        makeBody({ox + 9 * t - c.size - gap, floorY - c.size, c.size, c.size}, BodyRole::player,
                 kLayerPlayer, kLayerSolid, response::slide, {c.speed, 0}, group(i));
    b.falls = true;
    s.bodies.push_back(b);
  }
  s.rules = std::make_shared<RestWallRules>(c.speed);
  return s;
}

SceneDef restWall() {
  CommonDefaults d;
  d.speed = 120;
  d.count = 4;
  d.maxCount = 10000;
  d.speedMeaning = "how hard the body is pushed into the wall, as a speed";
  d.countMeaning = "bodies, one room each";
  SceneDef def;
  def.category = "Resting";
  def.tagNames = {"solid", "floor tile", "wall tile"};
  def.name = "rest-wall";
  def.description = "a body pushed against a wall while standing on a floor; must not jitter";
  def.params = commonParams(d);
  def.params.push_back(gravityParam(1800));
  def.camera = [](const Params& p) {
    const Common c = readCommon(p);
    return Rect{c.offset - c.tile, c.offset, 12 * c.tile,
                2 * c.tile * (4.0 + std::ceil(c.size / c.tile))};
  };
  def.build = buildRestWall;
  return def;
}

// [SECTION] rest-floor ----------------------------------------------------------------------------
//
//     []        []
//          []        []     bodies dropped from 1..5 tiles up at `speed`, at sub-pixel x
//   ######################  one floor of tiles
//
// Once a body has landed (a collision with a normal pointing up) it must never move again.
//   jitter   ticks after landing in which a body's position changed
//   landings bodies that landed

constexpr std::int32_t kLanded = 1;

class RestFloorRules final : public SceneRules {
 public:
  void afterMove(TickContext& ctx, std::size_t i, Vec2,
                 std::span<const Collision> cols) const override {
    Body& b = ctx.bodies[i];
    if ((b.state & kLanded) != 0 && b.rect.position() != ctx.previous[i]) ++ctx.counters.jitter;
    for (const Collision& c : cols) {
      if (c.normal.y < 0.0 && (b.state & kLanded) == 0) {
        b.state |= kLanded;
        ++ctx.counters.landings;
      }
    }
  }
};

SceneSetup buildRestFloor(const Params& p) {
  const Common c = readCommon(p);
  const double t = c.tile;
  const double pitch = t * std::ceil((c.size + t) / t);
  SceneSetup s;
  s.cellSize = c.cell;
  s.gravity = {0.0, p.get("gravity")};
  const double floorY = c.offset + t * (6.0 + std::ceil(c.size / t));
  const double width = static_cast<double>(c.count) * pitch + 2 * t;
  const auto tiles = static_cast<std::int64_t>(std::ceil(width / t));
  for (std::int64_t k = 0; k < tiles; ++k) {
    s.solids.push_back({{c.offset + static_cast<double>(k) * t, floorY, t, t}, kFloor});
  }
  Rng rng(c.seed);
  for (std::int64_t i = 0; i < c.count; ++i) {
    const double x =
        c.offset + t + static_cast<double>(i) * pitch + rng.uniform() * (pitch - c.size);
    const double drop = t * (1.0 + 4.0 * rng.uniform());
    Body b = makeBody({x, floorY - c.size - drop, c.size, c.size}, BodyRole::block, kLayerCrowd,
                      kLayerSolid, response::slide, {0.0, c.speed}, group(i));
    b.falls = true;
    s.bodies.push_back(b);
  }
  s.rules = std::make_shared<RestFloorRules>();
  return s;
}

SceneDef restFloor() {
  CommonDefaults d;
  d.speed = 60;
  d.count = 8;
  d.maxCount = 10000;
  d.speedMeaning = "initial downward speed of the dropped bodies";
  d.countMeaning = "bodies dropped side by side";
  SceneDef def;
  def.category = "Resting";
  def.tagNames = {"solid", "floor tile", "wall tile"};
  def.name = "rest-floor";
  def.description = "bodies dropped onto a floor under gravity; once landed they must not move";
  def.params = commonParams(d);
  def.params.push_back(gravityParam(1800));
  def.camera = [](const Params& p) {
    const Common c = readCommon(p);
    const double pitch = c.tile * std::ceil((c.size + c.tile) / c.tile);
    const double w = std::min(static_cast<double>(c.count) * pitch + 2 * c.tile, 40 * c.tile);
    return Rect{c.offset, c.offset, w, c.tile * (8.0 + std::ceil(c.size / c.tile))};
  };
  def.build = buildRestFloor;
  return def;
}

// [SECTION] seam-walk -----------------------------------------------------------------------------
//
//   |#|                                                        |#|
//   |#|  [walker] ->                                           |#|   end walls turn walkers
//   |#|################ ... 1000 separate tiles ... ###########|#|   around
//
// A walker pressed onto a floor by gravity walks across 999 seams between tiles. A seam must
// never stop it: `snags` counts collisions with a floor tile whose normal is horizontal.
// Walkers do not meet each other. `state` is the walking direction, +1 or -1.

constexpr double kSeamTiles = 1000.0;

class SeamWalkRules final : public SceneRules {
 public:
  explicit SeamWalkRules(double speed) : speed_(speed) {}
  void control(TickContext& ctx) const override {
    for (Body& b : ctx.bodies) b.velocity.x = speed_ * static_cast<double>(b.state);
  }
  void afterMove(TickContext& ctx, std::size_t i, Vec2,
                 std::span<const Collision> cols) const override {
    Body& b = ctx.bodies[i];
    for (const Collision& c : cols) {
      if (c.normal.x == 0.0) continue;
      const std::uint8_t tag = ctx.tagOf(c.other);
      if (tag == kFloor) ++ctx.counters.snags;
      if (tag == kWall) b.state = c.normal.x < 0.0 ? -1 : 1;
    }
  }

 private:
  double speed_;
};

SceneSetup buildSeamWalk(const Params& p) {
  const Common c = readCommon(p);
  const double t = c.tile;
  const double wallTiles = 2.0 + std::ceil(c.size / t);
  const double floorY = c.offset + t * (wallTiles + 1.0);
  SceneSetup s;
  s.cellSize = c.cell;
  s.gravity = {0.0, p.get("gravity")};
  for (double k = 0; k < kSeamTiles; ++k)
    s.solids.push_back({{c.offset + k * t, floorY, t, t}, kFloor});
  for (double k = 1; k <= wallTiles; ++k) {
    s.solids.push_back({{c.offset - t, floorY - k * t, t, t}, kWall});
    s.solids.push_back({{c.offset + kSeamTiles * t, floorY - k * t, t, t}, kWall});
  }
  const double span = kSeamTiles * t - c.size;
  Rng rng(c.seed);
  for (std::int64_t i = 0; i < c.count; ++i) {
    const double x = c.offset + std::fmod(2 * t + static_cast<double>(i) * 3 * t, span) +
                     rng.uniform() * t * 0.5;
    Body b =
        makeBody({std::min(x, c.offset + span), floorY - c.size, c.size, c.size}, BodyRole::walker,
                 kLayerPlayer, kLayerSolid, response::slide, {c.speed, 0.0}, group(i));
    b.falls = true;
    b.state = 1;
    s.bodies.push_back(b);
  }
  s.rules = std::make_shared<SeamWalkRules>(c.speed);
  return s;
}

SceneDef seamWalk() {
  CommonDefaults d;
  d.speed = 240;
  d.size = 14;
  d.count = 1;
  d.maxCount = 10000;
  d.speedMeaning = "walking speed";
  d.sizeMeaning = "side of a walker";
  d.countMeaning = "walkers (they do not meet each other)";
  SceneDef def;
  def.category = "Resting";
  def.tagNames = {"solid", "floor tile", "wall tile"};
  def.name = "seam-walk";
  def.description = "walking along a floor of 1000 separate tiles under gravity; no seam may snag";
  def.params = commonParams(d);
  def.params.push_back(gravityParam(1800));
  def.camera = [](const Params& p) {
    const Common c = readCommon(p);
    return Rect{c.offset - c.tile, c.offset, 30 * c.tile,
                c.tile * (5.0 + std::ceil(c.size / c.tile))};
  };
  def.build = buildSeamWalk;
  return def;
}

// [SECTION] bounce-gap ----------------------------------------------------------------------------
//
// One slot per ball: a box `size + gap` wide, walled by one tile on every side.
//
//   |#|######|#|
//   |#|      |#|
//   |#| o -> |#|   the ball's free play across is `gap` (4 px), its travel per tick is
//   |#|      |#|   speed · dt (16 px at the defaults): it bounces several times a tick.
//   |#|######|#|
//
// `escapes` counts balls that ended a tick outside their box (they are then stopped). A mover
// that teleports lands inside a wall and may be pushed out of its far side.

class BounceGapRules final : public SceneRules {
 public:
  explicit BounceGapRules(std::vector<Rect> boxes) : boxes_(std::move(boxes)) {}
  void afterMove(TickContext& ctx, std::size_t i, Vec2, std::span<const Collision>) const override {
    Body& b = ctx.bodies[i];
    const Rect& box = boxes_[b.group];
    const bool inside = b.rect.x >= box.x && b.rect.right() <= box.right() && b.rect.y >= box.y &&
                        b.rect.bottom() <= box.bottom();
    if (!inside) {
      ++ctx.counters.escapes;
      b.velocity = {};
      b.active = false;
    }
  }

 private:
  std::vector<Rect> boxes_;
};

SceneSetup buildBounceGap(const Params& p) {
  const Common c = readCommon(p);
  const double t = c.tile;
  const double w = c.size + p.get("gap");
  const double h = c.size + 4 * t;
  SceneSetup s;
  s.cellSize = c.cell;
  std::vector<Rect> boxes;
  Rng rng(c.seed);
  for (std::int64_t i = 0; i < c.count; ++i) {
    const Rect box{c.offset + t + static_cast<double>(i) * (w + 3 * t), c.offset + t, w, h};
    boxes.push_back(box);
    s.solids.push_back({{box.x - t, box.y - t, t, h + 2 * t}, kWall});
    s.solids.push_back({{box.right(), box.y - t, t, h + 2 * t}, kWall});
    s.solids.push_back({{box.x, box.y - t, w, t}, kWall});
    s.solids.push_back({{box.x, box.bottom(), w, t}, kWall});
    const Vec2 at{box.x + rng.uniform() * (w - c.size), box.y + rng.uniform() * (h - c.size)};
    const double sx = rng.uniform() < 0.5 ? -1.0 : 1.0;
    const double vy = c.speed * 0.25 * (2.0 * rng.uniform() - 1.0);
    s.bodies.push_back(makeBody({at.x, at.y, c.size, c.size}, BodyRole::ball, kLayerCrowd,
                                kLayerSolid, response::bounce, {sx * c.speed, vy}, group(i)));
  }
  s.rules = std::make_shared<BounceGapRules>(std::move(boxes));
  return s;
}

SceneDef bounceGap() {
  CommonDefaults d;
  d.speed = 960;
  d.size = 8;
  d.count = 16;
  d.maxCount = 10000;
  d.speedMeaning = "horizontal ball speed (16 px a tick at 960 px/s and 60 Hz)";
  d.sizeMeaning = "side of a ball";
  d.countMeaning = "balls, one slot each";
  SceneDef def;
  def.category = "Tunnelling";
  def.tagNames = {"solid", "floor tile", "wall"};
  def.name = "bounce-gap";
  def.description = "balls bouncing in a gap narrower than one tick's travel; counts escapes";
  def.params = commonParams(d);
  def.params.push_back(realParam("gap", "px", "free play across a slot (slot width - ball size)",
                                 4.0, 0.0, 1e4, true));
  def.camera = [](const Params& p) {
    const Common c = readCommon(p);
    const double w = c.size + p.get("gap") + 3 * c.tile;
    return Rect{c.offset, c.offset, std::min(static_cast<double>(c.count), 8.0) * w,
                c.size + 6 * c.tile};
  };
  def.build = buildBounceGap;
  return def;
}

}  // namespace

void registerRestingScenes(SceneRegistry& r) {
  r.add(restWall());
  r.add(restFloor());
  r.add(seamWalk());
  r.add(bounceGap());
}

}  // namespace tv::sim::detail
