#pragma once
/// A recording as a Source: a tv::Replay, the frame on screen, the call selected in it, and the
/// item whose moves are traced. It never computes a collision itself: every trace it shows is
/// the one core filled while the replay re-executed the recorded call. With a mover it is a
/// what-if run: the same recorded calls made again by that mover (open-loop).

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <unordered_map>
#include <vector>

#include "tv/record/replay.hpp"
#include "tv/sim/body.hpp"
#include "tv/sim/scene.hpp"
#include "tv/ui/source.hpp"

namespace tv::ui {

class ReplaySource final : public Source {
 public:
  /// Where a replay's bytes come from, so a what-if run can open them again: a file, or bytes
  /// in memory (a live stream's).
  struct Origin {
    std::string path;                                       ///< a file, or empty
    std::shared_ptr<const std::vector<std::uint8_t>> bytes;  ///< else these
  };

  /// Opens `path` (tv::Error naming the file and what is wrong). The debugger opens what can be
  /// opened: a bad chunk ends the replay there, with a warning.
  [[nodiscard]] static std::unique_ptr<ReplaySource> open(const std::string& path,
                                                          ReplayOptions options = {});
  /// The same from bytes in memory; `name` is what the HUD calls it.
  [[nodiscard]] static std::unique_ptr<ReplaySource> fromBytes(
      std::shared_ptr<const std::vector<std::uint8_t>> bytes, std::string name,
      SourceKind kind = SourceKind::recording, ReplayOptions options = {});
  /// Takes a replay opened elsewhere (tests); shows frame 0.
  ReplaySource(Replay replay, std::string name, Origin origin = {},
               SourceKind kind = SourceKind::recording);

  // -- Source ------------------------------------------------------------------------------------
  [[nodiscard]] SourceKind kind() const override { return kind_; }
  [[nodiscard]] std::string name() const override { return name_; }
  [[nodiscard]] std::string moverName() const override;
  [[nodiscard]] std::unique_ptr<Source> rerun(const MoverSpec& mover) const override;
  [[nodiscard]] bool openLoop() const override { return replay_.options().mover.has_value(); }

  [[nodiscard]] std::uint64_t frame() const override { return frame_; }
  [[nodiscard]] std::uint64_t lastFrame() const override;
  [[nodiscard]] bool ended() const override { return true; }
  void goTo(std::uint64_t f) override;

  [[nodiscard]] std::span<const CallInfo> calls() const override { return calls_; }
  [[nodiscard]] std::optional<std::uint32_t> call() const override { return call_; }
  void selectCall(std::optional<std::uint32_t> k) override;
  [[nodiscard]] bool traces(const CallInfo& c) const override;

  void trace(std::optional<ItemId> item) override;
  [[nodiscard]] std::optional<ItemId> traced() const override { return selected_; }
  [[nodiscard]] std::span<const TracedMove> history() const override { return moves_; }
  [[nodiscard]] const MoveTrace* callTrace() const override;

  [[nodiscard]] const World& world() const override { return replay_.world(); }
  [[nodiscard]] WorldPicture picture() override;
  [[nodiscard]] std::span<const sim::ContactAt> contactEvents() const override {
    return contactEvents_;
  }
  [[nodiscard]] std::optional<Ground> ground(ItemId id) const override;
  [[nodiscard]] bool hasContacts() const override { return sawContacts_; }
  /// The game corrected a corner somewhere in the recording (its nudges are drawn).
  [[nodiscard]] bool hasNudges() const { return hasNudges_; }
  /// Everything in the world at this frame, padded (a default square for an empty world).
  [[nodiscard]] Rect home() const override;
  [[nodiscard]] double followMinSide() const override;

  [[nodiscard]] std::string describe(ItemId id) const override { return replay_.label(id); }
  [[nodiscard]] std::string category(ItemId id) const override {
    return replay_.category(id);
  }
  [[nodiscard]] std::vector<ItemRow> items() const override;
  [[nodiscard]] std::vector<std::string> notes() const override;

