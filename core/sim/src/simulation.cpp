// Simulation: building, ticking, the snapshot ring and the state hash.
//
// Index: [SECTION] building · [SECTION] ticking · [SECTION] rendering · [SECTION] snapshots ·
//        [SECTION] hashing · [SECTION] tracing
#include "tv/sim/simulation.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <string>

#include "tv/corner.hpp"
#include "tv/error.hpp"
#include "tv/outcome.hpp"
#include "tv/solid.hpp"

namespace tv::sim {

namespace {

constexpr std::string_view kWhere = "tv::sim::Simulation";

std::uint64_t mix(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

struct Hasher {
  std::uint64_t h = 0x7476'7369'6D00'0001ull;  // "tvsim"
  void add(std::uint64_t w) { h = mix(h ^ (w + 0x9E3779B97F4A7C15ull + (h << 6) + (h >> 2))); }
  void add(double v) { add(std::bit_cast<std::uint64_t>(v)); }
  void add(Vec2 v) {
    add(v.x);
    add(v.y);
  }
};

void checkParams(const SceneDef& scene, const Params& params) {
  const auto specs = params.specs();
  bool same = specs.size() == scene.params.size();
  for (std::size_t i = 0; same && i < specs.size(); ++i)
    same = specs[i].name == scene.params[i].name;
  if (!same) {
    fail(kWhere, "the parameters are not those of scene '" + scene.name +
                     "' (build them with its defaults())");
  }
  // Revalidate against the scene's own ranges: a Params object carries its own copy of them.
  for (std::size_t i = 0; i < specs.size(); ++i)
    Params::validate(scene.params[i], params.values()[i]);
}

MoverSpec resolveMover(MoverSpec spec, const Params& params) {
  (void)Mover(spec);  // a bad spec throws as given, before any default replaces a field
  if (spec.kind == MoverKind::substep) {
    const double fromScene = params.get(param::substep);
    if (fromScene > 0.0) {
      spec.maxStep = fromScene;
    } else if (spec.maxStep == 0.0) {
      spec.maxStep = params.get(param::tile) * 0.5;
    }
  }
  return spec;
}

}  // namespace

void TickContext::count(Counted what, std::size_t i, ItemId other) {
  Counters& c = counters;
  switch (what) {
    case Counted::tunnelled:
      ++c.tunnelled;
      break;
    case Counted::farPushOut:
      ++c.farPushOuts;
      break;
    case Counted::missed:
      ++c.misses;
      break;
    case Counted::escaped:
      ++c.escapes;
      break;
    case Counted::overlapped:
      ++c.overlaps;
      break;
    case Counted::jittered:
      ++c.jitter;
      break;
    case Counted::snagged:
      ++c.snags;
      break;
    case Counted::dropped:
      ++c.drops;
      break;
    case Counted::popped:
      ++c.pops;
      break;
    case Counted::manyCollisions:
      return;
  }
  if (!named) return;
  TickEvent e;
  e.tick = tick + 1;
  e.body = static_cast<std::int64_t>(i);
  e.what = what;
  e.other = other;
  named->push_back(e);
}

// [SECTION] building ------------------------------------------------------------------------------

Simulation::Simulation(const SceneDef& scene, const Params& params, MoverSpec mover,
                       SimConfig config)
    : scene_(scene), params_(params), config_(config), requested_(mover) {
  checkParams(scene_, params_);
  if (config_.snapshotCapacity < 1) {
    fail(kWhere,
         "snapshotCapacity must be >= 1, but was " + std::to_string(config_.snapshotCapacity));
  }
  requirePositive(kWhere, "maxFrameTime", config_.maxFrameTime);
  dt_ = params_.get(param::dt);
  mover_ = Mover(resolveMover(mover, params_));
  fixed_ = FixedStep(dt_, std::max(config_.maxFrameTime, dt_));
  build(scene_.build(params_));
}

Simulation::Simulation(std::string_view scene, std::string_view mover)
    : Simulation(findScene(scene), findScene(scene).defaults(), parseMover(mover)) {}

std::optional<std::size_t> Simulation::solidOf(ItemId id) const {
  // Solids are the world's first items, added in order: their slots are 0..n-1 (a rebuild
  // reuses them), so the slot finds the solid and the generation confirms it.
  if (id.index < solidItems_.size() && solidItems_[id.index] == id) return id.index;
  return std::nullopt;
}

void Simulation::build(SceneSetup setup) {
  events_.clear();
  contacts_.clear();
  nudges_.clear();
  contactEvents_.clear();
  tracker_ = Contacts{};
  contactOneWay_.clear();
  contactSolids_.clear();
  readsContacts_ = false;
  world_ = World(setup.cellSize);
  gravity_ = setup.gravity;
  rules_ = std::move(setup.rules);
  solids_ = std::move(setup.solids);
  bodies_ = std::move(setup.bodies);
  solidNames_ = std::move(setup.solidNames);
  bodyNames_ = std::move(setup.bodyNames);
  solidItems_.clear();
  const std::size_t items = solids_.size() + bodies_.size();
  bodyBySlot_.assign(items, -1);
  tagBySlot_.assign(items, 0);
  oneWayBySlot_.assign(items, 0);
  const auto grow = [&](ItemId id) {
    if (id.index >= bodyBySlot_.size()) {
      bodyBySlot_.resize(id.index + 1, -1);
      tagBySlot_.resize(id.index + 1, 0);
      oneWayBySlot_.resize(id.index + 1, 0);
    }
  };
  for (const Solid& s : solids_) {
    const ItemId id = world_.add(s.rect);
    grow(id);
    tagBySlot_[id.index] = s.tag;
    oneWayBySlot_[id.index] = s.oneWay ? 1 : 0;
    solidItems_.push_back(id);
  }
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    Body& b = bodies_[i];
    b.item = world_.add(b.rect);
    grow(b.item);
    bodyBySlot_[b.item.index] = static_cast<std::int32_t>(i);
  }
  // What a game's contacts know of its level: which items are one-way platforms (ground kind
  // oneWay) and which are moving solids (kind solid; a one-way moving platform stays oneWay).
  for (std::size_t k = 0; k < solids_.size(); ++k)
    if (solids_[k].oneWay) contactOneWay_.push_back(solidItems_[k]);
  for (const Body& b : bodies_) {
    readsContacts_ = readsContacts_ || b.contacts;
    if (b.oneWay) {
      contactOneWay_.push_back(b.item);
    } else if (b.solid || b.layer == kLayerSolid) {
      contactSolids_.push_back(b.item);
    }
  }
  previous_.resize(bodies_.size());
  for (std::size_t i = 0; i < bodies_.size(); ++i) previous_[i] = bodies_[i].rect.position();
  previousBefore_ = previous_;
  counters_ = {};
  tick_ = 0;
  ring_.clear();
  ring_.resize(config_.snapshotCapacity);
  oldest_ = newest_ = 0;
  traceValid_ = false;
  if (traced_ && *traced_ >= bodies_.size()) traced_.reset();
  record();
}

void Simulation::restart(const Params& params) {
  restart(params, requested_);
}

void Simulation::restart(const Params& params, MoverSpec mover) {
  Simulation next(scene_, params, mover, config_);  // throws before anything here changes
  next.traced_ = traced_;
  if (next.traced_ && *next.traced_ >= next.bodies_.size()) next.traced_.reset();
  *this = std::move(next);
}

void Simulation::restart() {
  restart(params_, requested_);
}

// [SECTION] ticking -------------------------------------------------------------------------------

void Simulation::tick() {
  step(dt_);
}

void Simulation::tick(double dt) {
  requirePositive("tv::sim::Simulation::tick", "dt", dt);
  step(dt);
}

int Simulation::frame(double frameTime) {
  const int n = fixed_.advance(frameTime);
  for (int i = 0; i < n; ++i) step(dt_);
  return n;
}

std::uint64_t Simulation::run(std::uint64_t maxTicks) {
  std::uint64_t n = 0;
  while (n < maxTicks && !finished()) {
    step(dt_);
    ++n;
  }
  return n;
}

bool Simulation::finished() const {
  return rules_ && rules_->finished(bodies_);
}

TickContext Simulation::context(double dt) {
  return {bodies_,     counters_,  world_,        tick_,  dt, previous_,
          bodyBySlot_, tagBySlot_, oneWayBySlot_, &events_};
}

void Simulation::syncWorld(std::size_t i) {
  // Rules may teleport a body (a respawn) by writing its rect.
  const Body& b = bodies_[i];
  if (world_.rect(b.item) != b.rect) world_.update(b.item, b.rect);
}

void Simulation::step(double dt) {
  // A tick that throws part way (a move refusing a goal, a rule's bad write) is undone: the
  // bodies, world and counters go back to this tick's snapshot and the interpolation's start
  // to what it was, so a throw changes nothing.
  std::swap(previous_, previousBefore_);
  try {
    stepOrThrow(dt);
  } catch (...) {
    restore(tick_);
    std::swap(previous_, previousBefore_);
    throw;
  }
}

void Simulation::stepOrThrow(double dt) {
  for (std::size_t i = 0; i < bodies_.size(); ++i) previous_[i] = bodies_[i].rect.position();
  traceValid_ = false;
  events_.clear();
  contacts_.clear();
  nudges_.clear();
  contactEvents_.clear();
  TickContext ctx = context(dt);
  if (rules_) {
    rules_->control(ctx);
    for (std::size_t i = 0; i < bodies_.size(); ++i) syncWorld(i);  // a teleport by the rules
  }
  moveSolids(dt);
  if (rules_ && rules_->batched()) {
    moveBatched(ctx, dt);
  } else {
    moveOneByOne(ctx, dt);
  }
  if (rules_) {
    const Counters before = counters_;
    const std::size_t mark = events_.size();
    rules_->afterTick(ctx);
    for (std::size_t i = 0; i < bodies_.size(); ++i) syncWorld(i);
    noteCounted(before, -1, {}, 0, mark);
  }
  ++tick_;
  record();
}

// The filter every move uses: a body meets what its mask shares a bit with, by its response.
// A one-way body is met only by a body that was entirely above it when its move began: the
// bodies' rects are where this tick's moves began (they are written back after each move).
ResponseId Simulation::respond(ItemId item, ItemId other) const {
  const std::int32_t a = item.index < bodyBySlot_.size() ? bodyBySlot_[item.index] : -1;
  const std::int32_t o = other.index < bodyBySlot_.size() ? bodyBySlot_[other.index] : -1;
  if (a < 0) return response::ignore;
  const Body& body = bodies_[static_cast<std::size_t>(a)];
  if (o >= 0 && bodies_[static_cast<std::size_t>(o)].oneWay &&
      !(body.rect.bottom() <= bodies_[static_cast<std::size_t>(o)].rect.y)) {
    return response::ignore;
  }
  if (o < 0 && other.index < oneWayBySlot_.size() && oneWayBySlot_[other.index] != 0 &&
      !(body.rect.bottom() <= world_.rect(other).y)) {
    return response::ignore;  // a one-way solid of the level
  }
  const std::uint32_t layer = o < 0 ? kLayerSolid : bodies_[static_cast<std::size_t>(o)].layer;
  return (body.mask & layer) != 0 ? body.response : response::ignore;
}

void Simulation::moveSolids(double dt) {
  riders_.clear();
  bool any = false;
  for (const Body& b : bodies_) {
    if (!b.solid) riders_.push_back(b.item);
    any = any || (b.solid && b.active);
  }
  if (!any) return;
  const auto filter = [this](ItemId item, ItemId other) { return respond(item, other); };
  for (Body& b : bodies_) {
    if (!b.solid || !b.active) continue;
    SolidOptions o;
    o.bodies = riders_;
    o.filter = filter;
    o.oneWay = b.oneWay;
    const Rect before = b.rect;
    const SolidMove m = moveSolid(world_, b.item, b.rect.position() + b.velocity * dt, o);
    counters_.squishes += m.squished.size();
    const std::size_t solid = static_cast<std::size_t>(&b - bodies_.data());
    // Each body once, by what mattered most: squished over pushed over carried. A rising solid
    // lifts its riders by pushing them (they are in its way); standing on it, they were carried.
    const auto note = [&](ItemId id, SolidAct act) {
      const std::int32_t i = id.index < bodyBySlot_.size() ? bodyBySlot_[id.index] : -1;
      if (i < 0) return;
      const auto k = static_cast<std::size_t>(i);
      for (const SolidContact& c : contacts_)
        if (c.solid == solid && c.body == k) return;
      const Rect& from = bodies_[k].rect;
      const bool rode = from.y == placeBefore(before.y, from.h) && from.x < before.right() &&
                        before.x < from.right();
      if (act == SolidAct::pushed && rode) act = SolidAct::carried;
      contacts_.push_back({solid, k, act, from, world_.rect(id)});
    };
    for (const Squish& q : m.squished) note(q.body, SolidAct::squished);
    for (const ItemId id : m.pushed) note(id, SolidAct::pushed);
    for (const ItemId id : m.carried) note(id, SolidAct::carried);
    for (Body& x : bodies_) x.rect = world_.rect(x.item);
  }
}

void Simulation::moveOneByOne(TickContext& ctx, double dt) {
  const auto filter = [this](ItemId item, ItemId other) { return respond(item, other); };
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    Body& b = bodies_[i];
    if (!b.active || b.solid) continue;
    if (b.falls) b.velocity = b.velocity + gravity_ * dt;
    const Vec2 goal = b.rect.position() + b.velocity * dt;
    // tv::moveCornered keeps no trace: a corrected body's moves are not traced.
    const bool traced = traced_ && *traced_ == i && b.maxNudge == 0.0;
    if (traced) trace_.clear();
    const MoveResult r = b.maxNudge > 0.0 ? moveCornered(i, goal, filter)
                                          : mover_.move(world_, b.item, goal, filter,
                                                        traced ? &trace_ : nullptr);
    b.rect = world_.rect(b.item);
    // As a game reads its player's contacts: right after its move, what it met included.
    if (b.contacts) readContacts(i, filter, r.collisions);
    b.velocity = respondVelocity(b.velocity, r.collisions);
    ++counters_.moves;
    counters_.collisions += r.collisions.size();
    if (traced) noteTrace();
    if (rules_) {
      const Counters before = counters_;
      const std::size_t mark = events_.size();
      rules_->afterMove(ctx, i, goal, r.collisions);
      syncWorld(i);
      noteCounted(before, static_cast<std::int64_t>(i), b.rect.at(previous_[i]),
                  r.collisions.size(), mark);
    } else if (manyCollisions_ > 0 && r.collisions.size() > manyCollisions_) {
      noteCounted(counters_, static_cast<std::int64_t>(i), b.rect.at(previous_[i]),
                  r.collisions.size(), events_.size());
    }
  }
}

