#pragma once
/// A long run to the tick a tool opens at (`--tick 999999` of a scene that never ends runs for
/// minutes), said on stderr as it goes: nothing in the first second, then a line every few
/// seconds with the tick reached, the share done and the time left at the rate so far.

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <string>
#include <utility>

#include "tv/ui/sim_source.hpp"

namespace tv::ui {

class TickProgress {
 public:
  /// `tool` starts each line ("tv-render"); `what` names the run ("--tick 999999").
  TickProgress(std::string tool, std::string what) : tool_(std::move(tool)), what_(std::move(what)) {}

  /// What SimSource::setProgress calls. A run that starts again from a lower tick (the next
  /// compared mover) is timed afresh.
  void operator()(std::uint64_t reached, std::uint64_t target) {
    const Clock::time_point now = Clock::now();
    if (reached < last_) start_ = now;
    last_ = reached;
    const double ran = seconds(now - start_);
    if (ran < 1.0 || seconds(now - said_) < 3.0) return;
    said_ = now;
    const double left = ran * static_cast<double>(target - reached) / static_cast<double>(reached);
    const bool minutes = left >= 120.0;
    std::fprintf(stderr, "%s: %s: at tick %llu (%.0f%%), about %.0f %s to go\n", tool_.c_str(),
                 what_.c_str(), static_cast<unsigned long long>(reached),
                 100.0 * static_cast<double>(reached) / static_cast<double>(target),
                 minutes ? left / 60.0 : left, minutes ? "min" : "s");
  }

  /// Reports the run of every panel of `session` to `*progress` until the next call with null.
  template <typename SessionT>
  static void attach(SessionT& session, TickProgress* progress) {
    for (std::size_t k = 0; k < session.size(); ++k) {
      SimSource* s = session.panel(k).sim();
      if (!s) continue;
      if (progress) {
        s->setProgress([progress](std::uint64_t r, std::uint64_t t) { (*progress)(r, t); });
      } else {
        s->setProgress({});
      }
    }
  }

 private:
  using Clock = std::chrono::steady_clock;
  static double seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }
  std::string tool_, what_;
  Clock::time_point start_ = Clock::now();
  Clock::time_point said_{};
  std::uint64_t last_ = 0;
};

}  // namespace tv::ui
