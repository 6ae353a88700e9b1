#pragma once
/// Fixed-timestep accumulator ("Fix Your Timestep!"): physics advances in equal ticks whatever
/// the render rate; rendering interpolates between the last two physics states.

#include <cmath>
#include <cstdint>

#include "tv/geometry.hpp"
#include "tv/observer.hpp"

namespace tv {

/// The fixed-step accumulator: a frame's time in, the number of physics ticks to run out.
///
///     tv::FixedStep clock;                             // 1/60 s ticks
///     for (int n = clock.advance(frameSeconds); n > 0; --n) {
///       previous = world.rect(player).position();      // the state before each tick
///       world.move(player, goal, filter);
///     }
///     draw(tv::interpolate(previous, world.rect(player).position(), clock.alpha()));
class FixedStep {
 public:
  /// `step`: seconds per tick, finite and > 0 (default 1/60). `maxFrameTime`: longest frame
  /// counted, finite and >= step (default 0.25 s) — the spiral-of-death guard: a long hitch
  /// costs at most maxFrameTime / step catch-up ticks instead of freezing the game. That ratio
  /// must be at most 2^20.
  explicit FixedStep(double step = 1.0 / 60.0, double maxFrameTime = 0.25);

  /// Adds one rendered frame's duration (finite, >= 0) and returns how many ticks to run
  /// before drawing it. Throws tv::Error on a bad frame time, changing nothing.
  [[nodiscard]] int advance(double frameTime);

  /// Where the render falls between the previous tick's state (0) and the current one (1).
  [[nodiscard]] double alpha() const { return accumulator_ / step_; }
  [[nodiscard]] double step() const { return step_; }                  ///< seconds per tick
  [[nodiscard]] double maxFrameTime() const { return maxFrameTime_; }  ///< seconds
  /// Seconds of frame time not yet run as ticks, in [0, step).
  [[nodiscard]] double accumulator() const { return accumulator_; }
  [[nodiscard]] std::uint64_t ticks() const { return ticks_; }    ///< ticks handed out so far
  [[nodiscard]] std::uint64_t frames() const { return frames_; }  ///< advance() calls so far
  /// Frames longer than maxFrameTime, whose excess was dropped.
  [[nodiscard]] std::uint64_t clampedFrames() const { return clamped_; }
  /// Reports every advance to `observer` (a recorder marks a frame there); null to stop.
  void attach(WorldObserver* observer) { observer_.set(observer, this); }

 private:
  double step_;
  double maxFrameTime_;
  double accumulator_ = 0.0;
  std::uint64_t ticks_ = 0;
  std::uint64_t frames_ = 0;
  std::uint64_t clamped_ = 0;
  detail::ObserverLink observer_;  // a copy reports to no one
};

/// Render position between two physics states.
[[nodiscard]] inline Vec2 interpolate(Vec2 previous, Vec2 current, double alpha) {
  return {previous.x + (current.x - previous.x) * alpha,
          previous.y + (current.y - previous.y) * alpha};
}

/// Pixel-art snapping on draw: the physics state stays fractional, the sprite does not.
[[nodiscard]] inline Vec2 floorOnDraw(Vec2 p) { return {std::floor(p.x), std::floor(p.y)}; }

}  // namespace tv