void Simulation::readContacts(std::size_t body, const Filter& filter,
                              std::span<const Collision> met) {
  ContactOptions o;
  o.filter = filter;
  o.oneWay = contactOneWay_;
  o.solids = contactSolids_;
  const Rect at = bodies_[body].rect;
  for (const ContactEvent& e : tracker_.update(world_, bodies_[body].item, o, met)) {
    // An end's other item may have left the world: it is drawn where the body is.
    const Rect other = world_.has(e.other) ? world_.rect(e.other) : at;
    contactEvents_.push_back({body, e, at, other});
  }
}

std::optional<Ground> Simulation::ground(std::size_t i) const {
  if (i >= bodies_.size()) {
    fail("tv::sim::Simulation::ground", "body " + std::to_string(i) +
                                            " does not exist (there are " +
                                            std::to_string(bodies_.size()) + ")");
  }
  if (!bodies_[i].contacts) return std::nullopt;
  return tracker_.ground(bodies_[i].item);
}

MoveResult Simulation::moveCornered(std::size_t body, Vec2 goal, const Filter& filter) {
  CornerOptions o;
  o.filter = filter;
  o.maxNudge = bodies_[body].maxNudge;
  CornerMove m = tv::moveCornered(world_, bodies_[body].item, goal, o);
  if (m.nudged) {
    const Rect at = m.nudge.hit.itemRect.at(m.nudge.hit.touch);
    nudges_.push_back({body, m.nudge.hit.other, at, at.at({at.x + m.nudge.dx, at.y})});
  }
  cornered_ = std::move(m.collisions);  // MoveResult's collisions are a view: kept here
  MoveResult r;
  r.position = m.position;
  r.collisions = cornered_;
  return r;
}

