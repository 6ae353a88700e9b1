#include "tv/mover.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <string>

#include "hit_order.hpp"
#include "tv/error.hpp"
#include "tv/sweep.hpp"

namespace tv {

namespace {

// The mover table: every mover once, with its spec and its line of description. Names, parsing
// and descriptions are all read from here.
constexpr MoverEntry kTable[] = {
    {"discrete", {.kind = MoverKind::discrete},
     "teleport to the goal, push out of overlaps: the naive mover, tunnels at speed"},
    {"sweep", {.kind = MoverKind::sweep},
     "one swept move over the move's bounding box (bump.lua's world:move)"},
    {"substep-discrete", {.kind = MoverKind::substep, .inner = MoverKind::discrete},
     "pieces of at most maxStep (tile/2), each teleported and pushed out: the usual patch"},
    {"substep-sweep", {.kind = MoverKind::substep, .inner = MoverKind::sweep},
     "pieces of at most maxStep (tile/2), each swept: the patch over bump.lua"},
    {"continuous", {.kind = MoverKind::continuous},
     "one exact sweep visiting only the cells the rect crosses: never tunnels, zero error"},
    {"pixel", {.kind = MoverKind::pixel},
     "one pixel at a time with a sub-pixel remainder (Celeste style): cost grows with speed"},
    {"adaptive", {.kind = MoverKind::adaptive},
     "continuous, but a body pressed onto a floor or wall slides from one read of its move's box"},
};

constexpr auto kNames = [] {
  std::array<std::string_view, std::size(kTable)> names{};
  for (std::size_t i = 0; i < names.size(); ++i) names[i] = kTable[i].name;
  return names;
}();

constexpr std::string_view kWhere = "tv::Mover";

// How many pieces a substep move needs, and guards against a piece count that cannot end.
constexpr double kMaxPieces = 1 << 24;
// Adaptive reads the bounding box of a move that spans at most this many cells (as World::move
// does for a move that meets nothing), whatever its length.
constexpr std::int64_t kAdaptiveScanCells = 4;
// The pixel mover makes one query per pixel: past this a move is refused, not ground through
// (and past 2^53 a double step count would never reach zero).
constexpr double kMaxPixels = 1 << 24;

}  // namespace

std::string MoverSpec::name() const {
  for (const MoverEntry& e : kTable) {
    if (e.spec.kind == kind && (kind != MoverKind::substep || e.spec.inner == inner))
      return std::string(e.name);
  }
  return "?";
}

std::span<const MoverEntry> moverTable() {
  return kTable;
}

MoverSpec parseMover(std::string_view name) {
  // "substep" alone is the usual patch, substep-discrete (its older name).
  if (name == "substep") name = "substep-discrete";
  for (const MoverEntry& e : kTable) {
    if (e.name == name) return e.spec;
  }
  std::string list;
  for (const auto n : kNames) list += (list.empty() ? "" : ", ") + std::string(n);
  fail("tv::parseMover", "unknown mover '" + std::string(name) + "' (known: " + list + ")");
}

std::span<const std::string_view> moverNames() {
  return kNames;
}

std::string_view moverDescription(std::string_view name) {
  for (const MoverEntry& e : kTable) {
    if (e.name == name) return e.description;
  }
  (void)parseMover(name);  // throws with the list of names
  return {};
}

Mover::Mover(MoverSpec spec) : spec_(spec), name_(spec.name()) {
  // A kind cast from an integer that names no mover would move nothing and report (0, 0).
  if (static_cast<unsigned>(spec.kind) > static_cast<unsigned>(MoverKind::adaptive)) {
    fail(kWhere, "kind must be a MoverKind (0 to 6), but was " +
                     std::to_string(static_cast<unsigned>(spec.kind)));
  }
  requireFinite(kWhere, "maxStep", spec.maxStep);
  if (spec.maxStep < 0) fail(kWhere, "maxStep must be >= 0, but was " + formatNumber(spec.maxStep));
  if (spec.kind == MoverKind::substep && spec.inner != MoverKind::discrete &&
      spec.inner != MoverKind::sweep) {
    fail(kWhere, "a substep mover's inner mover must be discrete or sweep");
  }
  if (!(spec.safetyFraction > 0.0 && spec.safetyFraction <= 1.0)) {
    fail(kWhere, "safetyFraction must be in (0, 1], but was " + formatNumber(spec.safetyFraction));
  }
}

MoveResult Mover::move(World& world, ItemId id, Vec2 goal, Filter filter, MoveTrace* trace) {
  if (WorldObserver* o = world.observer(); o && !o->busy()) [[unlikely]] {
    return observedMove(*o, world, id, goal, filter, trace);
  }
  return policyMove(world, id, goal, filter, trace);
}

// One recorded call: the world calls this policy makes are replayed by making it again. Out of
// line and without a second trip through move(): a recorded game pays for this on every move.
MoveResult Mover::observedMove(WorldObserver& o, World& world, ItemId id, Vec2 goal, Filter filter,
                               MoveTrace* trace) {
  const WorldObserver::Scope scope(o);
  const WorldObserver::Watched watched{filter, o};
  try {
    const Rect start = world.rect(id);
    const MoveResult r = policyMove(world, id, goal, Filter(watched), trace);
    o.moverMoved(*this, id, start, goal, r);
    return r;
  } catch (...) {
    o.failed();
    throw;
  }
}

MoveResult Mover::policyMove(World& world, ItemId id, Vec2 goal, Filter filter, MoveTrace* trace) {
  trace = activeTrace(trace);
  if (trace) {
    trace->clear();
    trace->mover = name_;
  }
  // Every policy either changes the world in one final call after all checks (discrete, pixel,
  // adaptive, world.move) or undoes its pieces on a throw (substep): a throw changes nothing.
  switch (spec_.kind) {
    case MoverKind::discrete:
      return discrete(world, id, goal, filter, trace, collisions_);
    case MoverKind::sweep:
      return world.move(id, goal, filter, {BroadPhase::bounds, trace});
    case MoverKind::substep:
      return substep(world, id, goal, filter, trace);
    case MoverKind::continuous:
      return world.move(id, goal, filter, {BroadPhase::swept, trace});
    case MoverKind::pixel:
      return pixel(world, id, goal, filter, trace);
    case MoverKind::adaptive:
      return adaptive(world, id, goal, filter, trace);
  }
  return {};
}

// Teleport, then push out of each overlap (in add order) along its shallowest axis, as a
// hand-written mover does. Crossed items are reported but not pushed out of.
MoveResult Mover::discrete(World& world, ItemId id, Vec2 goal, Filter filter, MoveTrace* trace,
                           std::vector<Collision>& out) {
  const Rect start = world.rect(id);
  if (!isFinite(goal)) {
    requireFinite("tv::Mover::move", "goal.x", goal.x);
    requireFinite("tv::Mover::move", "goal.y", goal.y);
  }
  Rect r = start.at(goal);
  world.queryRect(r, overlapping_, id);  // validates; throws before anything changes
  out.clear();
  if (trace) {
    trace->item = id;
    trace->start = start;
    trace->goal = goal;
    trace->legs.push_back({start, goal});
    Grid::forEachCell(world.grid().cellsOf(r), [&](Cell c) { trace->cells.push_back(c); });
  }
  for (const ItemId other : overlapping_) {
    if (trace) trace->candidates.push_back(other);
    const ResponseId resp = filter(id, other);
    if (trace) trace->answers.push_back({other, resp});
    if (resp == response::ignore) continue;
    (void)world.responseName(resp);  // throws on an answer that is not a registered response
    const Rect o = world.rect(other);
    const Sweep s = sweepRect(r, r.position(), o);
    if (s.kind != SweepKind::overlap) continue;  // an earlier push already cleared it
    Collision c;
    c.item = id;
    c.other = other;
    c.overlaps = true;
    c.ti = s.ti;
    c.move = goal - start.position();
    c.normal = s.normal;
    c.touch = s.touch;
    c.itemRect = r;
    c.otherRect = o;
    c.response = resp;
    c.target = resp == response::cross ? r.position() : s.touch;
    if (resp != response::cross) r = r.at(s.touch);
    out.push_back(c);
    if (trace) trace->hits.push_back(c);
  }
  world.update(id, r);
  if (trace) trace->final = r.position();
  return {r.position(), out};
}

MoveResult Mover::substep(World& world, ItemId id, Vec2 goal, Filter filter, MoveTrace* trace) {
  const Rect start = world.rect(id);
  requireFinite("tv::Mover::move", "goal.x", goal.x);
  requireFinite("tv::Mover::move", "goal.y", goal.y);
  const double maxStep = spec_.maxStep > 0.0 ? spec_.maxStep : 0.5 * world.minExtent();
  const Vec2 d = goal - start.position();
  const double len = length(d);
  const double pieces = len <= maxStep ? 1.0 : std::ceil(len / maxStep);
  if (!(pieces <= kMaxPieces)) {
    fail("tv::Mover::move", "substep move of length " + formatNumber(len) + " with maxStep " +
                                formatNumber(maxStep) + " needs more than 2^24 pieces");
  }
  const int n = static_cast<int>(pieces);
  const Vec2 step = d * (1.0 / pieces);
  collisions_.clear();
  MoveTrace* inner = nullptr;  // pieces are recorded into the same trace
  if (trace) {
    trace->item = id;
    trace->start = start;
    trace->goal = goal;
    inner = trace;
  }
  const BroadPhase broad = BroadPhase::bounds;
  Vec2 at = start.position();
  // A piece can meet bad input part way (a filter answer that is not a response): put the
  // item back where the move began.
  try {
    for (int i = 0; i < n; ++i) {
      const Vec2 target = at + step;
      if (trace) trace->substeps.push_back(target);
      MoveResult r;
      if (spec_.inner == MoverKind::sweep) {
        // The world's trace setters overwrite start/goal/final: keep ours.
        r = world.move(id, target, filter, {broad, inner});
      } else {
        r = discrete(world, id, target, filter, inner, pieceCollisions_);
      }
      collisions_.insert(collisions_.end(), r.collisions.begin(), r.collisions.end());
      at = r.position;
    }
  } catch (...) {
    world.update(id, start);
    throw;
  }
  if (trace) {
    trace->item = id;
    trace->start = start;
    trace->goal = goal;
    trace->final = at;
    trace->hits.assign(collisions_.begin(), collisions_.end());
  }
  return {at, collisions_};
}

// Celeste-style: whole pixels, one at a time on x then y, each checked for overlap; what is
// left below a pixel carries to the next move.
MoveResult Mover::pixel(World& world, ItemId id, Vec2 goal, Filter filter, MoveTrace* trace) {
  const Rect start = world.rect(id);
  requireFinite("tv::Mover::move", "goal.x", goal.x);
  requireFinite("tv::Mover::move", "goal.y", goal.y);
  if (!world.grid().fits(start.at(goal))) {
    fail("tv::Mover::move", "goal {" + formatNumber(goal.x) + ", " + formatNumber(goal.y) +
                                "} is too far from the origin for the world's cell size");
  }
  if (remainder_.size() <= id.index) remainder_.resize(id.index + 1);
  // Worked on a copy and stored with the final update, so a throw part way keeps the old one.
  // A remainder belongs to one item: a new item in a reused slot starts from zero.
  const Remainder& stored = remainder_[id.index];
  Vec2 rem = stored.generation == id.generation ? stored.rest : Vec2{};
  for (const double pixels : {rem.x + (goal.x - start.x), rem.y + (goal.y - start.y)}) {
    if (!(std::fabs(std::round(pixels)) <= kMaxPixels)) {
      fail("tv::Mover::move", "pixel move of " + formatNumber(pixels) +
                                  " px on one axis; the pixel mover takes at most 2^24 per move");
    }
  }
  collisions_.clear();
  if (trace) {
    trace->item = id;
    trace->start = start;
    trace->goal = goal;
    trace->legs.push_back({start, goal});
  }
  Rect r = start;
  const auto blockers = [&](const Rect& probe, Vec2 normal) {
    bool blocked = false;
    if (trace) {
      Grid::forEachCell(world.grid().cellsOf(probe), [&](Cell c) { trace->cells.push_back(c); });
    }
    world.queryRect(probe, overlapping_, id);
    for (const ItemId other : overlapping_) {
      if (trace) trace->candidates.push_back(other);
      const ResponseId resp = filter(id, other);
      if (trace) trace->answers.push_back({other, resp});
      if (resp == response::ignore) continue;
      (void)world.responseName(resp);  // throws on an answer that is not a registered response
      Collision c;
      c.item = id;
      c.other = other;
      c.move = goal - start.position();
      c.normal = normal;
      c.touch = r.position();
      c.target = r.position();
      c.itemRect = r;
      c.otherRect = world.rect(other);
      c.response = resp;
      collisions_.push_back(c);
      if (trace) trace->hits.push_back(c);
      if (resp != response::cross) blocked = true;
    }
    return blocked;
  };
  for (int axis = 0; axis < 2; ++axis) {
    double& rm = axis == 0 ? rem.x : rem.y;
    rm += axis == 0 ? goal.x - start.x : goal.y - start.y;
    double steps = std::round(rm);
    rm -= steps;
    const double sign = steps < 0 ? -1.0 : 1.0;
    const Vec2 unit = axis == 0 ? Vec2{sign, 0} : Vec2{0, sign};
    for (; steps != 0.0; steps -= sign) {
      const Rect probe = r.at(r.position() + unit);
      if (blockers(probe, unit * -1.0)) {
        rm = 0.0;
        break;
      }
      r = probe;
    }
  }
  world.update(id, r);
  remainder_[id.index] = {rem, id.generation};
  if (trace) trace->final = r.position();
  return {r.position(), collisions_};
}

namespace {

// The built-in responses whose legs stay inside the move's bounding box (a push out of an
// overlap may leave it: that is checked leg by leg).
bool staysInTheBox(ResponseId r) {
  return r == response::slide || r == response::touch || r == response::cross;
}

// True when `o` touches `r` on a face that the move to `g` (r at its goal) pushes into, and the
// two interiors overlap along that face: the sweep's hit at ti = 0, exactly, not at a corner
// (the far edge is already on the face, and the move carries it past). A body resting on a
// floor and pulled down by gravity, or walking along it, touches the floor's tiles so.
bool pressedInto(const Rect& r, const Rect& g, const Rect& o) {
  const bool acrossX = r.x < o.right() && o.x < r.right();
  const bool acrossY = r.y < o.bottom() && o.y < r.bottom();
  return (acrossX &&
          ((o.y == r.bottom() && g.bottom() > o.y) || (o.bottom() == r.y && g.y < o.bottom()))) ||
         (acrossY && ((o.x == r.right() && g.right() > o.x) ||  //
                      (o.right() == r.x && g.x < o.right())));
}

// What sweepRect(a, goal, b) gives for an item `b` that pressedInto(a, a.at(goal), b) found: a
// hit at ti = 0 on the face pressed into, placed as sweepRect places it (the far edge already
// on the face keeps its coordinate; the other axis is interpolated at ti and clamped), without
// its general entry-time arithmetic. Kept step for step with sweep.cpp; the adaptive tests
// compare every move with the continuous sweep.
Sweep pressedSweep(const Rect& a, Vec2 goal, const Rect& b) {
  const Rect g = a.at(goal);
  Sweep s;
  s.kind = SweepKind::hit;
  s.corner = false;
  const auto along = [&](double from, double to) {
    const double v = from + s.ti * (to - from);
    return std::clamp(v, std::min(from, to), std::max(from, to));
  };
  // ti is the gap to the face over the distance the near edge travels, as sweepRect's entry
  // time: zero, but with the sign of the gap (-0.0 - +0.0 is -0.0).
  if (a.x < b.right() && b.x < a.right()) {  // pressed into a face across y: a floor, a ceiling
    const bool down = goal.y > a.y;
    s.ti = down ? (b.y - a.bottom()) / (g.bottom() - a.bottom()) : (a.y - b.bottom()) / (a.y - g.y);
    s.touch = {along(a.x, goal.x), down ? a.y : b.bottom()};
    s.normal = {0.0, down ? -1.0 : 1.0};
  } else {  // a wall
    const bool right = goal.x > a.x;
    s.ti = right ? (b.x - a.right()) / (g.right() - a.right()) : (a.x - b.right()) / (a.x - g.x);
    s.touch = {right ? a.x : b.right(), along(a.y, goal.y)};
    s.normal = {right ? -1.0 : 1.0, 0.0};
  }
  return s;
}

}  // namespace

MoveResult Mover::adaptive(World& world, ItemId id, Vec2 goal, Filter filter, MoveTrace* trace) {
  const Rect start = world.rect(id);
  requireFinite("tv::Mover::move", "goal.x", goal.x);
  requireFinite("tv::Mover::move", "goal.y", goal.y);
  if (contact_.size() <= id.index) contact_.resize(id.index + 1);
  Contact& contact = contact_[id.index];
  const Vec2 d = goal - start.position();
  const bool pressing = contact.generation == id.generation + 1 &&
                        d.x * contact.normal.x + d.y * contact.normal.y < 0.0;
  MoveResult r;
  // A body moving back into what its last move ended against (resting on a floor under
  // gravity, walking along it, pressed to a wall) meets it again: its move is settled from one
  // read of its bounding box when it can be. Any other move most likely meets nothing, which
  // World::move decides in one scan of its cells.
  if (!pressing || !settleFromOneScan(world, id, start, goal, filter, trace, r)) {
    if (trace) {
      trace->clear();
      trace->mover = name_;
    }
    r = world.move(id, goal, filter, {BroadPhase::swept, trace});
  }
  contact =
      r.collisions.empty() ? Contact{} : Contact{r.collisions.back().normal, id.generation + 1};
  return r;
}

// Every leg of a move stays inside the move's bounding box while its responses slide, touch or
// cross, so whatever a leg can meet overlaps the box: one read of the box finds it all, and
// each leg is swept against those few items the way World::move sweeps it. Left out: the items
// the filter ignores, and those outside the box, which the swept walk reads but never hits.
// Returns false, having changed nothing, when a move needs more (a long move whose box spans
// many cells, a bounce or a user's response, a push out of an overlap that leaves the box, an
// answer that is not a response, a goal the world refuses): World::move then makes it whole.
bool Mover::settleFromOneScan(World& world, ItemId id, const Rect& start, Vec2 goal, Filter filter,
                              MoveTrace* trace, MoveResult& out) {
  const Rect end = start.at(goal);
  if (!(std::isfinite(end.right()) && std::isfinite(end.bottom()) && world.grid().fits(end) &&
        inRange(goal.x) && inRange(goal.y))) {
    return false;  // refused by World::move, with its message
  }
  const Rect box = unite(start, end);
  // The box of a longer move across many cells holds far more than the cells its rect crosses,
  // which the swept walk reads.
  if (world.grid().cellsOf(box).count() > kAdaptiveScanCells) {
    const double dist = std::max(std::fabs(goal.x - start.x), std::fabs(goal.y - start.y));
    if (!(dist < spec_.safetyFraction * std::min({start.w, start.h, world.minExtent()}))) {
      return false;
    }
  }
  reached_.clear();
  bool handOver = false;
  // anyOverlap visits each item whose interior meets the box once, and stops at the first that
  // the filter does not ignore: answering "ignore" to it keeps it going over all of them.
  (void)world.anyOverlap(box, id, [&](ItemId self, ItemId other) {
    const ResponseId resp = filter(self, other);
    if (trace) {
      trace->candidates.push_back(other);
      trace->answers.push_back({other, resp});
    }
    if (resp == response::ignore) return response::ignore;
    if (!staysInTheBox(resp)) handOver = true;
    reached_.push_back({other, world.rect(other), resp, false});
    return response::ignore;
  });
  if (handOver) return false;
  if (trace) {
    trace->item = id;
    trace->start = start;
    trace->goal = goal;
    Grid::forEachCell(world.grid().cellsOf(box), [&](Cell c) { trace->cells.push_back(c); });
  }
  collisions_.clear();
  Vec2 from = start.position(), to = goal;
  // As in World::move: the last leg start known to be outside everything the move did not
  // start in, where the move stops when it runs out of responses.
  Vec2 safe = from;
  const int maxResponses = MoveOptions{}.maxResponses;
  for (int i = 0; !reached_.empty(); ++i) {
    if (i == maxResponses) {
      to = safe;
      break;
    }
    const Rect r = start.at(from);
    // The leg's rect never leaves the union of its end rects, so what it can hit overlaps
    // that. The first leg's is the box; a later one's must lie inside the box, or what it can
    // meet may not all have been read.
    const Rect g = r.at(to);
    const double left = std::min(r.x, g.x), top = std::min(r.y, g.y);
    const double right = std::max(r.right(), g.right()), bottom = std::max(r.bottom(), g.bottom());
    if (i > 0 &&
        !(left >= box.x && top >= box.y && right <= box.right() && bottom <= box.bottom())) {
      return false;
    }
    if (trace) trace->legs.push_back({r, to});
    const Reached* lead = nullptr;
    Sweep leadSweep;
    const auto earlierAdded = [&](const Reached& a, const Reached& b) {
      return world.order(a.id) < world.order(b.id);
    };
    // The first leg of a body pressed onto what it touches: every item it presses into is hit
    // at exactly ti = 0, not at a corner, so they tie and the first added wins; nothing else
    // comes earlier unless the body starts inside something.
    if (i == 0) {
      bool overlapping = false;
      for (const Reached& o : reached_) {
        if (overlaps(r, o.rect)) {
          overlapping = true;
          break;
        }
        if (pressedInto(r, g, o.rect) && (!lead || earlierAdded(o, *lead))) lead = &o;
      }
      if (overlapping) {
        lead = nullptr;
      } else if (lead) {
        leadSweep = pressedSweep(r, to, lead->rect);
      }
    }
    if (!lead) {
      for (const Reached& o : reached_) {
        if (o.crossed || !(o.rect.x < right && left < o.rect.right() && o.rect.y < bottom &&
                           top < o.rect.bottom())) {
          continue;
        }
        const Sweep s = sweepRect(r, to, o.rect);
        if (s.kind == SweepKind::miss) continue;
        if (lead && !detail::hitBefore(r, to, s, o.rect, leadSweep, lead->rect,
                                       [&] { return earlierAdded(o, *lead); })) {
          continue;
        }
        lead = &o;
        leadSweep = s;
      }
    }
    if (!lead) break;
    Collision c;
    c.item = id;
    c.other = lead->id;
    c.overlaps = leadSweep.kind == SweepKind::overlap;
    c.corner = leadSweep.corner;
    c.ti = leadSweep.ti;
    c.move = to - r.position();
    c.normal = leadSweep.normal;
    c.touch = leadSweep.touch;
    c.itemRect = r;
    c.otherRect = lead->rect;
    c.response = lead->response;
    const Leg next = lead->response == response::slide   ? slideResponse(c, to)
                     : lead->response == response::touch ? touchResponse(c, to)
                                                         : crossResponse(c, to);
    c.target = next.goal;
    collisions_.push_back(c);
    if (trace) trace->hits.push_back(c);
    if (next.passThrough) reached_[static_cast<std::size_t>(lead - reached_.data())].crossed = true;
    from = next.start;
    to = next.goal;
    if (!c.overlaps) safe = from;
  }
  // A body held where it was (resting on a floor) leaves the world as it was: placing the
  // same rect again would only rewrite it, so the update is skipped when every bit matches.
  if (std::bit_cast<std::uint64_t>(to.x) != std::bit_cast<std::uint64_t>(start.x) ||
      std::bit_cast<std::uint64_t>(to.y) != std::bit_cast<std::uint64_t>(start.y)) {
    world.update(id, start.at(to));
  }
  if (trace) trace->final = to;
  out = {to, collisions_};
  return true;
}

}  // namespace tv
