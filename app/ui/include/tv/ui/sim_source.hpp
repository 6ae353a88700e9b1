#pragma once
/// A built-in scene or a level file as a Source: one simulation, run by one mover, that the
/// person can tune and re-run. Its frames are ticks; its calls are the moves of the bodies in a
/// tick, in the order the simulation made them.
///
/// Going to tick t restores (or re-runs up to) t - h from the simulation's ring of snapshots and
/// ticks the last h ticks again with tracing on, so the inspector and the history overlay show
/// the moves that led to t however it was reached; determinism makes the re-run identical to
/// the first run.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <utility>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "tv/sim/simulation.hpp"
#include "tv/ui/source.hpp"

namespace tv::ui {

/// A move with more responses than this is listed as a failure of its own (a body stuck
/// bouncing in a corner, a substep patch pushing out of the same wall again and again).
inline constexpr std::size_t kManyResponses = 8;

class SimSource final : public Source {
 public:
  /// At tick 0, tracing `traced` (a body's item) if given. Throws tv::Error on a bad scene,
  /// parameters or mover (naming the value). `kind` is scene or level (a file's scene).
  SimSource(const sim::SceneDef& scene, const sim::Params& params, MoverSpec mover,
            SourceKind kind = SourceKind::scene);

  // -- Source ------------------------------------------------------------------------------------
  [[nodiscard]] SourceKind kind() const override { return kind_; }
  [[nodiscard]] std::string name() const override { return sim_.scene().name; }
  [[nodiscard]] std::string moverName() const override { return sim_.moverSpec().name(); }
  [[nodiscard]] std::unique_ptr<Source> rerun(const MoverSpec& mover) const override;

  [[nodiscard]] std::uint64_t frame() const override { return sim_.ticks(); }
  [[nodiscard]] std::uint64_t lastFrame() const override { return furthest_; }
  [[nodiscard]] bool ended() const override { return sim_.finished(); }
  void goTo(std::uint64_t t) override;
  void play() override;
  [[nodiscard]] double playSeconds() const override;

  [[nodiscard]] std::span<const CallInfo> calls() const override;
  [[nodiscard]] std::optional<std::uint32_t> call() const override { return call_; }
  void selectCall(std::optional<std::uint32_t> k) override;
  [[nodiscard]] bool traces(const CallInfo&) const override { return true; }

  void trace(std::optional<ItemId> item) override;
  [[nodiscard]] std::optional<ItemId> traced() const override;
  [[nodiscard]] std::span<const TracedMove> history() const override { return moves_; }
  [[nodiscard]] const MoveTrace* callTrace() const override;
  [[nodiscard]] std::optional<Failure> failureOf(const TracedMove& m) const override;

  [[nodiscard]] const World& world() const override { return sim_.world(); }
  [[nodiscard]] std::span<const sim::ContactAt> contactEvents() const override {
    return sim_.contactEvents();
  }
  [[nodiscard]] std::optional<Ground> ground(ItemId id) const override;
  [[nodiscard]] bool hasContacts() const override;
  [[nodiscard]] WorldPicture picture() override;
  [[nodiscard]] Rect home() const override { return sim_.camera(); }
  [[nodiscard]] double followMinSide() const override;

  [[nodiscard]] std::string describe(ItemId id) const override;
  [[nodiscard]] std::string category(ItemId id) const override;
  [[nodiscard]] std::vector<ItemRow> items() const override;
  [[nodiscard]] std::vector<std::string> notes() const override { return notes_; }
  void setNotes(std::vector<std::string> notes) { notes_ = std::move(notes); }

  [[nodiscard]] SimSource* sim() override { return this; }

