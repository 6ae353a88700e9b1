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
     "continuous by another name: World::move reads a short move's box once, for every mover"},
};

constexpr auto kNames = [] {
  std::array<std::string_view, std::size(kTable)> names{};
  for (std::size_t i = 0; i < names.size(); ++i) names[i] = kTable[i].name;
  return names;
}();

constexpr std::string_view kWhere = "tv::Mover";

// How many pieces a substep move needs, and guards against a piece count that cannot end.
constexpr double kMaxPieces = 1 << 24;
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
  // world.move) or undoes its pieces on a throw (substep): a throw changes nothing.
  switch (spec_.kind) {
    case MoverKind::discrete:
      return discrete(world, id, goal, filter, trace, collisions_);
    case MoverKind::sweep:
      return world.move(id, goal, filter, {BroadPhase::bounds, trace});
    case MoverKind::substep:
      return substep(world, id, goal, filter, trace);
    case MoverKind::continuous:
    case MoverKind::adaptive:  // the same move: see MoverKind::adaptive
      return world.move(id, goal, filter, {BroadPhase::swept, trace});
    case MoverKind::pixel:
      return pixel(world, id, goal, filter, trace);
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
      // A one-way platform blocks only a step onto its top from entirely above it.
      if (resp != response::cross && (resp != response::oneway || onewayBlocks(c))) blocked = true;
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

}  // namespace tv
