#include "tv/timestep.hpp"

#include <algorithm>
#include <string>

#include "tv/error.hpp"

namespace tv {

namespace {
constexpr double kMaxTicksPerFrame = 1 << 20;
}  // namespace

FixedStep::FixedStep(double step, double maxFrameTime) : step_(step), maxFrameTime_(maxFrameTime) {
  constexpr std::string_view where = "tv::FixedStep";
  requirePositive(where, "step", step);
  requireFinite(where, "maxFrameTime", maxFrameTime);
  if (maxFrameTime < step) {
    fail(where, "maxFrameTime must be >= step (" + formatNumber(step) + "), but was " +
                    formatNumber(maxFrameTime));
  }
  // One frame may call for at most 2^20 ticks: beyond that a frame is a freeze, the tick count
  // would overflow, and at extreme ratios accumulator - step no longer shrinks.
  if (maxFrameTime / step > kMaxTicksPerFrame) {
    fail(where, "maxFrameTime / step must be <= 2^20, but was " + formatNumber(maxFrameTime) +
                    " / " + formatNumber(step));
  }
}

int FixedStep::advance(double frameTime) {
  constexpr std::string_view where = "tv::FixedStep::advance";
  requireFinite(where, "frameTime", frameTime);
  if (frameTime < 0.0) fail(where, "frameTime must be >= 0, but was " + formatNumber(frameTime));
  ++frames_;
  if (frameTime > maxFrameTime_) {
    ++clamped_;
    frameTime = maxFrameTime_;
  }
  accumulator_ += frameTime;
  int n = 0;
  while (accumulator_ >= step_) {
    accumulator_ -= step_;
    ++n;
  }
  ticks_ += static_cast<std::uint64_t>(n);
  if (observer_) observer_->advanced(frameTime, n);
  return n;
}

}  // namespace tv
