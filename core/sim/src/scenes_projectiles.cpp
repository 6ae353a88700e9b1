// Tunnelling scenes: fast small things against thin or moving things.
//   bullets-wall     projectiles into one thin wall of tiles; counts tunnelling
//   corner-graze     diagonal shots at tile corners, exact grazes included
//   bullets-enemies  bullets and enemies whose paths cross during a tick
#include <algorithm>
#include <cmath>
#include <numbers>

#include "scene_kit.hpp"
#include "tv/world.hpp"

namespace tv::sim::detail {
namespace {

void stop(Body& b) {
  b.velocity = {};
  b.active = false;
}

bool allDone(std::span<const Body> bodies) {
  return std::none_of(bodies.begin(), bodies.end(), [](const Body& b) { return b.active; });
}

// [SECTION] bullets-wall --------------------------------------------------------------------------
//
//                            |##|
//   lane 0   []--->          |##|      one tile thick; lanes centred on tiles, one lane pitch
//   lane 1        []--->     |##|      (a whole number of tiles > size) apart; the wall runs
//   lane 2      []--->       |##|      past the outer lanes by the shots' sideways drift
//            random phase    |##|
//                            x = offset
//
// Every projectile starts a random fraction of one tick's travel (plus 1 px) short of the wall,
// so across the thousand they reach it at every sub-step phase. A projectile stops at its first
// collision (touch) or once it is past the wall.
//   hits         stopped on the near side
//   tunnelled    ended on the far side (past the wall's right edge)
//   farPushOuts  of those, the ones whose move did report the wall: the mover saw it and pushed
//                the projectile out of its far side (discrete landing past the middle)

constexpr std::string_view kBulletsWall = "bullets-wall";

class BulletsWallRules final : public SceneRules {
 public:
  explicit BulletsWallRules(double wallRight) : wallRight_(wallRight) {}
  void afterMove(TickContext& ctx, std::size_t i, Vec2,
                 std::span<const Collision> cols) const override {
    Body& b = ctx.bodies[i];
    if (b.rect.x >= wallRight_) {
      ++ctx.counters.tunnelled;
      if (!cols.empty()) ++ctx.counters.farPushOuts;
      stop(b);
    } else if (!cols.empty()) {
      ++ctx.counters.hits;
      stop(b);
    }
  }
  bool finished(std::span<const Body> bodies) const override { return allDone(bodies); }