void Simulation::noteCounted(const Counters& before, std::int64_t body, const Rect& start,
                             std::size_t collisions, std::size_t mark) {
  // Most moves count nothing: one compare of the failure counters and out.
  const Counters& now = counters_;
  const bool counted = now.tunnelled != before.tunnelled || now.farPushOuts != before.farPushOuts ||
                       now.misses != before.misses || now.escapes != before.escapes ||
                       now.overlaps != before.overlaps || now.jitter != before.jitter ||
                       now.snags != before.snags || now.drops != before.drops ||
                       now.pops != before.pops;
  const bool many = body >= 0 && manyCollisions_ > 0 && collisions > manyCollisions_;
  if (!counted && !many) return;
  // What the rules counted by name (TickContext::count, since `mark`) is listed already: only
  // the rest is this move's (or, after the tick, no one body's).
  std::uint64_t named[static_cast<std::size_t>(Counted::manyCollisions) + 1] = {};
  for (std::size_t k = mark; k < events_.size(); ++k)
    named[static_cast<std::size_t>(events_[k].what)] += events_[k].count;
  TickEvent e;
  e.tick = tick_ + 1;
  e.body = body;
  e.collisions = collisions;
  MoveOutcome outcome;
  if (body >= 0 && (now.tunnelled != before.tunnelled || now.overlaps != before.overlaps)) {
    const Body& b = bodies_[static_cast<std::size_t>(body)];
    const auto filter = [this](ItemId item, ItemId other) { return respond(item, other); };
    outcome = judgeMove(world_, b.item, start, b.rect, filter);
  }
  const auto add = [&](Counted what, std::uint64_t was, std::uint64_t is, ItemId other) {
    was += named[static_cast<std::size_t>(what)];
    if (is <= was) return;
    e.what = what;
    e.count = is - was;
    e.other = other;
    events_.push_back(e);
  };
  add(Counted::tunnelled, before.tunnelled, now.tunnelled, outcome.passedThrough);
  add(Counted::farPushOut, before.farPushOuts, now.farPushOuts, outcome.passedThrough);
  add(Counted::missed, before.misses, now.misses, {});
  add(Counted::escaped, before.escapes, now.escapes, {});
  add(Counted::overlapped, before.overlaps, now.overlaps, outcome.endedInside);
  add(Counted::jittered, before.jitter, now.jitter, {});
  add(Counted::snagged, before.snags, now.snags, {});
  add(Counted::dropped, before.drops, now.drops, {});
  add(Counted::popped, before.pops, now.pops, {});
  if (many) add(Counted::manyCollisions, 0, 1, {});
}