  [[nodiscard]] ReplaySource* replay() override { return this; }

  // -- the replay --------------------------------------------------------------------------------
  [[nodiscard]] const Replay& recording() const { return replay_; }
  [[nodiscard]] const Origin& origin() const { return origin_; }
  [[nodiscard]] std::uint64_t frames() const { return replay_.frames(); }
  /// The first divergence in the frame on screen (a call's recorded result differs from what
  /// core returned), if any.
  [[nodiscard]] const std::optional<Divergence>& divergence() const { return divergence_; }
  /// The first divergence among every call replayed to draw this picture — from the keyframe
  /// the world was rebuilt at (or, playing on, since then) up to the frame and call on screen.
  /// When there is one the picture is not (or may not be) what the game got: pictureLabel().
  [[nodiscard]] const std::optional<Divergence>& pictureDivergence() const {
    return pictureDivergence_;
  }
  /// What the picture is labelled with (notes() has it, the world view and the inspector show
  /// it) when it was drawn from a world whose replay diverged: the frame on screen's divergence
  /// if it has one, else the earlier one under it. Empty for a faithful replay.
  [[nodiscard]] std::string pictureLabel() const;
  /// The recorded item with this label, if any (the first, if several share it).
  [[nodiscard]] std::optional<ItemId> findLabel(std::string_view label) const;
  /// True for items that move somewhere in the recording (drawn as bodies); the rest are solids.
  [[nodiscard]] bool moves(ItemId id) const;
  /// The smallest extent of the moving items (else of all), for framing.
  [[nodiscard]] double typicalSize() const;
  /// A what-if re-run with `mover`; `updatesAsMoves` also makes a body's position updates moves.
  [[nodiscard]] std::unique_ptr<ReplaySource> whatIf(const MoverSpec& mover,
                                                     bool updatesAsMoves) const;

 private:
  void rebuild();
  void stepFrame(std::uint64_t f, const std::vector<CallInfo>& calls, std::size_t end);
  void trimHistory();
  void noteContacts(std::uint64_t f, const CallInfo& c);
  /// Replays the recording as it is (not a what-if), so a difference is a divergence.
  [[nodiscard]] bool exact() const { return !replay_.options().mover.has_value(); }

  Replay replay_;
  std::string name_;
  Origin origin_;
  SourceKind kind_;
  std::uint64_t frame_ = 0;
  std::optional<std::uint32_t> call_;
  std::vector<CallInfo> calls_;
  std::optional<ItemId> selected_;
  std::vector<TracedMove> moves_;
  std::vector<sim::CornerNudgeAt> nudges_;  // the picture's: the frame's cornerNudge calls
  // The names the kept traces' `mover` views point into: a trace names its mover by a view of
  // the mover's own name, and a seek rebuilds the replay's movers, so the views would dangle.
  std::set<std::string, std::less<>> moverNames_;
  bool callTraced_ = false;
  bool primed_ = false;  // the replay stands at the end of frame_, nothing selected in it
  std::optional<Divergence> divergence_;
  std::optional<Divergence> pictureDivergence_;
  std::unordered_map<ItemId, std::size_t> recorded_;  // item -> index in replay.items()
  // The picture's storage.
  std::vector<sim::Solid> solids_;
  std::vector<ImU32> bodyFills_;  // per body of the last picture: its category's colour, or 0
  std::string terrain_;           // the category of the level's geometry (drawn as solids)
  bool hasNudges_ = false;        // any item's nudges > 0: read once, the items do not change
  std::vector<sim::Body> bodies_;
  std::size_t history_ = 8;  // frames re-traced before the one on screen
  // The frame on screen's contact events (Contacts::update calls up to the selected call), and
  // whether any such call has been replayed: the legend lists contacts from then on.
  std::vector<sim::ContactAt> contactEvents_;
  bool sawContacts_ = false;
};

}  // namespace tv::ui