 private:
  double wallRight_;
};

double lanePitch(double tile, double size) {
  return tile * std::ceil((size + tile) / tile);
}

SceneSetup buildBulletsWall(const Params& p) {
  const Common c = readCommon(p);
  const double angle = p.get("angle") * std::numbers::pi / 180.0;
  const Vec2 dir{std::cos(angle), std::sin(angle)};
  const double pitch = lanePitch(c.tile, c.size);
  const double stepX = c.speed * c.dt * dir.x;
  // The wall reaches past the first and last lanes by as far as a shot drifts sideways on its
  // way in, so a mover whose path is not straight (pixel: x first, then y) still meets it.
  const double drift = (1.0 + stepX) * std::fabs(dir.y / dir.x) + c.size;
  const double margin = c.tile * std::ceil(drift / c.tile);
  const double lanes = static_cast<double>(c.count);
  const double top = c.offset - margin;
  const auto rows =
      static_cast<std::int64_t>(std::ceil((lanes * pitch + c.tile + 2 * margin) / c.tile));
  SceneSetup s;
  s.cellSize = c.cell;
  for (std::int64_t k = 0; k < rows; ++k) {
    s.solids.push_back({{c.offset, top + static_cast<double>(k) * c.tile, c.tile, c.tile}});
  }
  Rng rng(c.seed);
  for (std::int64_t i = 0; i < c.count; ++i) {
    // Centred on a tile, not on a seam between two: a seam is a separate failure (see seam-walk).
    const double laneCentre = c.offset + c.tile + static_cast<double>(i) * pitch + c.tile * 0.5;
    const double dx = 1.0 + rng.uniform() * stepX;  // x-distance left to the wall's face
    const Vec2 start{c.offset - c.size - dx, laneCentre - c.size * 0.5 - dx * dir.y / dir.x};
    s.bodies.push_back(makeBody({start.x, start.y, c.size, c.size}, BodyRole::projectile,
                                kLayerProjectile, kLayerSolid, response::touch, dir * c.speed,
                                static_cast<std::uint32_t>(i)));
  }
  s.rules = std::make_shared<BulletsWallRules>(c.offset + c.tile);
  return s;
}

SceneDef bulletsWall() {
  CommonDefaults d;
  d.speed = 1920;
  d.size = 2;
  d.count = 1000;
  d.speedMeaning = "projectile speed";
  d.sizeMeaning = "side of a projectile";
  d.countMeaning = "projectiles, one per lane";
  SceneDef def;
  def.category = "Tunnelling";
  def.tagNames = {"wall tile"};
  def.name = std::string(kBulletsWall);
  def.description =
      "projectiles at random sub-step phases into a one-tile wall; counts how many end past it";
  def.params = commonParams(d);
  def.params.push_back(realParam("angle", "deg",
                                 "flight direction; 0 = straight right, 45 = "
                                 "diagonal down-right",
                                 0.0, -60.0, 60.0, false));
  def.camera = [](const Params& p) {
    const Common c = readCommon(p);
    return Rect{c.offset - 18 * c.tile, c.offset, 24 * c.tile, 14 * c.tile};
  };
  def.build = buildBulletsWall;
  return def;
}

// [SECTION] corner-graze --------------------------------------------------------------------------
//
// Each shot flies at 45° (equal speed on both axes) at the top-left corner of its own tile,
// shifted sideways by o = (j - 4)·(tile + size)/4 for j = 0..8 in turn:
//
//     o < 0          o = 0           o > 0               the shot's bottom-right corner runs
//      \              \                \                  along x - cx = (y - cy) + o; the
//       \##            \###          ###\##               swept square meets the tile's
//        ##             ###          ####                 interior iff |o| < tile + size, so
//   (cx,cy)=##         corner        ##                   j = 0 and j = 8 graze the corner
//                                                         exactly and must not hit.
// With the defaults (dt = 1/64 s, speeds a multiple of 1/4 px/s) every position is a dyadic
// number, so the grazes are exact at any offset. Shots slide; a shot is done once past its tile.
//   hits    shots that collided with their tile
//   misses  shots that passed without a collision (the exact grazes)

constexpr std::string_view kCornerGraze = "corner-graze";

class CornerGrazeRules final : public SceneRules {
 public:
  CornerGrazeRules(std::vector<Rect> tiles, double margin)
      : tiles_(std::move(tiles)), margin_(margin) {}
  void afterMove(TickContext& ctx, std::size_t i, Vec2,
                 std::span<const Collision> cols) const override {
    Body& b = ctx.bodies[i];
    if (!cols.empty() && (b.state & 1) == 0) {
      b.state |= 1;
      ++ctx.counters.hits;
    }
    const Rect& t = tiles_[b.group];
    const bool past = b.rect.x >= t.right() + margin_ || b.rect.y >= t.bottom() + margin_;
    if (past || (b.velocity.x == 0.0 && b.velocity.y == 0.0)) {
      if ((b.state & 1) == 0) ++ctx.counters.misses;
      stop(b);
    }
  }
  bool finished(std::span<const Body> bodies) const override { return allDone(bodies); }

