// Scenes of moving platforms (tv/solid.hpp).
//   one-way-rise  riders on one-way platforms rising and falling at up to 10 tiles a tick
//   lift-crush    a lift carrying riders into a ceiling, a crusher, a door pushing a crowd
//   corner-nudge  bodies jumping into ceiling corners, with and without corner correction
#include <algorithm>
#include <cmath>
#include <vector>

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
      const Body& platform = ctx.bodies[2 * k + 1];
      const Rect& p = platform.rect;
      Body& rider = ctx.bodies[2 * k];
      const Rect& r = rider.rect;
      // Counted by name: the tools list each as the rider's, against its platform.
      if (overlaps(r, p)) ctx.count(Counted::overlapped, 2 * k, platform.item);
      // A rider's `state` is 1 while it is off its platform: each departure counts once.
      const bool on = onTop(r, p);
      if (!on && rider.state == 0) {
        ctx.count(r.bottom() > p.y ? Counted::dropped : Counted::popped, 2 * k, platform.item);
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
    rider.contacts = true;  // a game reads what its riders stand on
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

// [SECTION] lift-crush -----------------------------------------------------------------------------
//
// One column per speed and up to three rows (the `solids` parameter picks them: 1 lift,
// 2 crusher, 4 door, or a sum). Column k's solids move at (k + 1) / count of `speed` (16, 32, ...
// 160 px a tick at the defaults: 1 to 10 tiles): towards what they press for `period` ticks,
// then back to where they started for as many, and so on; never past the ceiling, floor or wall
// they press against, never past where they started.
//
//     ##########           ceiling
//                          4 tiles
//      [a]  [b]            riders, walking to and fro on the lift
//     ==========           lift: rises into the ceiling, so its riders are pressed against it
//     ##########           floor under it (a rider that falls off lands here)
//
//     +--------+           crusher: comes down onto the two bodies standing under it
//                          4 tiles
//      [c]  [d]
//     ##########
//
//     |   [e][f][g]  #     door: slides right into a crowd walking left, pushing it against
//     ################     the wall
//
// carry 1: the lifts, crushers and doors are moving solids (Body::solid), moved by
// tv::moveSolid before the bodies: riders carried, bodies in the way pushed, a body pressed
// against the ceiling, floor or wall reported as a squish (the solid stops where it is pressed).
// carry 0, the negative control, what a game written on a plain AABB world does: "move the
// lift, then move the riders" — the rules teleport each solid, give the lift's riders the
// lift's velocity, and the mover moves every body from wherever the teleport left it.
//
// Counted after every tick: `drops` (a lift's rider left its top downwards: into the lift or
// through it) and `pops` (left it upwards, not on it), each departure once; `overlaps` (bodies
// left inside: a body that ended the tick inside a solid, moving or not, once per body and
// tick); `tunnelled` (a crusher or door passed a body, or pressed it through the floor or wall:
// it ended on the far side of one of them), once;
// `snags` (a rider's own walk met the side of the lift it stands on). `squishes` are counted by
// the simulation: a body pressed by a moving solid, once per tick it is pressed — expected, on
// every lift's rise, every crusher's and door's stroke.

enum class Press : std::uint8_t { lift, crusher, door };

// A moving solid and the bodies it carries or presses (contiguous in body order, before it).
struct PressLane {
  Press kind;
  std::size_t solid;   // its body index
  std::size_t first;   // its bodies: first .. first + count - 1
  std::size_t count;
  double rest;         // its coordinate along its axis where it starts (y, or x for a door)
  double limit;        // the furthest its stroke goes: on the ceiling, floor or wall, not into it
  double speed;        // px/s
  Rect backstop;       // that ceiling, floor or wall
};

// Body::state bits of the bodies a lane carries or presses.
constexpr std::int32_t kOffLift = 1;   // a rider not on its lift's top (counted once)
constexpr std::int32_t kPassed = 2;    // a body on the far side of its crusher or door (once)
constexpr std::int32_t kWalkLeft = 4;  // a rider walking left

constexpr double kWalk = 60.0;  // px/s: riders walk, the crowd walks into its door

class LiftCrushRules final : public SceneRules {
 public:
  LiftCrushRules(std::vector<PressLane> lanes, std::vector<Rect> statics, std::int64_t period,
                 bool carry)
      : lanes_(std::move(lanes)), statics_(std::move(statics)), period_(period), carry_(carry) {}

  void control(TickContext& ctx) const override {
    const bool out = (static_cast<std::int64_t>(ctx.tick) / period_) % 2 == 0;
    for (const PressLane& l : lanes_) {
      Body& s = ctx.bodies[l.solid];
      const bool horizontal = l.kind == Press::door;
      const double pos = horizontal ? s.rect.x : s.rect.y;
      const double toward = out ? l.limit : l.rest;
      const double step = l.speed * ctx.dt;
      const double next = toward > pos ? std::min(pos + step, toward) : std::max(pos - step, toward);
      const double v = (next - pos) / ctx.dt;
      s.velocity = horizontal ? Vec2{v, 0.0} : Vec2{0.0, v};
      for (std::size_t i = l.first; i < l.first + l.count; ++i) {
        Body& b = ctx.bodies[i];
        if (l.kind == Press::lift) {
          // To and fro on the lift: turn before a step would take the rider past an end.
          bool left = (b.state & kWalkLeft) != 0;
          if (left && b.rect.x - kWalk * ctx.dt < s.rect.x) left = false;
          if (!left && b.rect.right() + kWalk * ctx.dt > s.rect.right()) left = true;
          b.state = left ? (b.state | kWalkLeft) : (b.state & ~kWalkLeft);
          b.velocity.x = left ? -kWalk : kWalk;
        } else if (l.kind == Press::door) {
          b.velocity.x = -kWalk;  // a slide against the door zeroed it
        }
      }
      if (carry_) continue;
      // The naive game: teleport the solid, then let the riders follow at its velocity.
      for (std::size_t i = l.first; l.kind == Press::lift && i < l.first + l.count; ++i) {
        Body& b = ctx.bodies[i];
        if (onTop(b.rect, s.rect)) b.velocity.y = v;
      }
      s.rect = s.rect.at(horizontal ? Vec2{next, s.rect.y} : Vec2{s.rect.x, next});
    }
  }

  void afterMove(TickContext& ctx, std::size_t i, Vec2 /*goal*/,
                 std::span<const Collision> collisions) const override {
    const PressLane* l = laneOf(i);
    if (l == nullptr || l->kind != Press::lift) return;
    const ItemId lift = ctx.bodies[l->solid].item;
    for (const Collision& c : collisions) {
      if (c.other == lift && c.normal.x != 0.0) ++ctx.counters.snags;
    }
  }

  void afterTick(TickContext& ctx) const override {
    for (const PressLane& l : lanes_) {
      const Rect& s = ctx.bodies[l.solid].rect;
      const ItemId solid = ctx.bodies[l.solid].item;
      // Counted by name: the tools list each as the body's, against its lane's solid.
      for (std::size_t i = l.first; i < l.first + l.count; ++i) {
        Body& b = ctx.bodies[i];
        const Rect& r = b.rect;
        if (inside(ctx, r)) ctx.count(Counted::overlapped, i);
        if (l.kind == Press::lift) {
          const bool on = onTop(r, s);
          if (!on && (b.state & kOffLift) == 0)
            ctx.count(r.bottom() > s.y ? Counted::dropped : Counted::popped, i, solid);
          b.state = on ? (b.state & ~kOffLift) : (b.state | kOffLift);
        } else {
          // The crusher comes down, the door goes right: a body it passed is above it, left of
          // it; a body it pressed through the floor or wall is below it, right of it.
          const Rect& f = l.backstop;
          const bool passed = l.kind == Press::crusher ? r.bottom() <= s.y || r.y >= f.bottom()
                                                       : r.right() <= s.x || r.x >= f.right();
          if (passed && (b.state & kPassed) == 0) ctx.count(Counted::tunnelled, i, solid);
          b.state = passed ? (b.state | kPassed) : (b.state & ~kPassed);
        }
      }
    }
  }

 private:
  [[nodiscard]] const PressLane* laneOf(std::size_t i) const {
    for (const PressLane& l : lanes_)
      if (i >= l.first && i < l.first + l.count) return &l;
    return nullptr;
  }

  // Inside a ceiling, floor, wall, lift, crusher or door (touching is not inside).
  [[nodiscard]] bool inside(const TickContext& ctx, const Rect& r) const {
    for (const Rect& s : statics_)
      if (overlaps(r, s)) return true;
    for (const PressLane& l : lanes_)
      if (overlaps(r, ctx.bodies[l.solid].rect)) return true;
    return false;
  }

  std::vector<PressLane> lanes_;
  std::vector<Rect> statics_;
  std::int64_t period_;
  bool carry_;
};

constexpr std::int64_t kLifts = 1, kCrushers = 2, kDoors = 4;

// The height of the rows `solids` picks, in tiles of `t`, bodies of side `s`.
double liftCrushHeight(std::int64_t solids, double t, double s) {
  double h = 0.0;
  if ((solids & kLifts) != 0) h += 7.0 * t + s;      // ceiling, gap, rider, lift, gap, floor, gap
  if ((solids & kCrushers) != 0) h += 6.5 * t + s;  // crusher, gap, body, floor, gap
  if ((solids & kDoors) != 0) h += 2.5 * t;         // door on its floor
  return h;
}

SceneSetup buildLiftCrush(const Params& p) {
  const Common c = readCommon(p);
  const double t = c.tile, s = c.size;
  if (s > t) {
    sceneFail("lift-crush", "size " + formatNumber(s) + " must be at most the tile (" +
                                formatNumber(t) + "): three bodies must fit between door and wall");
  }
  const auto period = static_cast<std::int64_t>(p.get("period"));
  const bool carry = p.get("carry") != 0.0;
  const auto solids = static_cast<std::int64_t>(p.get("solids"));
  SceneSetup out;
  out.cellSize = c.cell;
  out.gravity = {0.0, 1800.0};
  std::vector<PressLane> lanes;
  std::vector<Rect> statics;
  const auto addStatic = [&](Rect r) {
    out.solids.push_back({r});
    statics.push_back(r);
  };
  // A lane: its bodies, then its solid (a moving solid, or teleported by the rules).
  const auto addLane = [&](Press kind, Rect solid, std::vector<Body> bodies, double limit,
                           double speed, Rect backstop) {
    PressLane l{kind, 0, out.bodies.size(), bodies.size(), 0.0, limit, speed, backstop};
    for (Body& b : bodies) out.bodies.push_back(b);
    l.solid = out.bodies.size();
    l.rest = kind == Press::door ? solid.x : solid.y;
    Body m = makeBody(solid, BodyRole::block, kLayerSolid, 0, response::slide, {});
    m.solid = carry;
    m.active = carry;
    out.bodies.push_back(m);
    lanes.push_back(l);
  };
  const auto body = [&](double x, double floorTop, BodyRole role, std::uint32_t layer,
                        std::uint32_t mask) {
    Body b = makeBody({x, placeBefore(floorTop, s), s, s}, role, layer, mask, response::slide, {});
    b.falls = true;
    b.contacts = true;  // a game reads what its bodies stand on
    return b;
  };
  const double width = 7 * t;
  double y = c.offset;
  if ((solids & kLifts) != 0) {
    for (std::int64_t k = 0; k < c.count; ++k) {
      const double x = c.offset + static_cast<double>(k) * width;
      const double v = c.speed * static_cast<double>(k + 1) / static_cast<double>(c.count);
      const Rect ceiling{x + t, y, 5 * t, t / 2};
      const Rect lift{x + 2 * t, ceiling.bottom() + 4 * t + s, 3 * t, t / 2};
      addStatic(ceiling);
      addStatic({x + t, lift.bottom() + t, 5 * t, t / 2});
      Body a = body(lift.x + 2, lift.y, BodyRole::walker, kLayerPlayer, kLayerSolid);
      Body b = body(lift.right() - s - 2, lift.y, BodyRole::walker, kLayerPlayer, kLayerSolid);
      b.state = kWalkLeft;
      addLane(Press::lift, lift, {a, b}, ceiling.bottom(), v, ceiling);
    }
    y += 7 * t + s;
  }
  if ((solids & kCrushers) != 0) {
    for (std::int64_t k = 0; k < c.count; ++k) {
      const double x = c.offset + static_cast<double>(k) * width;
      const double v = c.speed * static_cast<double>(k + 1) / static_cast<double>(c.count);
      const Rect crusher{x + 2 * t, y, 3 * t, t};
      const Rect floor{x + t, crusher.bottom() + 4 * t + s, 5 * t, t / 2};
      addStatic(floor);
      addLane(Press::crusher, crusher,
              {body(crusher.x + 4, floor.y, BodyRole::walker, kLayerPlayer, kLayerSolid),
               body(crusher.right() - s - 4, floor.y, BodyRole::walker, kLayerPlayer, kLayerSolid)},
              floor.y - crusher.h, v, floor);
    }
    y += 6.5 * t + s;
  }
  if ((solids & kDoors) != 0) {
    for (std::int64_t k = 0; k < c.count; ++k) {
      const double x = c.offset + static_cast<double>(k) * width;
      const double v = c.speed * static_cast<double>(k + 1) / static_cast<double>(c.count);
      const Rect door{x, y, t / 2, 2 * t};
      const Rect wall{x + 6.5 * t, y, t / 2, 2 * t};
      addStatic({x, door.bottom(), width, t / 2});
      addStatic(wall);
      std::vector<Body> crowd;
      for (int i = 0; i < 3; ++i) {
        crowd.push_back(body(x + 1.5 * t + i * (s + 2), door.bottom(), BodyRole::crowd,
                             kLayerCrowd, kLayerSolid | kLayerCrowd));
      }
      addLane(Press::door, door, std::move(crowd), wall.x - door.w, v, wall);
    }
  }
  out.rules = std::make_shared<LiftCrushRules>(std::move(lanes), std::move(statics), period, carry);
  return out;
}

SceneDef liftCrush() {
  CommonDefaults d;
  d.speed = 9600;  // 160 px a tick at 60 Hz: 10 tiles
  d.size = 12;
  d.count = 10;
  d.maxCount = 1000;
  d.speedMeaning = "the fastest solids' speed (column k moves at (k + 1) / count of it)";
  d.sizeMeaning = "side of a rider, a crushed body, one of the crowd (at most the tile)";
  d.countMeaning = "columns: a lift, a crusher and a door each";
  SceneDef def;
  def.category = "Platforms";
  def.name = "lift-crush";
  def.description =
      "a lift carrying riders into a ceiling, a crusher, a door pushing a crowd, at up to 10 "
      "tiles a tick; counts drops, pops, bodies left inside, squishes";
  def.params = commonParams(d);
  def.params.push_back(intParam("period", "ticks each way before a solid turns", 6, 1, 1000));
  def.params.push_back(intParam(
      "carry", "1: moving solids (tv::moveSolid); 0: teleported, riders follow (the control)", 1,
      0, 1));
  def.params.push_back(
      intParam("solids", "rows: 1 lifts, 2 crushers, 4 doors, or a sum (7: all)", 7, 1, 7));
  def.camera = [](const Params& p) {
    const Common c = readCommon(p);
    return Rect{c.offset, c.offset, static_cast<double>(c.count) * 7 * c.tile,
                liftCrushHeight(static_cast<std::int64_t>(p.get("solids")), c.tile, c.size)};
  };
  def.build = buildLiftCrush;
  return def;
}

// [SECTION] corner-nudge ---------------------------------------------------------------------------
//
// One column per clip: a ceiling 3 tiles wide, and two bodies under its ends jumping straight up
// into its corners, column k's clipping them by k px (0, 1, ... count - 1) — the body's right
// edge k px under the ceiling's left end, the other's left edge k px under its right end. A roof
// above stops every jump; a body that lands back on the floor is put back where it started and
// jumps again.
//
//     ################################   roof
//
//          +---------------+             ceiling, 3 tiles
//       [a]|               |[b]          a: its right edge k px left of the ceiling's left end
//        ^                   ^               ... under it by k px; b: the mirror image
//     ################################   floor
//
// correct 1: the bodies move by tv::moveCornered with maxNudge `nudge` (Celeste's 4 px): a clip
// of at most `nudge` px is nudged round the corner and the jump goes on up; a deeper one stops.
// correct 0, the negative control: the mover moves them as it moves anything, and every clip
// stops the jump (or, for a mover that does not sweep, lands it inside the ceiling).
//
// Counted per jump, once: `snags` (stopped on a corner it clipped by at most `nudge` px: a jump
// the game should have let through), `hits` (stopped on a corner it clipped by more: as it should
// be), `tunnelled` (ended above the ceiling still under its end: through the corner, not round
// it), `misses` (got past a corner clipped by more than `nudge` px: pushed round it further than
// the game allows); `overlaps` (a body that ended a move inside a ceiling, floor or roof),
// `escapes` (out through the roof or the floor: put back at its start) and `jumps`.

constexpr std::uint8_t kCornerCeiling = 1;
constexpr std::int32_t kAirborne = 1;  // Body::state: jumped, not landed yet
constexpr std::int32_t kJudged = 2;    // this jump already counted

class CornerNudgeRules final : public SceneRules {
 public:
  CornerNudgeRules(std::vector<Rect> ceilings, std::vector<Vec2> starts, std::vector<Rect> statics,
                   double floorTop, double nudge, double speed)
      : ceilings_(std::move(ceilings)),
        starts_(std::move(starts)),
        statics_(std::move(statics)),
        floorTop_(floorTop),
        nudge_(nudge),
        speed_(speed) {}

  void control(TickContext& ctx) const override {
    for (std::size_t i = 0; i < ctx.bodies.size(); ++i) {
      Body& b = ctx.bodies[i];
      // Out through the roof or the floor (a mover that does not sweep, fast): counted, and
      // back to its start.
      if (b.rect.bottom() <= statics_[0].y || b.rect.y >= statics_[1].bottom()) {
        ++ctx.counters.escapes;
        b.state = 0;
      }
      if ((b.state & kAirborne) != 0) continue;
      b.rect = b.rect.at(starts_[i]);  // back under the corner, and up again
      b.velocity = {0.0, -speed_};
      b.state = kAirborne;
      ++ctx.counters.jumps;
    }
  }

  void afterMove(TickContext& ctx, std::size_t i, Vec2 /*goal*/,
                 std::span<const Collision> collisions) const override {
    Body& b = ctx.bodies[i];
    const double clip = clipOf(i);
    for (const Collision& c : collisions) {
      if ((b.state & kJudged) != 0) break;
      if (ctx.tagOf(c.other) != kCornerCeiling || c.normal.y <= 0.0) continue;
      if (clip <= nudge_) {
        ++ctx.counters.snags;
      } else {
        ++ctx.counters.hits;
      }
      b.state |= kJudged;
    }
    const Rect& r = b.rect;
    const Rect& ceiling = ceilings_[i / 2];
    const bool under = r.x < ceiling.right() && ceiling.x < r.right();
    if ((b.state & kJudged) == 0 && r.bottom() <= ceiling.y && under) {
      // Above the ceiling and still under its end: through the corner, not round it.
      ++ctx.counters.tunnelled;
      b.state |= kJudged;
    } else if ((b.state & kJudged) == 0 && clip > nudge_ && !under && r.y < ceiling.bottom()) {
      // Past a corner clipped deeper than the nudge: moved round it further than the game
      // allows (a mover pushing it out of the corner sideways).
      ++ctx.counters.misses;
      b.state |= kJudged;
    }
    for (const Rect& s : statics_) {
      if (overlaps(r, s)) {
        ++ctx.counters.overlaps;
        break;
      }
    }
    // Landed: falling, on the floor again. Next tick it jumps from its start.
    if (b.velocity.y == 0.0 && r.bottom() == floorTop_ && (b.state & kAirborne) != 0 &&
        ctx.previous[i].y < r.y) {
      b.state = 0;
    }
  }

 private:
  // Bodies 2k and 2k + 1 clip column k's ceiling by k px.
  [[nodiscard]] double clipOf(std::size_t i) const { return static_cast<double>(i / 2); }

  std::vector<Rect> ceilings_;
  std::vector<Vec2> starts_;
  std::vector<Rect> statics_;
  double floorTop_;
  double nudge_;
  double speed_;
};

SceneSetup buildCornerNudge(const Params& p) {
  const Common c = readCommon(p);
  const double t = c.tile, s = c.size;
  const bool correct = p.get("correct") != 0.0;
  const double nudge = p.get("nudge");
  const double width = 6 * t;
  if (static_cast<double>(c.count - 1) >= s) {
    sceneFail("corner-nudge", "count " + formatNumber(static_cast<double>(c.count)) +
                                  ": the deepest clip (count - 1 px) must be less than the size (" +
                                  formatNumber(s) + ")");
  }
  if (s > 1.5 * t) {
    sceneFail("corner-nudge", "size " + formatNumber(s) + " must be at most 1.5 tiles (" +
                                  formatNumber(1.5 * t) + "): a column is 6 tiles wide");
  }
  SceneSetup out;
  out.cellSize = c.cell;
  out.gravity = {0.0, 1800.0};
  const double x0 = c.offset, y0 = c.offset;
  const double total = static_cast<double>(c.count) * width;
  const Rect roof{x0, y0, total, t / 2};  // statics_[0], the floor statics_[1]
  const double ceilingY = roof.bottom() + 4 * t;
  const double floorTop = ceilingY + t / 2 + 2 * t + s;
  const Rect floor{x0, floorTop, total, t / 2};
  std::vector<Rect> ceilings, statics{roof, floor};
  std::vector<Vec2> starts;
  out.solids.push_back({roof});
  out.solids.push_back({floor});
  for (std::int64_t k = 0; k < c.count; ++k) {
    const double clip = static_cast<double>(k);
    const double x = x0 + static_cast<double>(k) * width;
    const Rect ceiling{x + 1.5 * t, ceilingY, 3 * t, t / 2};
    out.solids.push_back({ceiling, kCornerCeiling});
    ceilings.push_back(ceiling);
    statics.push_back(ceiling);
    for (const double bx : {ceiling.x - s + clip, ceiling.right() - clip}) {
      const Vec2 at{bx, placeBefore(floorTop, s)};
      Body b = makeBody({at.x, at.y, s, s}, BodyRole::player, kLayerPlayer, kLayerSolid,
                        response::slide, {}, static_cast<std::uint32_t>(k));
      b.falls = true;
      b.contacts = true;  // a game reads its player's ground and touches
      b.maxNudge = correct ? nudge : 0.0;
      out.bodies.push_back(b);
      starts.push_back(at);
    }
  }
  out.rules = std::make_shared<CornerNudgeRules>(std::move(ceilings), std::move(starts),
                                                 std::move(statics), floorTop, nudge, c.speed);
  return out;
}

SceneDef cornerNudge() {
  CommonDefaults d;
  d.speed = 600;  // 10 px a tick: the jump clears the ceiling and meets the roof
  d.size = 12;
  d.count = 9;
  d.maxCount = 64;
  d.speedMeaning = "the jump's speed, straight up";
  d.sizeMeaning = "side of a jumping body";
  d.countMeaning = "columns: clips of 0, 1, ... count - 1 px";
  SceneDef def;
  def.category = "Platforms";
  def.name = "corner-nudge";
  def.description =
      "bodies jumping into ceiling corners clipped by 0 to 8 px, with and without corner "
      "correction; counts snags (stopped by a clip it should pass), stops, pass-throughs";
  def.tagNames = {"floor or roof", "ceiling"};
  def.missesFail = true;  // a jump past a corner it should have stopped on
  def.params = commonParams(d);
  def.params.push_back(realParam("nudge", "px", "corner correction's largest nudge (Celeste: 4)",
                                 4.0, 0.0, 64.0, false));
  def.params.push_back(intParam(
      "correct", "1: corner correction (tv::moveCornered); 0: the mover alone (the control)", 1,
      0, 1));
  def.camera = [](const Params& p) {
    const Common c = readCommon(p);
    return Rect{c.offset, c.offset, static_cast<double>(c.count) * 6 * c.tile,
                7 * c.tile + c.size + c.tile / 2};
  };
  def.build = buildCornerNudge;
  return def;
}

}  // namespace

void registerPlatformScenes(SceneRegistry& r) {
  r.add(oneWayRise());
  r.add(liftCrush());
  r.add(cornerNudge());
}

}  // namespace tv::sim::detail
