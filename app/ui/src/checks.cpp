// What the debugger learns about the whole run beside the view.
#include "tv/ui/checks.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>

#include "tv/ui/replay_source.hpp"
#include "tv/ui/sim_source.hpp"
#include "tv/ui/words.hpp"

namespace tv::ui {

namespace {

// A re-run body this far from where the recording goes on makes the game's next goals moot.
constexpr double kFarAway = 64.0;

struct Counts {
  std::uint64_t tunnelled, overlaps, escapes, snags, jitter, misses;
};

Counts countsOf(const sim::Simulation& s) {
  const sim::Counters& c = s.counters();
  // Misses count only where the scene calls them failures (not an exact graze).
  return {c.tunnelled, c.overlaps, c.escapes, c.snags, c.jitter,
          s.scene().missesFail ? c.misses : 0};
}

// The first failure kind in which `a` is worse than `b`, e.g. "tunnelled".
const char* worse(const Counts& a, const Counts& b) {
  if (a.tunnelled > b.tunnelled) return "tunnelled";
  if (a.overlaps > b.overlaps) return "overlapped a solid";
  if (a.escapes > b.escapes) return "escaped";
  if (a.snags > b.snags) return "snagged on a seam";
  if (a.jitter > b.jitter) return "jittered";
  if (a.misses > b.misses) return "missed";
  return nullptr;
}

// "814 moves re-run, 60 ended elsewhere; the runs differ from frame 25; from frame 31 the
// game's goals stop making sense (a re-run body is far from where the recording goes on)".
std::string whatIfSummary(const WhatIfReport& r) {
  std::string s = std::to_string(r.moves) + " moves re-run, " +
                  std::to_string(r.differences.size()) + " ended elsewhere";
  if (r.firstDifferentFrame) {
    s += "; the runs differ from frame " + std::to_string(*r.firstDifferentFrame);
  } else {
    s += "; the runs never differ";
  }
  if (r.firstImplausibleFrame) {
    s += "; from frame " + std::to_string(*r.firstImplausibleFrame) +
         " the game's goals stop making sense (a re-run body is far from where the recording "
         "goes on)";
  }
  if (r.failedCalls > 0) {
    s += "; " + std::to_string(r.failedCalls) + " calls refused by the re-run world";
  }
  return s;
}

}  // namespace

Checks::~Checks() = default;

void Checks::reset(Session& session, bool wait) {
  session_ = &session;
  sims_.clear();
  known_ = 0;
  difference_.reset();
  failure_.reset();
  failureText_.clear();
  list_ = {};
  validation_.reset();
  whatIfs_.clear();
  collected_.clear();
  validationCollected_ = false;
  whatIfReport_.reset();
  error_.clear();
  sceneDone_ = true;

  if (session.primary().sim()) {
    for (std::size_t k = 0; k < session.size(); ++k) {
      const SimSource* s = session.panel(k).sim();
      if (!s) continue;
      const sim::Simulation& shown = s->simulation();
      auto copy = std::make_unique<sim::Simulation>(shown.scene(), shown.params(), shown.moverSpec());
      copy->setManyCollisions(kManyResponses);
      sims_.push_back(std::move(copy));
    }
    sceneDone_ = sims_.empty();
    return;
  }
  const ReplaySource* recorded = session.primary().replay();
  if (!recorded) return;
  // The recorded run's own failures come from validating it; each what-if panel's from its run.
  // A what-if that makes updates moves judges the recorded run the same way, as tv-replay does.
  bool updatesAsMoves = false;
  for (std::size_t k = 1; k < session.size(); ++k) {
    if (const ReplaySource* r = session.panel(k).replay()) {
      updatesAsMoves = updatesAsMoves || r->recording().options().updatesAsMoves;
    }
  }
  validation_ = std::make_unique<ValidationJob>();
  validation_->start(recorded->origin(), wait, updatesAsMoves);
  for (std::size_t k = 1; k < session.size(); ++k) {
    const ReplaySource* r = session.panel(k).replay();
    auto job = std::make_unique<WhatIfJob>();
    if (r) job->start(r->origin(), r->recording().options(), kFarAway, wait);
    whatIfs_.push_back(std::move(job));
    collected_.push_back(false);
  }
  collect();
}

bool Checks::running() const {
  if (validation_ && validation_->running()) return true;
  return std::any_of(whatIfs_.begin(), whatIfs_.end(), [](const auto& j) { return j->running(); });
}

bool Checks::done() const {
  if (!sims_.empty()) return sceneDone_;
  return !running();
}

void Checks::noteSceneFailures() {
  // The baseline is the best any mover did in each kind (none with one mover): a mover worse
  // than it failed where another did not. Every mover is checked, and every one that failed at
  // this tick is named.
  Counts best = countsOf(*sims_.front());
  if (sims_.size() == 1) best = {0, 0, 0, 0, 0, 0};
  for (const auto& s : sims_) {
    const Counts c = countsOf(*s);
    best = {std::min(best.tunnelled, c.tunnelled), std::min(best.overlaps, c.overlaps),
            std::min(best.escapes, c.escapes),     std::min(best.snags, c.snags),
            std::min(best.jitter, c.jitter),       std::min(best.misses, c.misses)};
  }
  for (const auto& s : sims_) {
    const char* what = worse(countsOf(*s), best);
    if (!what) continue;
    failure_ = known_;
    if (!failureText_.empty()) failureText_ += ", ";
    failureText_ += s->moverSpec().name() + " " + what;
  }
}

void Checks::advance(double budgetMs) {
  collect();
  if (sims_.empty() || sceneDone_) return;
  const auto start = std::chrono::steady_clock::now();
  const std::size_t before = list_.entries.size();
  while (!sceneDone_) {
    bool allFinished = true;
    for (std::size_t k = 0; k < sims_.size(); ++k) {
      sim::Simulation& s = *sims_[k];
      s.tick();
      allFinished = allFinished && s.finished();
      // Named by the panel's source: the same scene, so the same items.
      const Source& named = session_->panel(std::min(k, session_->size() - 1));
      for (const sim::TickEvent& e : s.events()) {
        if (list_.entries.size() >= kMaxListed) break;
        if (auto f = failureOf(s, e, named)) list_.entries.push_back({k, std::move(*f)});
      }
    }
    known_ = sims_.front()->ticks();
    list_.looked = known_;
    for (std::size_t k = 1; k < sims_.size() && !difference_; ++k) {
      if (sims_[k]->stateHash() != sims_.front()->stateHash()) difference_ = known_;
    }
    if (!failure_) noteSceneFailures();
    // Runs on after the marks are found: the timeline's length is how far this has looked.
    if (allFinished || known_ >= kHorizon) {
      sceneDone_ = true;
      list_.complete = true;
      if (!allFinished) list_.note = "looked at the first " + std::to_string(kHorizon) + " ticks";
    }
    const std::chrono::duration<double, std::milli> spent = std::chrono::steady_clock::now() - start;
    if (spent.count() > budgetMs) break;
  }
  // In frame order within each panel, the panels one after the other.
  if (list_.entries.size() != before) std::stable_sort(list_.entries.begin(), list_.entries.end(),
                   [](const FailureList::Entry& a, const FailureList::Entry& b) {
                     return a.panel < b.panel;
                   });
}

void Checks::noteMove(std::size_t panel, const MoveDifference& d, bool recorded) {
  if (!d.tunnelled && !d.overlapping) return;
  if (list_.entries.size() >= kMaxListed) return;
  Failure f;
  f.frame = d.frame;
  f.call = d.call;
  f.item = d.item;
  f.kind = d.tunnelled ? FailureKind::tunnelled : FailureKind::overlapping;
  // Named as the recording names it: "tunnelled through wall", "ended inside tile 12".
  std::string what = d.tunnelled ? "tunnelled" : "ended inside a solid";
  if (d.solid.valid()) {
    what = std::string(d.tunnelled ? "tunnelled through " : "ended inside ") +
           session_->primary().describe(d.solid);
  }
  if (!recorded) {
    // A re-run's move: how far from where the game's own move ended.
    char by[64];
    std::snprintf(by, sizeof by, ", %.4g from the recorded end", d.distance);
    what += by;
  }
  f.what = std::move(what);
  list_.entries.push_back({panel, std::move(f)});
}

void Checks::collect() {
  if (!session_ || !sims_.empty()) return;
  bool changed = false;
  if (validation_ && !validationCollected_ && validation_->done()) {
    validationCollected_ = true;
    if (const auto d = validation_->divergence()) {
      Failure f;
      f.frame = d->frame;
      f.call = d->call;
      f.kind = FailureKind::diverged;
      f.what = "diverged: " + d->what + " recorded " + d->expected + ", replayed " + d->got;
      if (const ReplaySource* r = session_->primary().replay()) {
        if (const auto id = r->findLabel(d->item)) f.item = *id;
      }
      list_.entries.push_back({0, std::move(f)});
    }
    // The recorded run's own moves that tunnelled or ended inside a solid: the game's.
    for (const MoveDifference& d : validation_->recordedFailures()) noteMove(0, d, true);
    changed = true;
  }
  for (std::size_t k = 0; k < whatIfs_.size(); ++k) {
    if (collected_[k] || !whatIfs_[k]->done()) continue;
    collected_[k] = true;
    changed = true;
    if (!whatIfs_[k]->error().empty()) {
      error_ = whatIfs_[k]->error();
      continue;
    }
    const auto report = whatIfs_[k]->report();
    if (!report) continue;
    if (k == 0) whatIfReport_ = report;
    list_.summary.resize(session_->size());
    list_.summary[k + 1] = whatIfSummary(*report);
    for (const MoveDifference& d : report->differences) noteMove(k + 1, d, false);
  }
  if (!changed) return;
  std::stable_sort(list_.entries.begin(), list_.entries.end(),
                   [](const FailureList::Entry& a, const FailureList::Entry& b) {
                     return a.panel != b.panel ? a.panel < b.panel
                                               : a.failure.frame < b.failure.frame;
                   });
  list_.complete = !running();
  const ReplaySource* r = session_->primary().replay();
  list_.looked = r && r->frames() > 0 ? r->frames() - 1 : 0;  // the last frame looked at
  failure_.reset();
  failureText_.clear();
  for (const auto& e : list_.entries) {
    if (!failure_ || e.failure.frame < *failure_) {
      failure_ = e.failure.frame;
      failureText_ = session_->panel(e.panel).moverName() + " " + e.failure.what;
    }
  }
  known_ = list_.complete ? list_.looked : (validation_ ? validation_->progress() : 0);
  if (whatIfReport_) difference_ = whatIfReport_->firstDifferentFrame;
}

}  // namespace tv::ui