void Simulation::moveBatched(TickContext& ctx, double dt) {
  const auto filter = [this](ItemId item, ItemId other) { return respond(item, other); };
  batchMoves_.clear();
  batchBodies_.clear();
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    Body& b = bodies_[i];
    if (!b.active || b.solid) continue;
    if (b.falls) b.velocity = b.velocity + gravity_ * dt;
    batchMoves_.push_back({b.item, b.rect.position() + b.velocity * dt});
    batchBodies_.push_back(i);
  }
  batch_.step(world_, batchMoves_, filter);
  for (std::size_t k = 0; k < batchBodies_.size(); ++k) {
    const std::size_t i = batchBodies_[k];
    Body& b = bodies_[i];
    const BatchOutcome out = batch_.outcome(k);
    b.rect = world_.rect(b.item);
    b.velocity = respondVelocity(b.velocity, out.collisions);
    ++counters_.moves;
    counters_.collisions += out.collisions.size();
    if (rules_) {
      const Counters before = counters_;
      const std::size_t mark = events_.size();
      rules_->afterMove(ctx, i, batchMoves_[k].goal, out.collisions);
      syncWorld(i);
      noteCounted(before, static_cast<std::int64_t>(i), b.rect.at(previous_[i]),
                  out.collisions.size(), mark);
    }
  }
}

