#include "tv/ui/session.hpp"

#include <algorithm>

#include "tv/error.hpp"

namespace tv::ui {

namespace {
constexpr std::string_view kWhere = "tv::ui::Session";

void checkBody(const sim::Simulation& s, std::optional<std::size_t> body) {
  if (body && *body >= s.bodies().size()) {
    fail(kWhere, "body " + std::to_string(*body) + " does not exist (the scene has " +
                     std::to_string(s.bodies().size()) + " bodies: 0.." +
                     std::to_string(s.bodies().size() - 1) + ")");
  }
}
}  // namespace

Session::Session(const sim::SceneDef& scene, const sim::Params& params, MoverSpec mover,
                 std::optional<std::size_t> selected)
    : sim_(scene, params, mover) {
  select(selected);
}

void Session::select(std::optional<std::size_t> body) {
  checkBody(sim_, body);
  selected_ = body;
  sim_.traceBody(body);
  moves_.clear();
}

void Session::setHistoryLength(std::size_t n) {
  history_ = std::max<std::size_t>(n, 1);
  if (moves_.size() > history_) {
    moves_.erase(moves_.begin(), moves_.end() - static_cast<std::ptrdiff_t>(history_));
  }
}

void Session::noteTrace() {
  const MoveTrace* t = sim_.lastTrace();
  if (!t) return;
  if (moves_.size() == history_) moves_.erase(moves_.begin());
  moves_.push_back({sim_.ticks(), *t});
}

void Session::tick() {
  sim_.tick();
  noteTrace();
  noteFailure();
  interpolating_ = false;  // drawn at the tick: the accumulator's alpha no longer applies
}

int Session::frame(double seconds) {
  const int n = sim_.frame(seconds);
  interpolating_ = true;
  // A frame that ran several ticks leaves only its last tick's trace in the simulation.
  if (n > 0) noteTrace();
  noteFailure();
  return n;
}

std::uint64_t failureCount(const sim::Counters& c) {
  return c.tunnelled + c.escapes + c.overlaps + c.jitter + c.snags;
}

void Session::noteFailure() {
  // Counts only grow as ticks run; none means the simulation was taken back before the first
  // failure (a seek or a restart), and the tick recorded no longer holds.
  if (failureCount(sim_.counters()) == 0) {
    firstFailure_.reset();
  } else if (!firstFailure_) {
    firstFailure_ = sim_.ticks();
  }
}

void Session::advanceTo(std::uint64_t t, double renderHz, bool stopAtEnd) {
  if (t < sim_.ticks()) {
    fail(kWhere, "tick " + std::to_string(t) + " is behind the current tick " +
                     std::to_string(sim_.ticks()) + " (ticks must be in increasing order)");
  }
  // With stopAtEnd, a scene that has ended goes no further: nothing happens after its end.
  const auto more = [&] { return sim_.ticks() < t && !(stopAtEnd && sim_.finished()); };
  if (renderHz <= 0.0) {
    while (more()) tick();
    return;
  }
  const double frameTime = 1.0 / renderHz;
  while (more()) {
    frame(frameTime);
    if (sim_.ticks() > t) {
      fail(kWhere, "a render rate of " + formatNumber(renderHz) +
                       " Hz runs several ticks per frame and stepped over tick " +
                       std::to_string(t) + "; use a rate of at least 1 / dt");
    }
  }
}

void Session::restart(const sim::Params& params, MoverSpec mover) {
  sim_.restart(params, mover);
  firstFailure_.reset();
  checkBody(sim_, selected_);  // the body count may have changed
  select(selected_);
  interpolating_ = false;
}

WorldPicture Session::picture() {
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
  p.selected = selected_;
  p.moves = moves_;
  return p;
}

Rect Session::followView(double minSide) const {
  if (moves_.empty()) return sim_.camera();
  // The last move only: earlier ones trail off the edge rather than shrink the action.
  const MoveTrace& t = moves_.back().trace;
  Rect box = unite(t.start, t.start.at(t.goal));
  box = unite(box, t.start.at(t.final));
  for (const Collision& c : t.hits) box = unite(box, c.otherRect);
  const double pad = std::max(box.w, box.h) * 0.25;
  box = {box.x - pad, box.y - pad, box.w + 2 * pad, box.h + 2 * pad};
  const Vec2 c = box.center();
  const double w = std::max(box.w, minSide), h = std::max(box.h, minSide);
  return {c.x - w * 0.5, c.y - h * 0.5, w, h};
}

std::string Session::describe(ItemId id) const {
  const auto bodies = sim_.bodies();
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    if (bodies[i].item == id) return "body " + std::to_string(i);
  }
  return "solid " + std::to_string(id.index);
}

}  // namespace tv::ui
