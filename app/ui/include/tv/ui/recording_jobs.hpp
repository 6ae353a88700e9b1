#pragma once
/// Whole-recording checks that run beside the view, each on its own Replay in its own thread,
/// so playback goes on while they work: validation (the first divergence, with progress) and a
/// what-if run under another mover (the report). Screenshots run them to the end first, so the
/// marks never depend on how fast the machine is.

#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "tv/record/replay.hpp"
#include "tv/ui/replay_source.hpp"

namespace tv::ui {

class ValidationJob {
 public:
  ValidationJob() = default;
  ~ValidationJob();
  ValidationJob(const ValidationJob&) = delete;
  ValidationJob& operator=(const ValidationJob&) = delete;

  /// Validates the recording from the start (stops any run before), as `tv-replay --validate
  /// --traced` does: call after call untraced, then — when that matched — every call traced and
  /// from each keyframe, as the debugger re-runs what it shows. `wait`: in this thread.
  /// `updatesAsMoves`: the recorded run's failures count its position-only updates as moves,
  /// as a what-if with --updates-as-moves judges it (tv-replay's "recorded run" column).
  void start(const ReplaySource::Origin& origin, bool wait, bool updatesAsMoves = false);
  void stop();

  [[nodiscard]] bool running() const { return running_.load(); }
  [[nodiscard]] bool done() const { return done_.load(); }
  /// Frames checked so far by the first pass (untraced).
  [[nodiscard]] std::uint64_t progress() const { return progress_.load(); }
  /// While the second pass (traced) runs: the frame it is at.
  [[nodiscard]] std::optional<std::uint64_t> tracedProgress() const {
    if (!tracing_.load()) return std::nullopt;
    return tracedProgress_.load();
  }
  /// The first divergence, once done (none: the replay matched the recording, untraced and
  /// traced).
  [[nodiscard]] std::optional<tv::Divergence> divergence() const;
  /// The divergence was found only by the traced pass: the calls as the game made them replay
  /// bit for bit, the same calls traced do not.
  [[nodiscard]] bool divergedTracedOnly() const { return tracedOnly_.load(); }
  /// The recorded run's own moves that tunnelled or ended inside a solid (Replay::checkRecorded),
  /// once done.
  [[nodiscard]] std::vector<MoveDifference> recordedFailures() const;
  /// Why it could not run (a file that no longer opens), once done.
  [[nodiscard]] std::string error() const;

 private:
  void run(const ReplaySource::Origin& origin, bool updatesAsMoves);

  std::thread thread_;
  std::atomic<bool> running_{false}, done_{false}, cancel_{false}, tracing_{false}, tracedOnly_{false};
  std::atomic<std::uint64_t> progress_{0}, tracedProgress_{0};
  mutable std::mutex mutex_;
  std::optional<tv::Divergence> divergence_;
  std::vector<MoveDifference> recordedFailures_;
  std::string error_;
};

class WhatIfJob {
 public:
  WhatIfJob() = default;
  ~WhatIfJob();
  WhatIfJob(const WhatIfJob&) = delete;
  WhatIfJob& operator=(const WhatIfJob&) = delete;

  /// Re-runs the recording with `options.mover`, comparing with what it recorded.
  void start(const ReplaySource::Origin& origin, const ReplayOptions& options, double farAway,
             bool wait);
  [[nodiscard]] bool running() const { return running_.load(); }
  [[nodiscard]] bool done() const { return done_.load(); }
  /// The report, once done.
  [[nodiscard]] std::optional<WhatIfReport> report() const;
  [[nodiscard]] std::string error() const;

 private:
  void join();

  std::thread thread_;
  std::atomic<bool> running_{false}, done_{false};
  mutable std::mutex mutex_;
  std::optional<WhatIfReport> report_;
  std::string error_;
};

}  // namespace tv::ui
