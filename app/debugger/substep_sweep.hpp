#pragma once
// The substep sweep: the scene run to the current tick once per max substep length, each run
// measured — bodies tunnelled, position error against the exact (continuous) run, and wall
// time per tick — and plotted against the length. One run per frame, so the window fills in
// while the debugger stays responsive. Picking a length applies it (a live tune).

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "tv/mover.hpp"
#include "tv/sim/params.hpp"
#include "tv/sim/scene.hpp"

namespace tv::viewer {

struct SweepPoint {
  double length = 0.0;  ///< max substep length, px
  std::uint64_t tunnelled = 0;
  double error = 0.0;  ///< mean distance of a body from where the exact run has it, px
  double msPerTick = 0.0;
  bool skipped = false;  ///< not run: over the work limit (tv/app/work_limit.hpp)
};

class SubstepSweep {
 public:
  /// Starts over for the scene as it is now, up to `ticks` (at least 1), with `mover` (a
  /// substep mover; others are swept as substep-discrete, the one that can fail).
  void reset(const sim::SceneDef& scene, const sim::Params& params, MoverSpec mover,
             std::uint64_t ticks);
  /// Runs the next length, if any; returns true when something changed.
  bool advance();

  [[nodiscard]] bool stale(const sim::SceneDef& scene, const sim::Params& params,
                           const MoverSpec& mover, std::uint64_t ticks) const;
  [[nodiscard]] const std::vector<SweepPoint>& points() const { return points_; }
  [[nodiscard]] std::size_t pending() const { return lengths_.size() - points_.size(); }
  [[nodiscard]] const MoverSpec& mover() const { return mover_; }
  [[nodiscard]] std::uint64_t ticks() const { return ticks_; }
  [[nodiscard]] const std::string& error() const { return error_; }

  /// The window; returns a length the person picked, to apply. `currentLength` is the length
  /// the scene runs with; `byDefault`: it is the default (the parameter reads 0, tile/2).
  std::optional<double> draw(bool* open, double currentLength, bool byDefault);

 private:
  const sim::SceneDef* scene_ = nullptr;
  sim::Params params_;
  MoverSpec mover_;
  std::uint64_t ticks_ = 0;
  std::vector<double> lengths_;
  std::vector<Vec2> exact_;  // every body's position in the continuous run at ticks_
  std::vector<SweepPoint> points_;
  std::string error_;
};

}  // namespace tv::viewer
