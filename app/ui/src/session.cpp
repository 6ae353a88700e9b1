// The session: panels in lockstep at one frame, one call, one traced item.
#include "tv/ui/session.hpp"

#include <algorithm>

#include "tv/error.hpp"
#include "tv/ui/sim_source.hpp"

namespace tv::ui {

Session::Session(std::unique_ptr<Source> primary) {
  if (!primary) fail("tv::ui::Session", "needs a source");
  panels_.push_back(std::move(primary));
}

Session::Session(std::vector<std::unique_ptr<Source>> panels) : panels_(std::move(panels)) {
  if (panels_.empty() || !panels_.front()) fail("tv::ui::Session", "needs a source");
}

std::vector<Source*> Session::panels() {
  std::vector<Source*> out;
  for (auto& p : panels_) out.push_back(p.get());
  return out;
}

void Session::setPanels(std::vector<std::unique_ptr<Source>> panels, std::uint64_t landOn) {
  if (panels.empty()) fail("tv::ui::Session", "needs a source");
  const std::optional<ItemId> item = traced();
  // Built and brought to the frame first, so a refusal leaves the session as it was.
  for (auto& p : panels) {
    if (item && p->world().has(*item)) p->trace(item);
  }
  std::vector<std::unique_ptr<Source>> old = std::move(panels_);
  panels_ = std::move(panels);
  try {
    goTo(landOn, true);
  } catch (...) {
    panels_ = std::move(old);
    throw;
  }
}

void Session::compareWith(const std::vector<MoverSpec>& others) {
  std::vector<std::unique_ptr<Source>> rest;
  for (const MoverSpec& m : others) rest.push_back(primary().rerun(m));  // may throw: no change
  compareWith(std::move(rest));
}

void Session::compareWith(std::vector<std::unique_ptr<Source>> others) {
  // The primary is kept as it is: its traces, its tuning.
  const std::uint64_t f = primary().frame();
  const auto call = primary().call();
  const auto item = primary().traced();
  panels_.resize(1);
  for (auto& r : others) {
    if (item && r->world().has(*item)) r->trace(item);
    r->goTo(f);
    panels_.push_back(std::move(r));
  }
  if (call) selectCall(call);
}

// -- time ----------------------------------------------------------------------------------------

std::uint64_t Session::lastFrame() const {
  std::uint64_t last = 0;
  for (const auto& p : panels_) last = std::max(last, p->lastFrame());
  return last;
}

bool Session::ended() const {
  return std::all_of(panels_.begin(), panels_.end(), [](const auto& p) { return p->ended(); });
}

std::uint64_t Session::goTo(std::uint64_t f, bool stopAtEnd) {
  std::uint64_t reached = 0;
  for (auto& p : panels_) {
    SimSource* s = p->sim();
    if (stopAtEnd && s && f > s->frame()) {
      // Forward, no further than the scene's end; a mover that ended early then runs on to
      // the frame the others reach (below).
      s->advanceTo(f, 0.0, true);
    } else {
      p->goTo(f);
    }
    reached = std::max(reached, p->frame());
  }
  for (auto& p : panels_) {
    if (p->frame() < reached && p->sim()) p->goTo(reached);
  }
  return primary().frame();
}

void Session::play() {
  for (auto& p : panels_) p->play();
}

void Session::selectCall(std::optional<std::uint32_t> k) {
  Source& first = primary();
  first.selectCall(k);
  const std::optional<ItemId> item =
      k && *k < first.calls().size() ? std::optional<ItemId>(first.calls()[*k].item) : std::nullopt;
  for (std::size_t i = 1; i < panels_.size(); ++i) {
    Source& p = *panels_[i];
    if (p.replay() || !k) {
      p.selectCall(k);  // a recording's re-runs make the same calls in the same order
      continue;
    }
    // Another mover's tick: the same item's move, wherever it falls among that tick's moves.
    std::optional<std::uint32_t> same;
    const auto calls = p.calls();
    for (std::uint32_t j = 0; j < calls.size(); ++j) {
      if (item && calls[j].item == *item) same = j;
    }
    if (same) {
      p.selectCall(same);
    } else if (item) {
      p.trace(item);
    }
  }
}

void Session::stepCall(int direction) {
  const std::size_t n = calls().size();
  const auto current = call();
  if (direction > 0) {
    if (!current && n > 0) return selectCall(0);
    if (current && *current + 1 < n) return selectCall(*current + 1);
    // Past the frame's last call: the next frame's first.
    if (frame() < lastFrame() || !ended()) {
      goTo(frame() + 1);
      if (!calls().empty()) selectCall(0);
    }
    return;
  }
  if (current && *current > 0) return selectCall(*current - 1);
  if (current) return selectCall(std::nullopt);
  if (frame() > firstFrame()) {
    goTo(frame() - 1);
    const std::size_t m = calls().size();
    if (m > 0) selectCall(static_cast<std::uint32_t>(m - 1));
  }
}

// -- tracing -------------------------------------------------------------------------------------

void Session::trace(std::optional<ItemId> item) {
  for (auto& p : panels_) p->trace(item);
}

void Session::showFailure(const Failure& f) {
  goTo(f.frame);
  if (f.item.valid()) trace(f.item);
  if (f.call && !primary().sim()) {
    if (*f.call < calls().size()) selectCall(f.call);
    return;
  }
  if (!f.item.valid()) return;
  // A scene's tick: that item's move, wherever it falls among the tick's moves.
  std::optional<std::uint32_t> move;
  const auto all = calls();
  for (std::uint32_t k = 0; k < all.size(); ++k) {
    if (all[k].item == f.item) move = k;
  }
  if (move) selectCall(move);
}

Rect Session::followView() const {
  Rect r = primary().followView();
  for (const auto& p : panels_) r = unite(r, p->followView(primary().followMinSide()));
  return r;
}

}  // namespace tv::ui