// [SECTION] rendering -----------------------------------------------------------------------------

Vec2 Simulation::renderPosition(std::size_t i) const {
  if (i >= bodies_.size()) {
    fail("tv::sim::Simulation::renderPosition", "body " + std::to_string(i) +
                                                    " does not exist (there are " +
                                                    std::to_string(bodies_.size()) + ")");
  }
  return interpolate(previous_[i], bodies_[i].rect.position(), fixed_.alpha());
}

Rect Simulation::renderRect(std::size_t i) const {
  return bodies_.at(i).rect.at(renderPosition(i));
}

// [SECTION] snapshots -----------------------------------------------------------------------------

void Simulation::record() {
  Snapshot& s = ring_[tick_ % ring_.size()];
  s.bodies.resize(bodies_.size());
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    const Body& b = bodies_[i];
    s.bodies[i] = {b.rect.position(), b.velocity, b.state, b.active};
  }
  s.counters = counters_;
  s.traceStats = traceStats_;
  s.contacts = contacts_;
  s.nudges = nudges_;
  s.contactEvents = contactEvents_;
  if (readsContacts_) s.tracker = tracker_;
  // Only the pixel mover keeps state between moves (its sub-pixel remainders); copying the
  // others would cost a little every tick and restore nothing.
  s.hasMover = mover_.spec().kind == MoverKind::pixel;
  if (s.hasMover) s.mover = mover_;
  newest_ = tick_;  // anything ahead (after a step back) is now another future
  if (tick_ - oldest_ >= ring_.size()) oldest_ = tick_ - ring_.size() + 1;
}