  // -- the simulation ---------------------------------------------------------------------------
  [[nodiscard]] const sim::Simulation& simulation() const { return sim_; }
  [[nodiscard]] sim::Simulation& simulation() { return sim_; }
  /// One tick of the scene's dt, traced; bodies are then drawn at their physics state.
  void tick();
  /// One rendered frame of `seconds` through the fixed-step accumulator; returns the ticks run.
  /// Bodies are then drawn interpolated at the accumulator's alpha.
  int frame(double seconds);
  /// Runs forward until tick `t`. With `renderHz` > 0 it goes frame by frame at that rate and
  /// stops on the first frame that reaches `t` (the render position is interpolated as a game
  /// drawing at that rate would draw it); with 0 it ticks. Throws tv::Error when `t` is behind
  /// the current tick, or when frames at `renderHz` step over it. With `stopAtEnd` it stops
  /// early at the end of a scene that ends before `t`.
  void advanceTo(std::uint64_t t, double renderHz, bool stopAtEnd = false);
  /// Called every 4096 ticks of advanceTo with the tick reached and the one asked for (the
  /// tools say how far a long run has got: TickProgress); empty, nothing is called.
  void setProgress(std::function<void(std::uint64_t reached, std::uint64_t target)> f) {
    progress_ = std::move(f);
  }
  /// Back to tick 0 with new parameters and mover (nothing changes on a throw).
  void restart(const sim::Params& params, MoverSpec mover);

  /// The body traced, if the traced item is one.
  [[nodiscard]] std::optional<std::size_t> tracedBody() const { return body_; }
  /// Traces body `i` (or none); tv::Error naming it when the scene has no such body.
  void traceBody(std::optional<std::size_t> i);
  /// The body whose item this is, if any.
  [[nodiscard]] std::optional<std::size_t> bodyOf(ItemId id) const;

  /// Frames per second playback draws at (0: one frame per tick); physics keeps its own dt.
  [[nodiscard]] double renderHz() const { return renderHz_; }
  void setRenderHz(double hz) { renderHz_ = hz; }
  /// True after frame() (render positions are interpolated), false after tick().
  [[nodiscard]] bool interpolating() const { return interpolating_; }
  /// Moves kept in the history (and ticks re-traced by goTo), >= 1.
  void setHistoryLength(std::size_t n);
  [[nodiscard]] std::size_t historyLength() const { return history_; }
  /// The tick at which this run first failed (tunnelled, escaped, overlapped, jittered or
  /// snagged), as seen while it ran; none while its counts are all 0.
  [[nodiscard]] std::optional<std::uint64_t> firstFailureTick() const { return firstFailure_; }

 private:
  void noteTrace();
  void noteFailure();
  void noteEvents();
  void rememberStart();
  void retrace(std::uint64_t t);
  void indexBodies();

  sim::Simulation sim_;
  SourceKind kind_;
  std::optional<std::size_t> body_;
  std::vector<TracedMove> moves_;
  std::size_t history_ = 8;
  std::vector<Rect> renderRects_;
  bool interpolating_ = false;
  double renderHz_ = 0.0;
  std::optional<std::uint64_t> firstFailure_;
  std::function<void(std::uint64_t, std::uint64_t)> progress_;
  std::uint64_t furthest_ = 0;
  std::optional<std::uint32_t> call_;
  bool callTraced_ = false;
  // Where each body was before the tick on screen (its calls' starts), and those calls, built
  // when asked for.
  std::vector<Rect> starts_;
  std::vector<bool> startedActive_;
  std::uint64_t startsTick_ = ~std::uint64_t{0};
  mutable std::vector<CallInfo> calls_;
  mutable std::uint64_t callsTick_ = ~std::uint64_t{0};
  std::vector<std::string> notes_;
  std::vector<Failure> recent_;  // failures counted in the last ticks run, for the words
  std::vector<std::int32_t> bodyBySlot_;  // world slot -> body index, or -1
};

/// Tunnelled + escapes + overlaps + jitter + snags + drops + pops: the counts that mean a mover
/// failed (squishes do not: a solid pressing a body against a wall should report one).
[[nodiscard]] std::uint64_t failureCount(const sim::Counters& c);

/// "projectile", "walker"...: what a body is in its scene.
[[nodiscard]] const char* roleName(sim::BodyRole r);

}  // namespace tv::ui
