// A scene or a level as a Source: the simulation, its traced body's recent moves, its calls.
#include "tv/ui/sim_source.hpp"

#include <algorithm>
#include <cinttypes>
#include <cstdio>

#include "tv/error.hpp"
#include "tv/ui/words.hpp"

namespace tv::ui {

namespace {

constexpr std::string_view kWhere = "tv::ui::SimSource";

void checkBody(const sim::Simulation& s, std::optional<std::size_t> body) {
  if (body && *body >= s.bodies().size()) {
    fail(kWhere, "body " + std::to_string(*body) + " does not exist (the scene has " +
                     std::to_string(s.bodies().size()) + " bodies: 0.." +
                     std::to_string(s.bodies().size() - 1) + ")");
  }
}

}  // namespace

const char* roleName(sim::BodyRole r) {
  switch (r) {
    case sim::BodyRole::projectile:
      return "projectile";
    case sim::BodyRole::enemy:
      return "enemy";
    case sim::BodyRole::ball:
      return "ball";
    case sim::BodyRole::walker:
      return "walker";
    case sim::BodyRole::player:
      return "player";
    case sim::BodyRole::crowd:
      return "crowd";
    case sim::BodyRole::block:
      return "block";
  }
  return "body";
}

std::uint64_t failureCount(const sim::Counters& c) {
  return c.tunnelled + c.escapes + c.overlaps + c.jitter + c.snags + c.drops + c.pops;
}

SimSource::SimSource(const sim::SceneDef& scene, const sim::Params& params, MoverSpec mover,
                     SourceKind kind)
    : sim_(scene, params, mover), kind_(kind) {
  sim_.setManyCollisions(kManyResponses);
  indexBodies();
}

std::unique_ptr<Source> SimSource::rerun(const MoverSpec& mover) const {
  auto s = std::make_unique<SimSource>(sim_.scene(), sim_.params(), mover, kind_);
  s->body_ = body_;
  s->sim_.traceBody(body_);
  s->history_ = history_;
  s->renderHz_ = renderHz_;
  s->notes_ = notes_;
  return s;
}

// -- time ----------------------------------------------------------------------------------------

void SimSource::rememberStart() {
  const auto bodies = sim_.bodies();
  starts_.resize(bodies.size());
  startedActive_.resize(bodies.size());
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    starts_[i] = bodies[i].rect;
    startedActive_[i] = bodies[i].active;
  }
  startsTick_ = sim_.ticks() + 1;
}

void SimSource::noteTrace() {
  const MoveTrace* t = sim_.lastTrace();
  if (!t) return;
  if (moves_.size() >= history_) moves_.erase(moves_.begin());
  moves_.push_back({sim_.ticks(), *t});
}

void SimSource::noteEvents() {
  // Only the last few ticks' are kept: the words are for the moves on screen.
  const std::uint64_t t = sim_.ticks();
  const std::uint64_t keep = t > history_ + 1 ? t - history_ - 1 : 0;
  std::erase_if(recent_, [&](const Failure& f) { return f.frame < keep || f.frame > t; });
  for (const sim::TickEvent& e : sim_.events()) {
    if (auto f = ui::failureOf(sim_, e, *this)) recent_.push_back(std::move(*f));
  }
}

std::optional<Failure> SimSource::failureOf(const TracedMove& m) const {
  std::optional<Failure> found;
  for (const Failure& f : recent_) {
    if (f.frame != m.tick || f.item != m.trace.item) continue;
    // A failure before a busy move: what went wrong before how much work it took. A rider's
    // drop or pop is told beside the move's own failure ("ended inside body 1; dropped by
    // body 1: ..."): the Failures tab lists it, so a click on it must find it said here.
    const bool platform = f.kind == FailureKind::dropped || f.kind == FailureKind::popped;
    if (!found || (found->kind == FailureKind::busy && f.kind != FailureKind::busy)) {
      found = f;
    } else if (platform && found->what.find(f.what) == std::string::npos) {
      found->what += "; " + f.what;
    }
  }
  return found;
}

void SimSource::noteFailure() {
  // Counts only grow as ticks run; none means the simulation was taken back before the first
  // failure (a seek or a restart), and the tick recorded no longer holds.
  if (failureCount(sim_.counters()) == 0) {
    firstFailure_.reset();
  } else if (!firstFailure_) {
    firstFailure_ = sim_.ticks();
  }
}

void SimSource::tick() {
  rememberStart();
  sim_.tick();
  noteTrace();
  noteFailure();
  noteEvents();
  interpolating_ = false;  // drawn at the tick: the accumulator's alpha no longer applies
  furthest_ = std::max(furthest_, sim_.ticks());
  call_.reset();
}

int SimSource::frame(double seconds) {
  // A frame usually runs one tick or none; the starts of its calls are known for one tick only.
  std::vector<Rect> starts = starts_;
  std::vector<bool> active = startedActive_;
  const std::uint64_t before = startsTick_;
  rememberStart();
  const int n = sim_.frame(seconds);
  if (n == 0) {
    starts_ = std::move(starts);
    startedActive_ = std::move(active);
    startsTick_ = before;
  } else if (n > 1) {
    startsTick_ = ~std::uint64_t{0};
  }
  interpolating_ = true;
  // A frame that ran several ticks leaves only its last tick's trace in the simulation.
  if (n > 0) {
    noteTrace();
    noteEvents();
    call_.reset();
  }
  noteFailure();
  furthest_ = std::max(furthest_, sim_.ticks());
  return n;
}