void Simulation::restore(std::uint64_t t) {
  events_.clear();
  const Snapshot& s = ring_[t % ring_.size()];
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    Body& b = bodies_[i];
    const BodyState& st = s.bodies[i];
    b.rect = b.rect.at(st.position);
    b.velocity = st.velocity;
    b.state = st.state;
    b.active = st.active;
    syncWorld(i);
    previous_[i] = st.position;
  }
  counters_ = s.counters;
  traceStats_ = s.traceStats;
  contacts_ = s.contacts;
  nudges_ = s.nudges;
  contactEvents_ = s.contactEvents;
  if (readsContacts_) tracker_ = s.tracker;
  if (s.hasMover) mover_ = s.mover;
  tick_ = t;
  traceValid_ = false;
  fixed_ = FixedStep(dt_, fixed_.maxFrameTime());
}

void Simulation::stepBack() {
  if (!canStepBack()) {
    fail("tv::sim::Simulation::stepBack",
         "tick " + std::to_string(tick_) + " is the oldest in the snapshot ring");
  }
  restore(tick_ - 1);
}

void Simulation::seek(std::uint64_t t) {
  if (t < oldest_) {
    fail("tv::sim::Simulation::seek", "tick " + std::to_string(t) +
                                          " has left the snapshot ring, which holds ticks " +
                                          std::to_string(oldest_) + ".." + std::to_string(newest_));
  }
  if (t <= newest_) {
    restore(t);
    return;
  }
  if (tick_ != newest_) restore(newest_);
  while (tick_ < t) step(dt_);
}

// [SECTION] hashing -------------------------------------------------------------------------------

std::uint64_t Simulation::stateHash() const {
  Hasher h;
  h.add(tick_);
  h.add(static_cast<std::uint64_t>(bodies_.size()));
  for (const Body& b : bodies_) {
    h.add(b.rect.position());
    h.add(b.velocity);
    h.add(static_cast<std::uint64_t>(static_cast<std::uint32_t>(b.state)) |
          (b.active ? std::uint64_t{1} << 32 : 0));
  }
  const Counters& c = counters_;
  for (const std::uint64_t v :
       {c.moves, c.collisions, c.hits, c.tunnelled, c.farPushOuts, c.misses, c.escapes, c.overlaps,
        c.jitter, c.snags, c.jumps, c.landings, c.respawns, c.drops, c.pops, c.squishes}) {
    h.add(v);
  }
  return h.h;
}

// [SECTION] tracing -------------------------------------------------------------------------------

void Simulation::traceBody(std::optional<std::size_t> i) {
  if (i && *i >= bodies_.size()) {
    fail("tv::sim::Simulation::traceBody", "body " + std::to_string(*i) +
                                               " does not exist (there are " +
                                               std::to_string(bodies_.size()) + ")");
  }
  traced_ = i;
  traceValid_ = false;
}

void Simulation::noteTrace() {
  traceValid_ = true;
  ++traceStats_.moves;
  traceStats_.candidates += trace_.candidates.size();
  traceStats_.cells += trace_.cells.size();
}

}  // namespace tv::sim
