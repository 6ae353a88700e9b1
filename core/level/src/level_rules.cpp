// A level's own rules. Counters (tv-run prints those that are not zero):
//   hits       bullets stopped by a solid
//   tunnelled  bullets whose move went through a solid (or round its corner) and out again
//   overlaps   moves that ended inside a solid
//   jumps, landings, respawns   walkers and players, as in the platformer scene
// `state` bits: 0 grounded, 1 facing left (as in the platformer scene).
#include "level_rules.hpp"

#include <algorithm>

#include "tv/sweep.hpp"
#include "tv/world.hpp"

namespace tv::level::detail {
namespace {

constexpr std::int32_t kGrounded = 1;
constexpr std::int32_t kFacingLeft = 2;

class LevelRules final : public sim::SceneRules {
 public:
  LevelRules(std::vector<BodyRule> bodies, double killY)
      : bodies_(std::move(bodies)), killY_(killY) {}

  void control(sim::TickContext& ctx) const override {
    for (std::size_t i = 0; i < ctx.bodies.size() && i < bodies_.size(); ++i) {
      sim::Body& b = ctx.bodies[i];
      const BodyRule& r = bodies_[i];
      if (!b.active || (r.motion != Motion::walker && r.motion != Motion::player)) continue;
      b.velocity.x = (b.state & kFacingLeft) != 0 ? -r.speed : r.speed;
      if (r.motion == Motion::player && (b.state & kGrounded) != 0 &&
          (ctx.tick + static_cast<std::uint64_t>(r.jump.phase)) %
                  static_cast<std::uint64_t>(r.jump.every) ==
              0) {
        b.velocity.y = -r.jump.speed;
        b.state &= ~kGrounded;
        ++ctx.counters.jumps;
      }
    }
  }

  void afterMove(sim::TickContext& ctx, std::size_t i, Vec2 /*goal*/,
                 std::span<const Collision> cols) const override {
    sim::Body& b = ctx.bodies[i];
    const BodyRule& r = bodies_[i];
    // Inside a one-way solid is where a body jumping up through it is: not an overlap. Its top
    // is ground only to a body standing on it (not one passing through).
    const auto blocking = [&ctx, &b](ItemId, ItemId other) {
      if (ctx.bodyOf(other) >= 0) return response::ignore;
      if (ctx.isOneWay(other) && !(b.rect.bottom() <= ctx.world.rect(other).y))
        return response::ignore;
      return response::touch;
    };
    const bool hitSolid = std::any_of(cols.begin(), cols.end(),
                                      [&](const Collision& c) { return ctx.bodyOf(c.other) < 0; });
    if (r.motion == Motion::bullet) {
      // Tunnelled: this move's centre path crossed the interior of some solid grown by half the
      // bullet (so the rect overlapped it on the way) and ended outside it again — through it,
      // or round its corner — whatever the mover reported. A stop on the near face, or a push
      // out sideways onto it, never enters that interior.
      const Vec2 half{b.rect.w / 2, b.rect.h / 2};
      const Vec2 c0 = ctx.previous[i] + half, c1 = b.rect.position() + half;
      const Rect before = b.rect.at(ctx.previous[i]);
      const double x0 = std::min(before.x, b.rect.x), y0 = std::min(before.y, b.rect.y);
      const Rect hull{x0, y0, std::max(before.right(), b.rect.right()) - x0,
                      std::max(before.bottom(), b.rect.bottom()) - y0};
      bool tunnelled = false;
      for (const ItemId other : ctx.world.queryRect(hull, b.item)) {
        if (ctx.bodyOf(other) >= 0) continue;
        const Rect s = ctx.world.rect(other);
        if (ctx.isOneWay(other) && !(before.bottom() <= s.y)) continue;  // passed from below
        const Rect grown{s.x - half.x, s.y - half.y, s.w + b.rect.w, s.h + b.rect.h};
        if (clipSegment(c0, c1, grown).hit) {
          tunnelled = true;
          break;
        }
      }
      if (tunnelled) {
        ++ctx.counters.tunnelled;
        if (hitSolid) ++ctx.counters.farPushOuts;
        b.velocity = {};
        b.active = false;
      } else if (hitSolid) {
        ++ctx.counters.hits;
        b.velocity = {};
        b.active = false;
      }
    }
    if (ctx.world.anyOverlap(b.rect, b.item, blocking)) ++ctx.counters.overlaps;
    if (r.motion != Motion::walker && r.motion != Motion::player) return;
    for (const Collision& c : cols) {
      if (c.normal.x > 0.0) b.state &= ~kFacingLeft;
      if (c.normal.x < 0.0) b.state |= kFacingLeft;
    }
    // Grounded is asked of the world (a solid right under the feet), as the platformer does.
    const Rect feet{b.rect.x, b.rect.bottom(), b.rect.w, 1.0};
    const bool grounded = b.velocity.y >= 0.0 && ctx.world.anyOverlap(feet, b.item, blocking);
    if (grounded && (b.state & kGrounded) == 0) ++ctx.counters.landings;
    b.state = grounded ? (b.state | kGrounded) : (b.state & ~kGrounded);
    if (r.motion == Motion::player && b.rect.y > killY_) {
      ++ctx.counters.respawns;
      b.rect = b.rect.at(r.start);
      b.velocity = {};
      b.state &= kFacingLeft;
    }
  }

  bool finished(std::span<const sim::Body> bodies) const override {
    // Done when every body is a bullet that has stopped (a level with walkers runs on).
    for (std::size_t i = 0; i < bodies.size() && i < bodies_.size(); ++i) {
      if (bodies_[i].motion != Motion::bullet || bodies[i].active) return false;
    }
    return !bodies.empty();
  }

 private:
  std::vector<BodyRule> bodies_;
  double killY_;
};

}  // namespace

std::shared_ptr<const sim::SceneRules> makeLevelRules(std::vector<BodyRule> bodies, double killY) {
  return std::make_shared<LevelRules>(std::move(bodies), killY);
}

}  // namespace tv::level::detail