void SimSource::play() {
  if (renderHz_ > 0.0) {
    (void)frame(1.0 / renderHz_);
  } else {
    tick();
  }
}

double SimSource::playSeconds() const {
  return renderHz_ > 0.0 ? 1.0 / renderHz_ : sim_.dt();
}

void SimSource::advanceTo(std::uint64_t t, double renderHz, bool stopAtEnd) {
  if (t < sim_.ticks()) {
    fail(kWhere, "tick " + std::to_string(t) + " is behind the current tick " +
                     std::to_string(sim_.ticks()) + " (ticks must be in increasing order)");
  }
  // With stopAtEnd, a scene that has ended goes no further: nothing happens after its end.
  const auto more = [&] { return sim_.ticks() < t && !(stopAtEnd && sim_.finished()); };
  const auto report = [&] {
    if (progress_ && (sim_.ticks() & 4095) == 0) progress_(sim_.ticks(), t);
  };
  if (renderHz <= 0.0) {
    while (more()) {
      tick();
      report();
    }
    return;
  }
  const double frameTime = 1.0 / renderHz;
  while (more()) {
    frame(frameTime);
    report();
    if (sim_.ticks() > t) {
      fail(kWhere, "a render rate of " + formatNumber(renderHz) +
                       " Hz runs several ticks per frame and stepped over tick " +
                       std::to_string(t) + "; use a rate of at least 1 / dt");
    }
  }
}

void SimSource::retrace(std::uint64_t t) {
  const std::uint64_t h = std::min<std::uint64_t>(history_, t);
  const std::uint64_t from = t - h;
  // Older than the ring holds: from tick 0 again (deterministic, so the same states).
  if (from < sim_.oldestTick()) {
    sim_.restart();
    firstFailure_.reset();
  }
  sim_.seek(from);
  sim_.traceBody(body_);
  moves_.clear();
  noteFailure();
  recent_.clear();
  while (sim_.ticks() < t) {
    rememberStart();
    sim_.tick();
    noteTrace();
    noteFailure();
    noteEvents();
  }
  interpolating_ = false;
  furthest_ = std::max(furthest_, sim_.ticks());
}

void SimSource::goTo(std::uint64_t t) {
  call_.reset();
  callTraced_ = false;
  retrace(t);
}

// -- calls ---------------------------------------------------------------------------------------

std::span<const CallInfo> SimSource::calls() const {
  const std::uint64_t t = sim_.ticks();
  if (callsTick_ == t) return calls_;
  calls_.clear();
  callsTick_ = t;
  if (startsTick_ != t) return calls_;  // a frame that ran several ticks: not known
  const auto bodies = sim_.bodies();
  const std::string mover = sim_.moverSpec().name();
  for (std::size_t i = 0; i < bodies.size() && i < starts_.size(); ++i) {
    if (!startedActive_[i]) continue;  // a body that has stopped makes no move
    CallInfo c;
    c.kind = CallKind::moverMove;
    c.frame = t;
    c.index = static_cast<std::uint32_t>(calls_.size());
    c.item = bodies[i].item;
    c.start = starts_[i];
    c.position = bodies[i].rect.position();
    c.goal = c.position;  // the goal is the trace's to tell (select the call)
    c.mover = mover;
    char text[160];
    std::snprintf(text, sizeof text, "move %s (%.6g, %.6g) -> (%.6g, %.6g)", describe(c.item).c_str(),
                  c.start.x, c.start.y, c.position.x, c.position.y);
    c.summary = text;
    calls_.push_back(std::move(c));
  }
  return calls_;
}

void SimSource::selectCall(std::optional<std::uint32_t> k) {
  const auto all = calls();
  if (k && *k >= all.size()) return;
  if (!k) {
    call_.reset();
    callTraced_ = false;
    return;
  }
  const ItemId item = all[*k].item;
  const std::uint64_t t = sim_.ticks();
  body_ = bodyOf(item);
  retrace(t);
  call_ = k;
  callTraced_ = !moves_.empty() && moves_.back().tick == t && moves_.back().trace.item == item;
}

const MoveTrace* SimSource::callTrace() const {
  return call_ && callTraced_ && !moves_.empty() ? &moves_.back().trace : nullptr;
}

// -- tracing -------------------------------------------------------------------------------------

void SimSource::indexBodies() {
  bodyBySlot_.clear();
  const auto bodies = sim_.bodies();
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    const std::size_t slot = bodies[i].item.index;
    if (slot >= bodyBySlot_.size()) bodyBySlot_.resize(slot + 1, -1);
    bodyBySlot_[slot] = static_cast<std::int32_t>(i);
  }
}

