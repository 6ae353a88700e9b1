#pragma once
/// How much work one tick of a scene asks of a mover, estimated before running it, so that a
/// speed of 1e9 px/s is refused with a message that says why and what the limit is instead of
/// freezing the program (tv-run, tv-render, tv-debugger alike). Core runs what it is given;
/// the tools decide what they are willing to start.
///
/// The estimate counts the unit each mover pays per move for a move of speed × dt: pieces for
/// the substep movers, pixels for `pixel`, cells of the bounding box for `sweep` (its area: a
/// diagonal costs the square), cells along the path for `continuous` and `adaptive`, one query
/// for `discrete`; times the bodies; times a cost per unit measured on the 2-core build machine
/// (Release, bullets-wall, 1000 bodies). It is a bound on the order of magnitude, not a timing.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>

#include "tv/error.hpp"
#include "tv/mover.hpp"
#include "tv/sim/params.hpp"

namespace tv::app {

/// Estimated seconds of work per tick above which a run is refused.
inline constexpr double kMaxSecondsPerTick = 1.0;

/// The latest tick a still or the debugger is asked to open at: a scene that never ends would
/// otherwise run for ever on --tick 99999999. A million ticks is over four hours at 60 Hz.
inline constexpr std::uint64_t kMaxTicks = 1'000'000;

struct TickWork {
  double units = 0.0;    ///< per move: pieces, pixels or cells
  const char* unit = "";  ///< "pieces of 8 px", "pixel steps", ...
  double seconds = 0.0;  ///< estimated for every body
};

namespace detail {
// Nanoseconds per unit, measured with tv-run --speed 1e6 / 1e7 on bullets-wall (0° and 45°).
inline constexpr double kNsPerPiece = 200.0;
inline constexpr double kNsPerPixel = 15.0;
inline constexpr double kNsPerCell = 15.0;
}  // namespace detail

/// The work of one tick of `bodies` bodies moving `speed` px/s for `dt` s with `mover` (its
/// maxStep already resolved, as Simulation::moverSpec() has it) over cells of `cell` px.
[[nodiscard]] inline TickWork tickWork(double speed, double dt, double cell,
                                       const MoverSpec& mover, std::size_t bodies) {
  const double d = std::abs(speed * dt);
  const double c = cell > 0.0 ? cell : 64.0;
  TickWork w;
  double ns = 0.0;
  switch (mover.kind) {
    case MoverKind::discrete:
      w.units = 1.0;
      w.unit = "query";
      ns = detail::kNsPerCell;
      break;
    case MoverKind::substep: {
      const double piece = mover.maxStep > 0.0 ? mover.maxStep : 1.0;
      w.units = std::ceil(d / piece);
      w.unit = "pieces";
      ns = detail::kNsPerPiece;
      break;
    }
    case MoverKind::pixel:
      w.units = std::ceil(d * std::sqrt(2.0));  // x then y: up to |dx| + |dy| steps
      w.unit = "pixel steps";
      ns = detail::kNsPerPixel;
      break;
    case MoverKind::sweep: {
      const double side = d / std::sqrt(2.0) / c + 2.0;  // the diagonal's box, the worst
      w.units = side * side;
      w.unit = "cells (its bounding box)";
      ns = detail::kNsPerCell;
      break;
    }
    default:
      w.units = d / c + 2.0;
      w.unit = "cells";
      ns = detail::kNsPerCell;
      break;
  }
  w.seconds = w.units * static_cast<double>(bodies) * ns * 1e-9;
  return w;
}

/// Why a run of `params` with `mover` over `bodies` bodies is refused, or nothing when it is
/// within kMaxSecondsPerTick. The message names the speed, what a move costs, the limit and
/// the largest speed that fits.
[[nodiscard]] inline std::optional<std::string> workLimitExceeded(const sim::Params& params,
                                                                  const MoverSpec& mover,
                                                                  std::size_t bodies) {
  const double speed = params.get(sim::param::speed);
  const double dt = params.get(sim::param::dt);
  const double cell = params.get(sim::param::cell);
  const TickWork w = tickWork(speed, dt, cell, mover, bodies);
  if (w.seconds <= kMaxSecondsPerTick) return std::nullopt;
  // The largest speed that fits, by bisection (the estimate grows with the speed).
  double lo = 0.0, hi = speed;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (tickWork(mid, dt, cell, mover, bodies).seconds <= kMaxSecondsPerTick) {
      lo = mid;
    } else {
      hi = mid;
    }
  }
  char text[512];
  std::snprintf(text, sizeof text,
                "--speed %s: %s would take %.3g %s per move (%.3g px a tick) for %zu bodies, "
                "about %.3g s of work per tick; the limit is %g s per tick, so at most "
                "--speed %.3g here (or fewer bodies with --count%s)",
                formatNumber(speed).c_str(), mover.name().c_str(), w.units, w.unit,
                std::abs(speed * dt), bodies, w.seconds, kMaxSecondsPerTick, lo,
                mover.kind == MoverKind::substep ? ", or a longer --substep" : "");
  return std::string(text);
}

}  // namespace tv::app
