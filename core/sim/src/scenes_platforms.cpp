// Scenes of moving platforms (tv/solid.hpp).
//   one-way-rise  riders on one-way platforms rising and falling at up to 10 tiles a tick
#include <cmath>

#include "scene_kit.hpp"
#include "tv/sim/body.hpp"
#include "tv/sim/scene.hpp"

namespace tv::sim::detail {

namespace {

// [SECTION] one-way-rise ---------------------------------------------------------------------------
//
// One column per platform: a one-way platform 3 tiles wide and a quarter tile thick, with a
// rider standing on it under gravity. Column k's platform moves at (k + 1) / count of `speed`
// (16, 32, ... 160 px a tick at the defaults: 1 to 10 tiles), up for `period` ticks, then down
// for as many, and so on.
//
//    [r]      [r]        rider: `size` square, falls, slides
//   =====    =====       platform k: one-way, a moving solid (carry 1) or teleported (carry 0)
//    col 0    col 1 ...
//
// carry 1: the platforms are moving solids (Body::solid), moved by tv::moveSolid before the
// riders. carry 0, the negative control: what a game written on a plain AABB world does — the
// rules teleport each platform, then give its rider the platform's velocity (plus gravity, as
// the simulation adds it) and the mover moves the rider; the one-way test is the bump-game
// filter (met only by a body entirely above it when its move began).
//
// Counted after every tick, per rider against its own platform: `drops` (it left the top
// downwards: fallen into or through it), `pops` (it left upwards: left behind in the air or
// thrown), each departure once; `overlaps` (ticks it ended inside its platform).

constexpr std::uint32_t kPlatformLayer = kLayerSolid;

std::uint32_t group(std::int64_t i) {
  return static_cast<std::uint32_t>(i);
}

bool onTop(const Rect& b, const Rect& p) {
  return b.y == placeBefore(p.y, b.h) && b.bottom() <= p.y;
}

class OneWayRiseRules final : public SceneRules {
 public:
  OneWayRiseRules(std::size_t columns, std::int64_t period, bool carry)
      : columns_(columns), period_(period), carry_(carry) {}

  void control(TickContext& ctx) const override {
    const bool up = (static_cast<std::int64_t>(ctx.tick) / period_) % 2 == 0;
    for (std::size_t k = 0; k < columns_; ++k) {
      Body& rider = ctx.bodies[2 * k];
      Body& platform = ctx.bodies[2 * k + 1];
      const double speed = std::abs(platform.velocity.y);
      platform.velocity = {0.0, up ? -speed : speed};
      if (carry_) continue;
      // The naive game: teleport the platform, and move its rider along with it.
      const bool riding = onTop(rider.rect, platform.rect);
      platform.rect = platform.rect.at(platform.rect.position() + platform.velocity * ctx.dt);
      if (riding) rider.velocity = {rider.velocity.x, platform.velocity.y};
    }
  }

  void afterTick(TickContext& ctx) const override {
    for (std::size_t k = 0; k < columns_; ++k) {
      const Rect& p = ctx.bodies[2 * k + 1].rect;
      Body& rider = ctx.bodies[2 * k];
      const Rect& r = rider.rect;
      if (overlaps(r, p)) ++ctx.counters.overlaps;
      // A rider's `state` is 1 while it is off its platform: each departure counts once.
      const bool on = onTop(r, p);
      if (!on && rider.state == 0) {
        if (r.bottom() > p.y) {
          ++ctx.counters.drops;
        } else {
          ++ctx.counters.pops;
        }
      }
      rider.state = on ? 0 : 1;
    }
  }

 private:
  std::size_t columns_;
  std::int64_t period_;
  bool carry_;
};

SceneSetup buildOneWayRise(const Params& p) {
  const Common c = readCommon(p);
  const double t = c.tile;
  const auto period = static_cast<std::int64_t>(p.get("period"));
  const bool carry = p.get("carry") != 0.0;
  SceneSetup s;
  s.cellSize = c.cell;
  s.gravity = {0.0, 1800.0};
  const double width = 3 * t, thick = t / 4, gap = t;
  // Riders start standing on the platforms, the platforms at the bottom of their swing (they
  // rise first, by `period` ticks of their speed, then sink back, and so on).
  const double top = c.offset + 4 * t + c.speed * c.dt * static_cast<double>(period);
  for (std::int64_t k = 0; k < c.count; ++k) {
    const double x = c.offset + static_cast<double>(k) * (width + gap);
    const double v = c.speed * static_cast<double>(k + 1) / static_cast<double>(c.count);
    // Rider first (body 2k, the one the tools trace by default), then its platform (2k + 1).
    Body rider = makeBody({x + (width - c.size) / 2, top - c.size, c.size, c.size},
                          BodyRole::walker, kLayerPlayer, kLayerSolid, response::slide, {},
                          group(k));
    rider.falls = true;
    s.bodies.push_back(rider);
    Body platform = makeBody({x, top, width, thick}, BodyRole::block, kPlatformLayer, 0,
                             response::slide, {0.0, -v}, group(k));
    platform.oneWay = true;
    platform.solid = carry;
    platform.active = carry;
    s.bodies.push_back(platform);
  }
  s.rules = std::make_shared<OneWayRiseRules>(static_cast<std::size_t>(c.count), period, carry);
  return s;
}

SceneDef oneWayRise() {
  CommonDefaults d;
  d.speed = 9600;  // 160 px a tick at 60 Hz: 10 tiles
  d.size = 12;
  d.count = 10;
  d.maxCount = 1000;
  d.speedMeaning = "the fastest platform's speed (column k moves at (k + 1) / count of it)";
  d.sizeMeaning = "side of a rider";
  d.countMeaning = "platforms, one rider each";
  SceneDef def;
  def.category = "Platforms";
  def.name = "one-way-rise";
  def.description =
      "riders on one-way platforms rising and falling at up to 10 tiles a tick; counts drops, "
      "pops";
  def.params = commonParams(d);
  def.params.push_back(intParam("period", "ticks each way before a platform turns", 6, 1, 1000));
  def.params.push_back(intParam(
      "carry", "1: platforms are moving solids (tv::moveSolid); 0: teleported (the control)", 1,
      0, 1));
  def.camera = [](const Params& p) {
    const Common c = readCommon(p);
    const double swing = c.speed * c.dt * p.get("period");
    return Rect{c.offset, c.offset, static_cast<double>(c.count) * 4 * c.tile,
                8 * c.tile + 2 * swing};
  };
  def.build = buildOneWayRise;
  return def;
}

}  // namespace

void registerPlatformScenes(SceneRegistry& r) {
  r.add(oneWayRise());
}

}  // namespace tv::sim::detail