 private:
  std::vector<Rect> tiles_;
  double margin_;
};

SceneSetup buildCornerGraze(const Params& p) {
  const Common c = readCommon(p);
  const double step = c.speed * c.dt;  // per axis, per tick
  const double reach = step * 3.0;     // the farthest start, along each axis
  const double pitch = c.tile * std::ceil((2 * reach + 4 * c.tile + 2 * c.size) / c.tile);
  const auto cols = static_cast<std::int64_t>(std::ceil(std::sqrt(static_cast<double>(c.count))));
  SceneSetup s;
  s.cellSize = c.cell;
  std::vector<Rect> tiles;
  Rng rng(c.seed);
  for (std::int64_t k = 0; k < c.count; ++k) {
    const double cx = c.offset + static_cast<double>(k % cols) * pitch + pitch * 0.5;
    const double cy = c.offset + static_cast<double>(k / cols) * pitch + pitch * 0.5;
    const Rect tile{cx, cy, c.tile, c.tile};
    tiles.push_back(tile);
    s.solids.push_back({tile});
    const double o = static_cast<double>(k % 9 - 4) * (c.tile + c.size) * 0.25;
    const double d = step * (2.0 + rng.dyadic(8));  // how far back along the diagonal
    s.bodies.push_back(makeBody({cx + o - d - c.size, cy - d - c.size, c.size, c.size},
                                BodyRole::projectile, kLayerProjectile, kLayerSolid,
                                response::slide, {c.speed, c.speed},
                                static_cast<std::uint32_t>(k)));
  }
  s.rules = std::make_shared<CornerGrazeRules>(std::move(tiles), c.tile);
  return s;
}

SceneDef cornerGraze() {
  CommonDefaults d;
  d.speed = 1920;
  d.size = 2;
  d.dt = 1.0 / 64.0;
  d.count = 36;
  d.speedMeaning = "speed on each axis (the shots fly at 45°)";
  d.sizeMeaning = "side of a shot";
  d.countMeaning = "shots, each at its own tile, cycling through 9 sideways offsets";
  SceneDef def;
  def.category = "Tunnelling";
  def.tagNames = {"tile"};
  def.name = std::string(kCornerGraze);
  def.description = "diagonal shots at tile corners: exact corner hits and exact grazes";
  def.missesWord = "grazes";  // a shot aimed past the corner must pass it: not a failure
  def.params = commonParams(d);
  def.camera = [](const Params& p) {
    const Common c = readCommon(p);
    const double reach = c.speed * c.dt * 3.0;
    const double pitch = c.tile * std::ceil((2 * reach + 4 * c.tile + 2 * c.size) / c.tile);
    return Rect{c.offset, c.offset, 3 * pitch, 3 * pitch};
  };
  def.build = buildCornerGraze;
  return def;
}

// [SECTION] bullets-enemies -----------------------------------------------------------------------
//
// Crossings: a bullet flies right while an enemy (a tile-sized square) flies down; their centres
// reach the same point M a random fraction into some tick:
//
//                 enemy
//                  ##
//                  ##  |
//                      v
//    [] ------->   M
//
// One at a time, each is tested against where the other stands, and when both are a long way
// from M at the tick's ends, neither sees the other. tv::Batch moves them together.
//   hits    crossings that collided
//   misses  crossings that passed (the bullet's left edge past the enemy, or the enemy's top
//           past the bullet) without a collision
// Bodies 2k and 2k + 1 are crossing k's bullet and enemy; both stop once it is decided.

constexpr std::string_view kBulletsEnemies = "bullets-enemies";
constexpr std::int32_t kMet = 1;

class BulletsEnemiesRules final : public SceneRules {
 public:
  explicit BulletsEnemiesRules(bool batched) : batched_(batched) {}
  void afterMove(TickContext& ctx, std::size_t i, Vec2,
                 std::span<const Collision> cols) const override {
    const std::size_t partner = i ^ 1u;
    for (const Collision& c : cols) {
      if (c.other == ctx.bodies[partner].item) ctx.bodies[i].state |= kMet;
    }
  }
  void afterTick(TickContext& ctx) const override {
    for (std::size_t k = 0; k + 1 < ctx.bodies.size(); k += 2) {
      Body& bullet = ctx.bodies[k];
      Body& enemy = ctx.bodies[k + 1];
      if (!bullet.active && !enemy.active) continue;
      if (((bullet.state | enemy.state) & kMet) != 0) {
        ++ctx.counters.hits;
      } else if (bullet.rect.x >= enemy.rect.right() || enemy.rect.y >= bullet.rect.bottom()) {
        ++ctx.counters.misses;
      } else {
        continue;
      }
      stop(bullet);
      stop(enemy);
    }
  }
  bool finished(std::span<const Body> bodies) const override { return allDone(bodies); }
  bool batched() const override { return batched_; }