std::optional<std::size_t> SimSource::bodyOf(ItemId id) const {
  if (id.index >= bodyBySlot_.size() || bodyBySlot_[id.index] < 0) return std::nullopt;
  const auto i = static_cast<std::size_t>(bodyBySlot_[id.index]);
  if (sim_.bodies()[i].item != id) return std::nullopt;  // another generation of the slot
  return i;
}

void SimSource::traceBody(std::optional<std::size_t> i) {
  checkBody(sim_, i);
  body_ = i;
  sim_.traceBody(i);
  moves_.clear();
  call_.reset();
  callTraced_ = false;
}

void SimSource::trace(std::optional<ItemId> item) {
  if (!item) {
    traceBody(std::nullopt);
    return;
  }
  const auto b = bodyOf(*item);
  if (!b) {
    if (!sim_.world().has(*item)) fail(kWhere, "item " + std::to_string(item->index) + " does not exist");
    // A solid never moves: nothing to trace.
    traceBody(std::nullopt);
    return;
  }
  const std::uint64_t t = sim_.ticks();
  body_ = b;
  call_.reset();
  callTraced_ = false;
  retrace(t);  // the new body's moves that led here, at once
}

std::optional<ItemId> SimSource::traced() const {
  if (!body_) return std::nullopt;
  return sim_.bodies()[*body_].item;
}

void SimSource::setHistoryLength(std::size_t n) {
  history_ = std::max<std::size_t>(n, 1);
  if (moves_.size() > history_) {
    moves_.erase(moves_.begin(), moves_.end() - static_cast<std::ptrdiff_t>(history_));
  }
}

void SimSource::restart(const sim::Params& params, MoverSpec mover) {
  sim_.restart(params, mover);
  indexBodies();
  firstFailure_.reset();
  furthest_ = 0;
  if (body_ && *body_ >= sim_.bodies().size()) body_.reset();  // the body count may have changed
  traceBody(body_);
  interpolating_ = false;
  startsTick_ = callsTick_ = ~std::uint64_t{0};
}

// -- what is shown -------------------------------------------------------------------------------

WorldPicture SimSource::picture() {
  renderRects_.clear();
  if (interpolating_) {
    for (std::size_t i = 0; i < sim_.bodies().size(); ++i)
      renderRects_.push_back(sim_.renderRect(i));
  }
  WorldPicture p;
  p.world = &sim_.world();
  p.solids = sim_.solids();
  p.bodies = sim_.bodies();
  p.renderRects = renderRects_;
  p.contacts = sim_.solidContacts();
  p.nudges = sim_.cornerNudges();
  p.contactEvents = sim_.contactEvents();
  p.selected = body_;
  p.moves = moves_;
  return p;
}

std::optional<Ground> SimSource::ground(ItemId id) const {
  const auto b = bodyOf(id);
  return b ? sim_.ground(*b) : std::nullopt;
}

bool SimSource::hasContacts() const {
  const auto bodies = sim_.bodies();
  return std::any_of(bodies.begin(), bodies.end(), [](const sim::Body& b) { return b.contacts; });
}

double SimSource::followMinSide() const {
  const sim::Params& p = sim_.params();
  return 4.0 * std::max(p.get(sim::param::tile), p.get(sim::param::size));
}

// -- items ---------------------------------------------------------------------------------------

namespace {

// What a solid of this tag is called in this scene ("wall tile"), or "solid".
std::string tagWord(const sim::Simulation& s, std::size_t solid) {
  const std::uint8_t tag = s.solids()[solid].tag;
  const auto& names = s.scene().tagNames;
  return tag < names.size() && !names[tag].empty() ? names[tag] : std::string("solid");
}

}  // namespace

std::string SimSource::describe(ItemId id) const {
  // A map object's own name first ("Block 12", "turret 3"), else what it is and its number.
  if (const auto b = bodyOf(id)) {
    const std::string_view name = sim_.bodyName(*b);
    return name.empty() ? "body " + std::to_string(*b) : std::string(name);
  }
  if (const auto k = sim_.solidOf(id)) {
    const std::string_view name = sim_.solidName(*k);
    return name.empty() ? tagWord(sim_, *k) + " " + std::to_string(*k) : std::string(name);
  }
  return "item " + std::to_string(id.index);
}

std::string SimSource::category(ItemId id) const {
  if (const auto b = bodyOf(id)) return roleName(sim_.bodies()[*b].role);
  if (const auto k = sim_.solidOf(id)) return tagWord(sim_, *k);
  return "";
}

std::vector<ItemRow> SimSource::items() const {
  std::vector<ItemRow> rows;
  const auto bodies = sim_.bodies();
  rows.reserve(bodies.size() + sim_.solids().size());
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    ItemRow r;
    r.id = bodies[i].item;
    r.name = describe(r.id);
    r.category = roleName(bodies[i].role);
    r.moves = true;
    r.lastFrame = furthest_;
    rows.push_back(std::move(r));
  }
  sim_.world().forEachItem([&](ItemId id, const Rect&) {
    if (bodyOf(id)) return;
    ItemRow r;
    r.id = id;
    r.name = describe(id);
    r.category = "solid";
    r.lastFrame = furthest_;
    rows.push_back(std::move(r));
  });
  return rows;
}

}  // namespace tv::ui
