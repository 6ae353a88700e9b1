#pragma once
/// A session: one simulation, the body the debugger follows, and that body's recent moves as
/// core traced them. The viewer and the headless renderer drive it the same way, so a picture
/// from either shows the same ticks.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "tv/geometry.hpp"
#include "tv/mover.hpp"
#include "tv/sim/simulation.hpp"
#include "tv/ui/overlays.hpp"

namespace tv::ui {

class Session {
 public:
  /// Traces body `selected` (if any) from tick 0. Throws tv::Error on a bad scene, parameters,
  /// mover or body index (naming the value).
  Session(const sim::SceneDef& scene, const sim::Params& params, MoverSpec mover,
          std::optional<std::size_t> selected = 0);

  /// One tick of the scene's dt; keeps the selected body's trace. Bodies are then drawn at
  /// their physics state.
  void tick();
  /// One rendered frame of `seconds` through the fixed-step accumulator; returns ticks run.
  /// Bodies are then drawn interpolated at the accumulator's alpha.
  int frame(double seconds);
  /// Runs forward until tick `t`. With `renderHz` > 0 it goes frame by frame at that rate and
  /// stops on the first frame that reaches `t`, so the render position is interpolated as a
  /// game at that refresh rate would draw it; with 0 it ticks (and draws at the physics state).
  /// Throws tv::Error when `t` is behind the current tick, or when frames at `renderHz` run
  /// more than one tick at a time and step over `t` (the session has then advanced past `t`).
  /// With `stopAtEnd` it stops early at the end of a scene that ends before `t`.
  void advanceTo(std::uint64_t t, double renderHz, bool stopAtEnd = false);
  /// Back to tick 0, with new parameters and mover (nothing changes on a throw).
  void restart(const sim::Params& params, MoverSpec mover);

  /// Follows another body (or none); its history starts afresh.
  void select(std::optional<std::size_t> body);
  [[nodiscard]] std::optional<std::size_t> selected() const { return selected_; }

  [[nodiscard]] const sim::Simulation& sim() const { return sim_; }
  [[nodiscard]] sim::Simulation& sim() { return sim_; }
  /// The selected body's last moves, oldest first (at most `historyLength`).
  [[nodiscard]] std::span<const TracedMove> moves() const { return moves_; }
  void setHistoryLength(std::size_t n);
  [[nodiscard]] std::size_t historyLength() const { return history_; }
  /// True after `frame` (render positions are interpolated), false after `tick`.
  [[nodiscard]] bool interpolating() const { return interpolating_; }

  /// The tick at which this session first failed (tunnelled, escaped, overlapped, jittered or
  /// snagged), as seen by tick() and frame(); none while its counts are all 0.
  [[nodiscard]] std::optional<std::uint64_t> firstFailureTick() const { return firstFailure_; }

  /// What the world view draws now (valid until the next call that changes the session).
  [[nodiscard]] WorldPicture picture();

  /// The world rect that frames the selected body's last move (start, goal, end and what it
  /// hit), padded and at least `minSide` on each side; the scene's camera if none.
  [[nodiscard]] Rect followView(double minSide) const;

  /// "body 3", "solid 17": what an item of the world is, for the inspector.
  [[nodiscard]] std::string describe(ItemId id) const;

 private:
  void noteTrace();
  void noteFailure();

  sim::Simulation sim_;
  std::optional<std::size_t> selected_;
  std::vector<TracedMove> moves_;
  std::size_t history_ = 8;
  std::vector<Rect> renderRects_;
  bool interpolating_ = false;
  std::optional<std::uint64_t> firstFailure_;
};

/// Tunnelled + escapes + overlaps + jitter + snags: the counts that mean a mover failed.
[[nodiscard]] std::uint64_t failureCount(const sim::Counters& c);

}  // namespace tv::ui
