// World::hitsAlong: every hit of one straight leg, in the order a move takes them. Lua's
// `world:project` (bump's) calls it, so that a game's projections and its moves agree on what
// comes first: a sort on the rounded ti would not (two faces a rounding apart share it).

#include <algorithm>
#include <string>

#include "hit_order.hpp"
#include "tv/bump.hpp"
#include "tv/error.hpp"
#include "tv/world.hpp"

namespace tv {

namespace {

constexpr std::string_view kHitsAlong = "tv::World::hitsAlong";

// The sweep a collision was made from, for the order of hits (hit_order.hpp).
Sweep sweepOf(const Collision& c) {
  Sweep s;
  s.kind = c.overlaps ? SweepKind::overlap : SweepKind::hit;
  s.ti = c.ti;
  s.normal = c.normal;
  s.touch = c.touch;
  s.corner = c.corner;
  return s;
}

}  // namespace

void World::hitsAlong(ItemId self, const Rect& r, Vec2 goal, Filter filter,
                      std::vector<Collision>& out, const MoveOptions& options) const {
  out.clear();
  if (self.valid()) (void)slot(self, kHitsAlong);
  validateRect(r, kHitsAlong);
  validateGoal(r, goal, kHitsAlong);
  validateOptions(options, kHitsAlong);
  try {
    if (options.semantics == MoveSemantics::bump) {
      bump::project(*this, self, r, goal, filter, {}, out);
      return;
    }
    sweepLeg(self.valid() ? self.index : ItemId::kNone, r, goal, options.broad, out);
    // Nothing of the world's is used from here on: the filter may query the world.
    std::sort(out.begin(), out.end(), [&](const Collision& a, const Collision& b) {
      return detail::hitBefore(r, goal, sweepOf(a), a.otherRect, sweepOf(b), b.otherRect,
                               [&] { return orders_[a.other.index] < orders_[b.other.index]; });
    });
    std::size_t kept = 0;
    for (std::size_t i = 0; i < out.size(); ++i) {
      const ResponseId resp = filter(self, out[i].other);
      if (resp == response::ignore) continue;
      if (resp >= responses_.size()) {
        fail(kHitsAlong, "filter returned response " + std::to_string(resp) +
                             ", which is not registered");
      }
      out[kept] = out[i];
      out[kept].item = self;
      out[kept].response = resp;
      ++kept;
    }
    out.resize(kept);
  } catch (...) {
    out.clear();
    throw;
  }
}

}  // namespace tv