 private:
  bool batched_;
};

SceneSetup buildBulletsEnemies(const Params& p) {
  const Common c = readCommon(p);
  const double step = c.speed * c.dt;
  // Whole ticks before the tick of the meeting: enough that they start well apart.
  const double lead = std::ceil((c.size + c.tile) / step) + 1.0;
  const double reach = step * (lead + 1.0);
  const double region = c.tile * std::ceil((2 * reach + 4 * c.tile + c.size) / c.tile);
  const auto cols = static_cast<std::int64_t>(std::ceil(std::sqrt(static_cast<double>(c.count))));
  SceneSetup s;
  s.cellSize = c.cell;
  Rng rng(c.seed);
  for (std::int64_t k = 0; k < c.count; ++k) {
    const Vec2 m{c.offset + static_cast<double>(k % cols) * region + region * 0.5,
                 c.offset + static_cast<double>(k / cols) * region + region * 0.5};
    const double d = step * (lead + rng.uniform());
    const auto group = static_cast<std::uint32_t>(k);
    s.bodies.push_back(makeBody({m.x - d - c.size * 0.5, m.y - c.size * 0.5, c.size, c.size},
                                BodyRole::projectile, kLayerProjectile, kLayerEnemy,
                                response::touch, {c.speed, 0.0}, group));
    s.bodies.push_back(makeBody({m.x - c.tile * 0.5, m.y - d - c.tile * 0.5, c.tile, c.tile},
                                BodyRole::enemy, kLayerEnemy, kLayerProjectile, response::touch,
                                {0.0, c.speed}, group));
  }
  s.rules = std::make_shared<BulletsEnemiesRules>(p.get("batch") != 0.0);
  return s;
}

SceneDef bulletsEnemies() {
  CommonDefaults d;
  d.speed = 1920;
  d.size = 4;
  d.count = 100;
  d.speedMeaning = "speed of bullets (right) and enemies (down)";
  d.sizeMeaning = "side of a bullet (an enemy is one tile)";
  d.countMeaning = "crossings (one bullet and one enemy each)";
  SceneDef def;
  def.category = "Tunnelling";
  def.tagNames = {"tile"};
  def.name = std::string(kBulletsEnemies);
  def.description =
      "bullets and enemies whose paths cross mid-tick; one-at-a-time moves miss, a batch meets";
  def.missesFail = true;  // a bullet and an enemy that crossed without meeting: a failure
  def.params = commonParams(d);
  def.params.push_back(intParam("batch",
                                "1: move everything through one tv::Batch (moving vs moving); "
                                "0: one body at a time with the chosen mover",
                                0.0, 0.0, 1.0));
  def.camera = [](const Params& p) {
    const Common c = readCommon(p);
    const double step = c.speed * c.dt;
    const double lead = std::ceil((c.size + c.tile) / step) + 1.0;
    const double region =
        c.tile * std::ceil((2 * step * (lead + 1.0) + 4 * c.tile + c.size) / c.tile);
    return Rect{c.offset, c.offset, 2 * region, 2 * region};
  };
  def.build = buildBulletsEnemies;
  return def;
}

}  // namespace

void registerProjectileScenes(SceneRegistry& r) {
  r.add(bulletsWall());
  r.add(cornerGraze());
  r.add(bulletsEnemies());
}

}  // namespace tv::sim::detail
