#include "tv/ui/recording_jobs.hpp"

#include <exception>

#include "tv/app/user_message.hpp"

namespace tv::ui {

// -- validation --------------------------------------------------------------------------------

ValidationJob::~ValidationJob() {
  stop();
}

void ValidationJob::stop() {
  cancel_ = true;
  if (thread_.joinable()) thread_.join();
  cancel_ = false;
}

namespace {

Replay openOrigin(const ReplaySource::Origin& origin, const ReplayOptions& options) {
  return origin.bytes ? Replay::fromBytes(*origin.bytes, options) : Replay::open(origin.path, options);
}

}  // namespace

void ValidationJob::start(const ReplaySource::Origin& origin, bool wait, bool updatesAsMoves) {
  stop();
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    divergence_.reset();
    recordedFailures_.clear();
    error_.clear();
  }
  progress_ = 0;
  tracedProgress_ = 0;
  tracing_ = false;
  tracedOnly_ = false;
  done_ = false;
  running_ = true;
  if (wait) {
    run(origin, updatesAsMoves);
  } else {
    thread_ = std::thread([this, origin, updatesAsMoves] { run(origin, updatesAsMoves); });
  }
}

void ValidationJob::run(const ReplaySource::Origin& origin, bool updatesAsMoves) {
  std::optional<tv::Divergence> d;
  std::vector<MoveDifference> failures;
  std::string error;
  bool cancelled = false;
  try {
    ReplayOptions o;
    o.tolerant = true;
    Replay replay = openOrigin(origin, o);
    d = replay.validate([this](std::uint64_t frame) {
      progress_ = frame;
      return !cancel_.load();
    });
    cancelled = replay.cancelled();
    // Then the game's own moves, judged: what the Failures tab lists for the recorded run.
    if (!cancelled && !cancel_.load()) {
      if (updatesAsMoves) {
        ReplayOptions judged = o;
        judged.updatesAsMoves = true;
        failures = openOrigin(origin, judged).checkRecorded().recordedFailures;
      } else {
        failures = replay.checkRecorded().recordedFailures;
      }
    }
    if (!cancelled) progress_ = replay.frames();
    // Then every call traced, as the debugger replays what it draws: a divergence there is one
    // the picture would show, and the status bar must say so too.
    if (!d && !cancelled && !cancel_.load()) {
      tracing_ = true;
      d = replay.validate(
          [this](std::uint64_t frame) {
            tracedProgress_ = frame;
            return !cancel_.load();
          },
          Replay::Tracing::on);
      cancelled = replay.cancelled();
      tracedOnly_ = d.has_value();
      tracing_ = false;
    }
  } catch (const std::exception& e) {
    error = app::userMessage(e);
  }
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    divergence_ = std::move(d);
    recordedFailures_ = std::move(failures);
    error_ = std::move(error);
  }
  tracing_ = false;
  running_ = false;
  done_ = !cancelled;
}

std::optional<tv::Divergence> ValidationJob::divergence() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return divergence_;
}

std::vector<MoveDifference> ValidationJob::recordedFailures() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return recordedFailures_;
}

std::string ValidationJob::error() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return error_;
}

// -- what-if -----------------------------------------------------------------------------------

WhatIfJob::~WhatIfJob() {
  join();
}

void WhatIfJob::join() {
  // Replay::whatIf cannot be cancelled: a run started is waited for (it replays without
  // tracing, about a million moves a second).
  if (thread_.joinable()) thread_.join();
}

void WhatIfJob::start(const ReplaySource::Origin& origin, const ReplayOptions& options,
                      double farAway, bool wait) {
  join();
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    report_.reset();
    error_.clear();
  }
  done_ = false;
  running_ = true;
  auto work = [this, origin, options, farAway] {
    std::optional<WhatIfReport> report;
    std::string error;
    try {
      Replay replay = openOrigin(origin, options);
      report = replay.whatIf(farAway);
    } catch (const std::exception& e) {
      error = app::userMessage(e);
    }
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      report_ = std::move(report);
      error_ = std::move(error);
    }
    running_ = false;
    done_ = true;
  };
  if (wait) {
    work();
  } else {
    thread_ = std::thread(work);
  }
}

std::optional<WhatIfReport> WhatIfJob::report() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return report_;
}

std::string WhatIfJob::error() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return error_;
}

}  // namespace tv::ui
