#pragma once
// The .tvrec call encoding (FORMAT.md), shared by the recorder and the replay so the two cannot
// drift apart: a Model that both keep in step (the items as the recording says they are, the
// last delta of each, the mover table), the Encoder that turns observer reports into bytes, and
// decodeCall that turns bytes back into a Call, checking everything on the way.

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "bytes.hpp"
#include "tv/batch.hpp"
#include "tv/contact.hpp"
#include "tv/corner.hpp"
#include "tv/mover.hpp"
#include "tv/record/replay.hpp"
#include "tv/world.hpp"

namespace tv::rec {

inline constexpr char kMagic[8] = {'T', 'V', 'R', 'E', 'C', 0, '\r', '\n'};
inline constexpr std::uint16_t kVersionMajor = 1;
// 1.2: the contacts call (kind 15 + varint); 1.3: the cornerNudge call (15 + 1).
inline constexpr std::uint16_t kVersionMinor = 3;
inline constexpr std::size_t kHeaderSize = 32;
inline constexpr std::uint32_t kEndMark = 0x21444E45u;  // "END!": the chunk that closes a file
inline constexpr std::uint32_t kMaxChunk = 1u << 30;
inline constexpr std::size_t kMaxName = 4096;  // labels, categories, response names
inline constexpr std::uint32_t kMaxMovers = 4096;
inline constexpr int kDefaultMaxResponses = 64;
inline constexpr int kDefaultMaxEvents = 4096;

// Kind byte: low 4 bits the CallKind, high bits per-kind flags.
enum : std::uint8_t {
  kSameItem = 0x10,
  kExtras = 0x20,
  kFree = 0x40,      // moves: ended at the goal with no collision
  kMoverDef = 0x80,  // moverMove: the mover's spec follows
  kSkipValid = 0x20,
  kAny = 0x40,
  kAnswers = 0x80,
  kForget = 0x40,  // contacts: Contacts::forget
};
// The kind code that says "the kind is 15 + the varint that follows".
inline constexpr std::uint8_t kExtendedKind = 15;
// Extras byte.
// kBump: the call follows bump.lua's rules (MoveSemantics::bump).
enum : std::uint8_t { kBounds = 1, kLimit = 2, kHasAnswers = 4, kHasLegs = 8, kBump = 16 };

struct Answer {
  ItemId item, other;
  ResponseId response = response::slide;
};

struct BodyOut {
  ItemId item;
  Rect start;
  Vec2 goal, position;
  std::uint32_t first = 0, count = 0;  // its collisions in Call::collisions
};

// One decoded call: every input and recorded result.
struct Call {
  CallKind kind = CallKind::move;
  std::uint64_t offset = 0;
  ItemId item;
  Rect rect;   // add, update (new), project, queryRect, anyOverlap
  Rect start;  // moves and update: the item before the call
  Vec2 goal;   // moves; queryPoint's point; querySegment's a
  Vec2 b;      // querySegment's b
  ItemId skip;
  BroadPhase broad = BroadPhase::swept;
  int maxResponses = kDefaultMaxResponses;
  MoveSemantics semantics = MoveSemantics::tunnelvision;
  Vec2 position;
  std::vector<Collision> collisions;
  std::vector<ItemId> found;
  std::vector<SegmentHit> segment;
  bool any = false;
  std::string name, category;  // addResponse's name; label's label and category
  std::uint32_t mover = 0;
  std::vector<BodyOut> bodies;
  int maxEvents = kDefaultMaxEvents;
  double frameTime = 0.0;
  std::int64_t ticks = 0;
  std::vector<Answer> answers;
  bool answersInOrder = false;
  std::vector<Leg> legs;
  std::vector<ContactEvent> contacts;  // contacts: the events
  bool forget = false;                 // contacts: Contacts::forget
  CornerNudge nudge;                   // cornerNudge: the ceiling, where, dx (hit.item: c.item)
};

struct Model {
  struct Slot {
    Rect rect;
    Vec2 lastDelta;
    std::uint64_t order = 0;
    std::uint32_t generation = 0;
    bool alive = false;
  };
  double cellSize = 64.0;
  std::vector<Slot> slots;
  std::vector<std::uint32_t> freeSlots;
  std::uint64_t nextOrder = 0;
  std::vector<std::string> responses;
  std::uint32_t prevItem = 0;
  Rect prevAdd;
  double prevFrameTime = 0.0;
  std::vector<MoverSpec> movers;   // by id, over the whole file
  std::vector<bool> moverDefined;  // since the last keyframe
  std::uint64_t cells = 0;         // cells the live items are registered in (the budget)
  // The built-in responses the file was written with (4 before version 1.2 added `oneway`): a
  // file's response ids from there on are users', one place further on in this reader's table.
  std::uint16_t fileBuiltins = response::kBuiltinCount;

