#include "divergence.hpp"

#include <algorithm>
#include <chrono>
#include <string>

namespace tv::viewer {

namespace {

struct Failures {
  std::uint64_t tunnelled, overlaps, escapes, snags, jitter;
  friend bool operator==(const Failures&, const Failures&) = default;
};

Failures failuresOf(const sim::Counters& c) {
  return {c.tunnelled, c.overlaps, c.escapes, c.snags, c.jitter};
}

// The first failure kind in which `a` is worse than `b`, e.g. "tunnelled".
const char* worse(const Failures& a, const Failures& b) {
  if (a.tunnelled > b.tunnelled) return "tunnelled";
  if (a.overlaps > b.overlaps) return "overlapped a solid";
  if (a.escapes > b.escapes) return "escaped";
  if (a.snags > b.snags) return "snagged on a seam";
  if (a.jitter > b.jitter) return "jittered";
  return nullptr;
}

}  // namespace

void Divergence::reset(const sim::SceneDef& scene, const sim::Params& params,
                       const std::vector<MoverSpec>& movers) {
  sims_.clear();
  for (const MoverSpec& m : movers)
    sims_.push_back(std::make_unique<sim::Simulation>(scene, params, m));
  known_ = 0;
  done_ = sims_.empty();
  difference_.reset();
  failure_.reset();
  failureText_.clear();
}

void Divergence::noteFailures() {
  // The baseline is the best any mover did in each kind (none with one mover): a mover worse
  // than it failed where another did not. Every mover is checked, not only the first two, and
  // every one that failed at this tick is named.
  Failures best = failuresOf(sims_.front()->counters());
  if (sims_.size() == 1) best = Failures{0, 0, 0, 0, 0};
  for (const auto& s : sims_) {
    const Failures f = failuresOf(s->counters());
    best = {std::min(best.tunnelled, f.tunnelled), std::min(best.overlaps, f.overlaps),
            std::min(best.escapes, f.escapes), std::min(best.snags, f.snags),
            std::min(best.jitter, f.jitter)};
  }
  for (const auto& s : sims_) {
    const char* what = worse(failuresOf(s->counters()), best);
    if (!what) continue;
    failure_ = known_;
    if (!failureText_.empty()) failureText_ += ", ";
    failureText_ += s->moverSpec().name() + " " + what;
  }
}

void Divergence::advance(double budgetMs) {
  if (done_) return;
  const auto start = std::chrono::steady_clock::now();
  while (!done_) {
    bool allFinished = true;
    for (auto& s : sims_) {
      s->tick();
      allFinished = allFinished && s->finished();
    }
    known_ = sims_.front()->ticks();
    for (std::size_t k = 1; k < sims_.size() && !difference_; ++k) {
      if (sims_[k]->stateHash() != sims_.front()->stateHash()) difference_ = known_;
    }
    if (!failure_) noteFailures();
    // Runs on after the marks are found: the timeline's length is how far this has looked.
    if (allFinished || known_ >= kHorizon) done_ = true;
    const std::chrono::duration<double, std::milli> spent =
        std::chrono::steady_clock::now() - start;
    if (spent.count() > budgetMs) break;
  }
}

}  // namespace tv::viewer
