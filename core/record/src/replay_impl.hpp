#pragma once
// Replay's private state, shared by replay.cpp (opening, indexing, listing) and replay_run.cpp
// (seeking, stepping, validating, what-if).

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include "format.hpp"
#include "tv/batch.hpp"
#include "tv/contact.hpp"
#include "tv/record/replay.hpp"

namespace tv {

namespace rec {

// The legs a replayed user response hands back, in order: set by the replay around each call.
struct LegCursor {
  const std::vector<Leg>* legs = nullptr;
  std::size_t next = 0;
  bool overrun = false;
  bool whatIf = false;  // what-if: recorded legs belong to other collisions; slide instead
};

}  // namespace rec

struct FrameInfo {
  std::uint64_t offset = 0;  // payload start in the file
  std::uint32_t size = 0;
  std::uint32_t calls = 0;
  bool keyframe = false;
};

struct Replay::Impl {
  std::vector<std::uint8_t> bytes;
  ReplayOptions options;
  double cellSize = 64.0;
  std::uint32_t keyframeEvery = 64;
  std::vector<FrameInfo> frames;
  std::vector<std::uint64_t> keyframes;
  std::vector<std::string> warnings;
  std::vector<RecordedItem> items;
  std::unordered_map<ItemId, std::size_t> itemIndex;
  std::unordered_map<ItemId, std::pair<std::string, std::string>> labels;
  std::unordered_map<ItemId, ResponseId> commonAnswer;
  std::unordered_set<ItemId> moving;  // items the recording moves or updates
  // Beside `items`, by the same index: whether it moves, and its longest move.
  std::vector<bool> isMoving;
  struct Longest {
    double sq = 0.0;
    Vec2 d;
  };
  std::vector<Longest> longest;
  std::vector<std::uint32_t> slotItem;  // by slot: 1 + the index in `items` of its last item
  ReplaySummary summary;
  bool statefulMovers = false;
  // calls(frame) decodes from the keyframe: the last answer is kept for a UI asking every frame.
  std::optional<std::uint64_t> callsFrame;
  std::vector<CallInfo> callsCache;

  // Where the replay is.
  std::unique_ptr<World> world;
  rec::LegCursor legs;  // the recorded legs of the call being replayed (its user responses')
  rec::Model model;
  std::uint16_t fileBuiltins = response::kBuiltinCount;  // the file's (rec::builtinsOf)
  rec::In in;
  rec::Call call;
  std::uint64_t frame = 0;
  std::uint32_t callIndex = 0;
  std::optional<Divergence> pendingDivergence;  // a keyframe that differs from the world
  bool restoreAtKeyframes = false;  // validate(Tracing::on): go on from each keyframe, as seek
  std::vector<std::unique_ptr<Mover>> movers;  // by recorded mover id
  Batch batch;
  // Contacts::update calls: the replay's own tracker, and the bodies it has updated since the
  // world was last rebuilt (whose begin / persist / end it can check; for the others, only what
  // they touch).
  Contacts contacts;
  std::unordered_set<ItemId> contactsSeen;
  std::vector<Collision> contactsMet;
  std::unique_ptr<Mover> whatIfMover;
  std::vector<ItemId> found;
  std::vector<BatchMove> batchMoves;
  bool cancelled = false;
  WhatIfReport* report = nullptr;  // set while whatIf() runs
  bool classifyRecorded = false;   // set while whatIf()'s first pass runs
  double farAway = 64.0;

  void index();
  bool beginFrame(rec::In& in, rec::Model& m, WorldState& ws, std::uint64_t f);
  std::size_t itemFor(ItemId id, std::uint64_t frame);
  void markMoving(std::size_t k);
  void moveLength(std::size_t k, Vec2 d);
  void tally(
      const rec::Call& c, std::uint64_t f,
      std::unordered_map<ItemId, std::vector<std::pair<ResponseId, std::uint64_t>>>& answers);
  [[nodiscard]] std::string labelOf(ItemId id) const;

  void enterFrame(std::uint64_t f, bool restore);
  void restoreWorld(const WorldState& ws);
  std::optional<Divergence> execute(MoveTrace* trace, bool compare);
  std::optional<Divergence> replayMove(MoveTrace* trace, bool compare, std::uint32_t index);
  std::optional<Divergence> executeOther(MoveTrace* trace, bool compare, std::uint32_t index);
  Mover& recordedMover(std::uint32_t id);
  // The words of a divergence of the current call (the first one set stays).
  void setDivergence(std::optional<Divergence>& out, std::uint32_t index, const std::string& what,
                     const std::string& expected, const std::string& got) const;
  void describeMove(std::optional<Divergence>& out, std::uint32_t index, std::string_view prefix,
                    Vec2 pos, std::span<const Collision> got, Vec2 expPos,
                    std::span<const Collision> exp) const;
  /// A pair the recording never asked about (what-if): the item's most common recorded answer;
  /// for an item with none (a body the game moves itself), other moving bodies are ignored and
  /// everything else slides.
  [[nodiscard]] ResponseId fallbackAnswer(ItemId item, ItemId other) const;
  [[nodiscard]] bool whatIf() const { return options.mover.has_value(); }
};

}  // namespace tv
