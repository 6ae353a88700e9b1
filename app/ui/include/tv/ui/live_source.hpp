#pragma once
/// A game running now, as a Source: the recorder's own chunks streamed to a tv::LiveReceiver
/// (tv/record/live.hpp), shown as they arrive. Underneath it is a recording — the frames the
/// receiver keeps, replayed through core like a file — refreshed as frames come, so everything a
/// recording shows (calls, traces, items, what-ifs) a live game shows too.
///
/// Frames keep their numbers in the run (the first frame the game sent is 0), also after the
/// receiver drops the oldest to stay within its bounds. A game that disconnects and connects
/// again starts a new run: the source starts over with it, and says so.

#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "tv/record/live.hpp"
#include "tv/ui/replay_source.hpp"
#include "tv/ui/source.hpp"

namespace tv::ui {

class LiveSource final : public Source {
 public:
  /// Shows what `receiver` receives (it must outlive this source); `address` is what the HUD
  /// calls it until a game connects.
  explicit LiveSource(std::shared_ptr<LiveReceiver> receiver);

  /// Takes in what arrived since the last call: new frames, drops, a new run, the connection's
  /// news. `newest`: bring the replay up to the newest frame now (following); otherwise the
  /// replay is rebuilt only when its frames no longer hold what is shown (the oldest dropped)
  /// or at most every `kRebuildSeconds`. Returns the connection's news, oldest first.
  std::vector<std::string> refresh(bool newest);
  /// Rebuilding a replay costs its whole window: while following, at most this often.
  static constexpr double kRebuildSeconds = 0.25;

  // -- Source ------------------------------------------------------------------------------------
  [[nodiscard]] SourceKind kind() const override { return SourceKind::live; }
  [[nodiscard]] std::string name() const override;
  [[nodiscard]] std::string moverName() const override { return "recorded"; }
  /// A what-if of the frames kept now (they do not grow with the stream).
  [[nodiscard]] std::unique_ptr<Source> rerun(const MoverSpec& mover) const override;

  [[nodiscard]] std::uint64_t frame() const override;
  [[nodiscard]] std::uint64_t firstFrame() const override;
  /// The newest frame received (the replay may not reach it yet: goTo brings it up).
  [[nodiscard]] std::uint64_t lastFrame() const override;
  /// The game closed its recording or left: nothing more comes in this run.
  [[nodiscard]] bool ended() const override;
  void goTo(std::uint64_t f) override;

  [[nodiscard]] std::span<const CallInfo> calls() const override;
  [[nodiscard]] std::optional<std::uint32_t> call() const override;
  void selectCall(std::optional<std::uint32_t> k) override;
  [[nodiscard]] bool traces(const CallInfo& c) const override;

  void trace(std::optional<ItemId> item) override;
  [[nodiscard]] std::optional<ItemId> traced() const override;
  [[nodiscard]] std::span<const TracedMove> history() const override;
  [[nodiscard]] const MoveTrace* callTrace() const override;

  [[nodiscard]] const World& world() const override;
  [[nodiscard]] WorldPicture picture() override;
  /// The replay's (its Contacts::update calls' events and grounds), as for a recording.
  [[nodiscard]] std::span<const sim::ContactAt> contactEvents() const override {
    return replay_ ? replay_->contactEvents() : std::span<const sim::ContactAt>();
  }
  [[nodiscard]] std::optional<Ground> ground(ItemId id) const override {
    return replay_ ? replay_->ground(id) : std::nullopt;
  }
  [[nodiscard]] bool hasContacts() const override { return replay_ && replay_->hasContacts(); }
  [[nodiscard]] Rect home() const override;
  [[nodiscard]] double followMinSide() const override;

  [[nodiscard]] std::string describe(ItemId id) const override;
  [[nodiscard]] std::string category(ItemId id) const override;
  [[nodiscard]] std::vector<ItemRow> items() const override;
  [[nodiscard]] std::vector<std::string> notes() const override;

  /// The replay of the frames kept (null before a game has sent a keyframe).
  [[nodiscard]] ReplaySource* replay() override { return replay_.get(); }

  // -- the connection ----------------------------------------------------------------------------
  [[nodiscard]] LiveReceiver& receiver() { return *rx_; }
  /// A game is connected now.
  [[nodiscard]] bool connected() const { return window_.connected; }
  /// The connected game accepts pause and step.
  [[nodiscard]] bool controllable() const { return window_.controllable; }
  /// Frames of this run dropped so far to stay within the receiver's bounds.
  [[nodiscard]] std::uint64_t dropped() const { return window_.dropped; }
  /// The run shown (1 for the first game; 0: none yet).
  [[nodiscard]] std::uint64_t run() const { return window_.run; }
  /// Writes the frames kept as a recording (a valid .tvrec); tv::Error when nothing is kept or
  /// the file cannot be written.
  void save(const std::string& path) const;

 private:
  void rebuild();
  [[nodiscard]] std::uint64_t base() const { return base_; }

  std::shared_ptr<LiveReceiver> rx_;
  LiveWindow window_;  // frames left out: only the numbers and the connection
  std::unique_ptr<ReplaySource> replay_;
  std::uint64_t base_ = 0;      // the run's number of the replay's frame 0
  std::uint64_t replayRun_ = 0;
  std::uint64_t built_ = 0;     // the run's frames the replay holds (nextFrame when built)
  std::chrono::steady_clock::time_point builtAt_{};
  std::optional<ItemId> traced_;  // kept across rebuilds
  World empty_{64.0};
  std::vector<std::string> notes_;
};

}  // namespace tv::ui
