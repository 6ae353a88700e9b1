#pragma once
/// What the debugger learns about the whole run beside the view, whatever the source: how far it
/// goes, where the panels first part ways, the first failure, every failure (the Failures tab),
/// and where a recording diverges from what it recorded. A still (tv-render, the debugger's
/// --screenshot) asks the same checks when its picture is about failures (--first-failure, a
/// what-if run), so both programs list the same ones.
///
/// A scene's panels: untraced copies of their simulations run ahead of the view in lockstep, a
/// few milliseconds per frame, recording every tick's state hash and what the rules counted,
/// body by body. A recording: validation, and each what-if panel's run under its mover, in
/// threads beside the view. Screenshots and stills run everything to the end first, so the marks
/// never depend on how fast the machine is.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "tv/record/replay.hpp"
#include "tv/sim/simulation.hpp"
#include "tv/ui/panels.hpp"
#include "tv/ui/recording_jobs.hpp"
#include "tv/ui/session.hpp"

namespace tv::ui {

class Checks {
 public:
  /// Ticks a scene is looked ahead at most (a minute at 60 Hz).
  static constexpr std::uint64_t kHorizon = 3600;
  /// Failures listed at most (a scene of 10^4 bodies failing every tick would fill memory).
  static constexpr std::size_t kMaxListed = 20000;

  Checks() = default;
  ~Checks();
  Checks(const Checks&) = delete;
  Checks& operator=(const Checks&) = delete;

  /// Starts again for the session's panels (which must outlive this or the next reset). `wait`:
  /// run the threads' work in this thread (screenshots). May throw tv::Error.
  void reset(Session& session, bool wait);
  /// Runs a scene's look-ahead for about `budgetMs` of wall time, and collects what the threads
  /// have finished.
  void advance(double budgetMs);

  /// Nothing left to learn (everything looked at, or the threads are done).
  [[nodiscard]] bool done() const;
  /// Frames looked at so far.
  [[nodiscard]] std::uint64_t known() const { return known_; }
  /// First frame whose state differs between the panels (scenes compared).
  [[nodiscard]] std::optional<std::uint64_t> firstDifference() const { return difference_; }
  /// First frame at which any mover's failure counts exceed the best of the compared movers, or
  /// with one mover the first frame with any; a recording's first listed failure.
  [[nodiscard]] std::optional<std::uint64_t> firstFailure() const { return failure_; }
  /// What failed first there, e.g. "discrete tunnelled, substep-discrete tunnelled".
  [[nodiscard]] const std::string& failureText() const { return failureText_; }
  /// Every failure found so far, per panel.
  [[nodiscard]] const FailureList& failures() const { return list_; }
  /// A recording's validation: running, done, its divergence or why it could not run.
  [[nodiscard]] const ValidationJob* validation() const { return validation_.get(); }
  /// The first what-if panel's report, once done.
  [[nodiscard]] const std::optional<WhatIfReport>& whatIf() const { return whatIfReport_; }
  /// A what-if run's error, if one failed.
  [[nodiscard]] const std::string& error() const { return error_; }
  /// Threads still working.
  [[nodiscard]] bool running() const;

 private:
  void noteSceneFailures();
  void collect();
  // Lists a recorded move (`recorded`) or a re-run's that tunnelled or ended inside a solid.
  void noteMove(std::size_t panel, const MoveDifference& d, bool recorded);

  Session* session_ = nullptr;
  // A scene's look-ahead: one untraced copy per panel.
  std::vector<std::unique_ptr<sim::Simulation>> sims_;
  bool sceneDone_ = true;
  std::uint64_t known_ = 0;
  std::optional<std::uint64_t> difference_, failure_;
  std::string failureText_;
  FailureList list_;
  // A recording's jobs: validation, and one what-if run per panel after the first.
  std::unique_ptr<ValidationJob> validation_;
  std::vector<std::unique_ptr<WhatIfJob>> whatIfs_;
  std::vector<bool> collected_;
  bool validationCollected_ = false;
  std::optional<WhatIfReport> whatIfReport_;
  std::string error_;
};

}  // namespace tv::ui
