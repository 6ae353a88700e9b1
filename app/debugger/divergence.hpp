#pragma once
// Where compared movers part ways. Untraced copies of the session's simulations run ahead of
// the view in lockstep, a few milliseconds per frame, recording every tick's state hash and
// failure counts; the timeline marks the first tick whose hashes differ and the first where
// one mover has tunnelled (or failed otherwise) and another has not. With one mover, the
// first tunnelling. Core needs no help for this: the hash is its determinism promise.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "tv/mover.hpp"
#include "tv/sim/params.hpp"
#include "tv/sim/scene.hpp"
#include "tv/sim/simulation.hpp"

namespace tv::viewer {

class Divergence {
 public:
  /// Ticks looked ahead at most (a minute at 60 Hz).
  static constexpr std::uint64_t kHorizon = 3600;

  Divergence() = default;
  /// Starts again for these movers on this scene (builds the copies: may throw tv::Error).
  void reset(const sim::SceneDef& scene, const sim::Params& params,
             const std::vector<MoverSpec>& movers);
  /// Runs ahead for about `budgetMs` of wall time.
  void advance(double budgetMs);

  /// Ticks known so far (the look-ahead's tick).
  [[nodiscard]] std::uint64_t known() const { return known_; }
  [[nodiscard]] bool done() const { return done_; }
  /// First tick whose state differs between the movers (compare mode only).
  [[nodiscard]] std::optional<std::uint64_t> firstDifference() const { return difference_; }
  /// First tick at which any mover's failure counts (tunnelled, overlaps, escapes, snags,
  /// jitter) exceed the best of the compared movers, or with one mover the first tick with any.
  [[nodiscard]] std::optional<std::uint64_t> firstFailure() const { return failure_; }
  /// What failed first there, e.g. "discrete tunnelled, substep-discrete tunnelled".
  [[nodiscard]] const std::string& failureText() const { return failureText_; }

 private:
  void noteFailures();

  std::vector<std::unique_ptr<sim::Simulation>> sims_;
  std::uint64_t known_ = 0;
  bool done_ = true;
  std::optional<std::uint64_t> difference_, failure_;
  std::string failureText_;
};

}  // namespace tv::viewer