  [[nodiscard]] std::uint64_t fromFile(std::uint64_t id) const {
    return id < fileBuiltins ? id : id + (response::kBuiltinCount - fileBuiltins);
  }

  void reset(const WorldState& s);
  [[nodiscard]] WorldState state() const;
};

[[nodiscard]] std::uint64_t cellCount(double cellSize, const Rect& r);

// How many built-in responses a file of this minor version was written with.
[[nodiscard]] constexpr std::uint16_t builtinsOf(unsigned minorVersion) {
  return minorVersion < 2 ? 4 : response::kBuiltinCount;
}

class Encoder {
 public:
  Out out;
  Model model;

  void keyframe(const WorldState& s);
  void add(ItemId id, const Rect& r);
  void remove(ItemId id);
  void update(ItemId id, const Rect& r);
  void move(CallKind kind, ItemId id, Vec2 goal, const MoveOptions& o, const MoveResult& r,
            std::span<const Answer> answers, std::span<const Leg> legs);
  void project(const Rect& rect, Vec2 goal, const MoveOptions& o, const MoveResult& r,
               std::span<const Answer> answers, std::span<const Leg> legs);
  void queryRect(const Rect& r, ItemId skip, std::span<const ItemId> found);
  void queryPoint(Vec2 p, std::span<const ItemId> found);
  void querySegment(Vec2 a, Vec2 b, std::span<const SegmentHit> hits);
  void anyOverlap(const Rect& r, ItemId skip, bool any, std::span<const Answer> answers);
  void addResponse(std::string_view name);
  void moverMove(std::uint32_t mover, bool define, const MoverSpec& spec, ItemId id,
                 const Rect& start, Vec2 goal, const MoveResult& r, std::span<const Answer> answers,
                 std::span<const Leg> legs);
  void batch(std::span<const BatchMove> moves, int maxEvents,
             std::span<const BatchOutcome> outcomes, std::span<const Answer> answers,
             std::span<const Leg> legs);
  void label(ItemId id, std::string_view label, std::string_view category);
  void advance(double frameTime, int ticks);
  void contacts(ItemId id, bool forget, std::span<const ContactEvent> events,
                std::span<const Answer> answers);
  void cornerNudge(ItemId id, ItemId ceiling, Vec2 touch, double dx);

 private:
  std::uint8_t item(std::uint32_t index);  // kSameItem or 0, writing the delta if needed
  void collisions(std::span<const Collision> cs, ItemId item, const Rect& start, Vec2 goal);
  void answerBlock(std::span<const Answer> answers, ItemId subject);
  void legBlock(std::span<const Leg> legs);
  void goal(const Model::Slot& s, Vec2 goal);
  void result(Vec2 position, Vec2 goal, const Rect& start, std::span<const Collision> cs,
              ItemId item);
};

// The 32-byte file header (FORMAT.md) of a recording of a world with this cell size.
[[nodiscard]] std::array<std::uint8_t, kHeaderSize> fileHeader(double cellSize,
                                                               std::uint32_t keyframeEvery);

// Reads a keyframe's world state into `s` and resets `m` from it (cell budget checked).
void decodeKeyframe(In& in, Model& m, WorldState& s, std::uint64_t maxCells);
// Reads one call; `in` must not be done.
void decodeCall(In& in, Model& m, Call& c, std::uint64_t maxCells);

// Whether the recorded answers of a call reproduce by pair (the usual case) or only in order.
[[nodiscard]] bool answersByPair(std::span<const Answer> answers);

}  // namespace tv::rec
