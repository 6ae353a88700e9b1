#include "divergence.hpp"

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

void Divergence::advance(double budgetMs) {
  if (done_) return;
  const auto start = std::chrono::steady_clock::now();
  const Failures none{0, 0, 0, 0, 0};
  while (!done_) {
    bool allFinished = true;
    for (auto& s : sims_) {
      s->tick();
      allFinished = allFinished && s->finished();
    }
    known_ = sims_.front()->ticks();
    const Failures first = failuresOf(sims_.front()->counters());
    for (std::size_t k = 0; k < sims_.size(); ++k) {
      const sim::Simulation& s = *sims_[k];
      if (!difference_ && k > 0 && s.stateHash() != sims_.front()->stateHash()) {
        difference_ = known_;
      }
      if (failure_) continue;
      // Compared: someone failed where another did not. Alone: the first failure.
      const Failures f = failuresOf(s.counters());
      const Failures& other =
          sims_.size() > 1 ? (k == 0 ? failuresOf(sims_[1]->counters()) : first) : none;
      if (const char* what = worse(f, other)) {
        failure_ = known_;
        failureText_ = s.moverSpec().name() + " " + what;
      }
    }
    // Runs on after the marks are found: the timeline's length is how far this has looked.
    if (allFinished || known_ >= kHorizon) done_ = true;
    const std::chrono::duration<double, std::milli> spent =
        std::chrono::steady_clock::now() - start;
    if (spent.count() > budgetMs) break;
  }
}

}  // namespace tv::viewer
