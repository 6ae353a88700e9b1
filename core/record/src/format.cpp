// Encoding and decoding of calls (FORMAT.md). Each encoder function has its decoder beside it
// in decodeCall, reading the same fields in the same order against the same predictions.

#include "format.hpp"

#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <type_traits>

#include "tv/bump.hpp"

namespace tv::rec {

static_assert(kCallKindCount <= kExtendedKind + 256,
              "a call's kind is the low 4 bits of its first byte, or 15 and a varint");

namespace {

// The kinds below 15 are their code; the others are written with kindBytes.
constexpr std::uint8_t kindOf(CallKind k) {
  return static_cast<std::uint8_t>(k) < kExtendedKind ? static_cast<std::uint8_t>(k)
                                                      : kExtendedKind;
}

// Normals come from a handful of constants; anything else is sent whole.
std::uint8_t normalCode(Vec2 n) {
  if (sameBits(n.x, 0.0) && sameBits(n.y, 0.0)) return 0;
  if (sameBits(n.x, -1.0) && sameBits(n.y, 0.0)) return 1;
  if (sameBits(n.x, 1.0) && sameBits(n.y, 0.0)) return 2;
  if (sameBits(n.x, 0.0) && sameBits(n.y, -1.0)) return 3;
  if (sameBits(n.x, 0.0) && sameBits(n.y, 1.0)) return 4;
  return 5;
}
constexpr Vec2 kNormals[5] = {{0, 0}, {-1, 0}, {1, 0}, {0, -1}, {0, 1}};

// Where a contact puts the item on an axis, from the other's edge (the likely touch).
double contactPrediction(double itemPos, double itemSize, double otherPos, double otherSize,
                         double normal) {
  if (normal < 0) return otherPos - itemSize;
  if (normal > 0) return otherPos + otherSize;
  return itemPos;
}

// Responses with a code of their own in collisions and answers (FORMAT.md): the four built-ins
// that version 1.0 had. Any other id is written out as a varint.
constexpr ResponseId kCodedResponses = 4;

std::uint8_t responseCode(ResponseId r) {
  return r < kCodedResponses ? static_cast<std::uint8_t>(r) : 4;
}

std::uint8_t answerCode(ResponseId r) {
  if (r < kCodedResponses) return static_cast<std::uint8_t>(r);
  return r == response::ignore ? 4 : 5;
}

}  // namespace

std::uint64_t cellCount(double cellSize, const Rect& r) {
  const Grid g(cellSize);
  // Refused by the world itself (and Grid::fits assumes w, h > 0).
  if (!isFinite(r) || !(r.w > 0 && r.h > 0) || !g.fits(r)) return 0;
  const CellRange c = g.cellsOf(r);
  const double n = (static_cast<double>(c.x1 - c.x0) + 1) * (static_cast<double>(c.y1 - c.y0) + 1);
  return n >= 1e18 ? std::uint64_t{1} << 60 : static_cast<std::uint64_t>(n);
}

bool answersByPair(std::span<const Answer> answers) {
  if (answers.size() > 64) return false;  // in order: always right, and cheap to check
  for (std::size_t i = 0; i < answers.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      if (answers[j].item == answers[i].item && answers[j].other == answers[i].other &&
          answers[j].response != answers[i].response) {
        return false;
      }
    }
  }
  return true;
}

std::array<std::uint8_t, kHeaderSize> fileHeader(double cellSize, std::uint32_t keyframeEvery) {
  Out h;
  for (const char c : kMagic) h.u8(static_cast<std::uint8_t>(c));
  h.u8(static_cast<std::uint8_t>(kVersionMajor & 0xFF));
  h.u8(static_cast<std::uint8_t>(kVersionMajor >> 8));
  h.u8(static_cast<std::uint8_t>(kVersionMinor & 0xFF));
  h.u8(static_cast<std::uint8_t>(kVersionMinor >> 8));
  h.f64(cellSize);
  h.u32(keyframeEvery);
  h.u32(0);  // flags, none yet
  h.u32(static_cast<std::uint32_t>(::crc32(0, h.data(), static_cast<uInt>(h.size()))));
  std::array<std::uint8_t, kHeaderSize> out{};
  std::memcpy(out.data(), h.data(), kHeaderSize);
  return out;
}

// [SECTION] model --------------------------------------------------------------------------------

void Model::reset(const WorldState& s) {
  cellSize = s.cellSize;
  slots.assign(s.slots.size(), {});
  cells = 0;
  for (std::size_t i = 0; i < s.slots.size(); ++i) {
    const WorldState::Slot& in = s.slots[i];
    Slot& out = slots[i];
    out.generation = in.generation;
    out.alive = in.alive;
    if (in.alive) {
      out.rect = in.rect;
      out.order = in.order;
      cells += cellCount(cellSize, in.rect);
    }
  }
  freeSlots = s.freeSlots;
  nextOrder = s.nextOrder;
  responses = s.responses;
  prevItem = 0;
  prevAdd = {};
  prevFrameTime = 0.0;
  moverDefined.assign(movers.size(), false);
}

WorldState Model::state() const {
  WorldState s;
  s.cellSize = cellSize;
  s.slots.reserve(slots.size());
  for (const Slot& slot : slots) {
    s.slots.push_back({slot.alive ? slot.rect : Rect{}, slot.alive ? slot.order : 0,
                       slot.generation, slot.alive});
  }
  s.freeSlots = freeSlots;
  s.nextOrder = nextOrder;
  s.responses = responses;
  return s;
}

// [SECTION] encoder -------------------------------------------------------------------------------

std::uint8_t Encoder::item(std::uint32_t index) {
  if (index == model.prevItem) return kSameItem;
  out.zigzag(static_cast<std::int64_t>(index) - static_cast<std::int64_t>(model.prevItem));
  model.prevItem = index;
  return 0;
}

void Encoder::keyframe(const WorldState& s) {
  out.f64(s.cellSize);
  out.varint(s.slots.size());
  out.varint(s.nextOrder);
  out.varint(s.responses.size());
  for (const std::string& r : s.responses) out.str(r);
  Rect prev;
  std::uint64_t prevOrder = 0;
  for (const WorldState::Slot& slot : s.slots) {
    out.u8(static_cast<std::uint8_t>((slot.alive ? 1 : 0) | (slot.generation != 0 ? 2 : 0)));
    if (slot.generation != 0) out.varint(slot.generation);
    if (!slot.alive) continue;
    out.zigzag(static_cast<std::int64_t>(slot.order - prevOrder));
    prevOrder = slot.order;
    Group g(out);
    g.put(slot.rect.x, prev.x + prev.w, prev.x);
    g.put(slot.rect.y, prev.y, prev.y + prev.h);
    g.put(slot.rect.w, prev.w, prev.h);
    g.put(slot.rect.h, prev.h, prev.w);
    prev = slot.rect;
  }
  out.varint(s.freeSlots.size());
  for (const std::uint32_t f : s.freeSlots) out.varint(f);
  model.reset(s);
}

void Encoder::add(ItemId, const Rect& r) {
  out.u8(kindOf(CallKind::add));
  const Rect p = model.prevAdd;
  Group g(out);
  g.put(r.x, p.x + p.w, p.x);
  g.put(r.y, p.y, p.y + p.h);
  g.put(r.w, p.w, p.h);
  g.put(r.h, p.h, p.w);
  std::uint32_t index;
  if (!model.freeSlots.empty()) {
    index = model.freeSlots.back();
    model.freeSlots.pop_back();
  } else {
    index = static_cast<std::uint32_t>(model.slots.size());
    model.slots.emplace_back();
  }
  Model::Slot& s = model.slots[index];
  s.rect = r;
  s.alive = true;
  s.order = model.nextOrder++;
  s.lastDelta = {};
  model.prevAdd = r;
  model.prevItem = index;
  model.cells += cellCount(model.cellSize, r);
}

void Encoder::remove(ItemId id) {
  const std::size_t at = out.size();
  out.u8(kindOf(CallKind::remove));
  out.at(at) |= item(id.index);
  Model::Slot& s = model.slots[id.index];
  model.cells -= std::min(model.cells, cellCount(model.cellSize, s.rect));
  s.alive = false;
  ++s.generation;
  model.freeSlots.push_back(id.index);
}

void Encoder::update(ItemId id, const Rect& r) {
  const std::size_t at = out.size();
  out.u8(kindOf(CallKind::update));
  out.at(at) |= item(id.index);
  Model::Slot& s = model.slots[id.index];
  Group g(out);
  g.put(r.x, s.rect.x + s.lastDelta.x, s.rect.x, s.rect.x);
  g.put(r.y, s.rect.y + s.lastDelta.y, s.rect.y, s.rect.y);
  g.put(r.w, s.rect.w, s.rect.h);
  g.put(r.h, s.rect.h, s.rect.w);
  const Vec2 d = r.position() - s.rect.position();
  if (d != Vec2{} && sameBits(s.rect.x + d.x, r.x) && sameBits(s.rect.y + d.y, r.y)) {
    s.lastDelta = d;
  }
  model.cells -= std::min(model.cells, cellCount(model.cellSize, s.rect));
  model.cells += cellCount(model.cellSize, r);
  s.rect = r;
}

void Encoder::goal(const Model::Slot& s, Vec2 goal) {
  Group g(out);
  g.put(goal.x, s.rect.x + s.lastDelta.x, s.rect.x, s.rect.x);
  g.put(goal.y, s.rect.y + s.lastDelta.y, s.rect.y, s.rect.y);
}

void Encoder::collisions(std::span<const Collision> cs, ItemId self, const Rect& start, Vec2 goal) {
  const std::uint32_t ref = self.valid() ? self.index : 0;
  Vec2 legStart = start.position(), legGoal = goal;
  Rect prevItem = start, prevOther;
  double prevTi = 0.0;
  for (const Collision& c : cs) {
    out.zigzag(static_cast<std::int64_t>(c.other.index) - static_cast<std::int64_t>(ref));
    const std::uint8_t nc = normalCode(c.normal);
    const std::uint8_t rc = responseCode(c.response);
    out.u8(static_cast<std::uint8_t>((c.overlaps ? 1 : 0) | (c.corner ? 2 : 0) | (nc << 2) |
                                     (rc << 5)));
    if (rc == 4) out.varint(c.response);
    if (nc == 5) {
      Group g(out);
      g.put(c.normal.x, 0, 1);
      g.put(c.normal.y, 0, 1);
    }
    {
      Group g(out);
      g.put(c.itemRect.x, legStart.x, prevItem.x);
      g.put(c.itemRect.y, legStart.y, prevItem.y);
      g.put(c.itemRect.w, start.w, start.h);
      g.put(c.itemRect.h, start.h, start.w);
    }
    {
      Group g(out);
      g.put(c.move.x, legGoal.x - c.itemRect.x, 0.0);
      g.put(c.move.y, legGoal.y - c.itemRect.y, 0.0);
      g.put(c.ti, 0.0, prevTi);
    }
    {
      const Rect m = c.other.index < model.slots.size() ? model.slots[c.other.index].rect : Rect{};
      Group g(out);
      g.put(c.otherRect.x, m.x, prevOther.x);
      g.put(c.otherRect.y, m.y, prevOther.y);
      g.put(c.otherRect.w, m.w, prevOther.w);
      g.put(c.otherRect.h, m.h, prevOther.h);
    }
    {
      const Rect& i = c.itemRect;
      const Rect& o = c.otherRect;
      Group g(out);
      g.put(c.touch.x, i.x, contactPrediction(i.x, i.w, o.x, o.w, c.normal.x), i.x);
      g.put(c.touch.y, i.y, contactPrediction(i.y, i.h, o.y, o.h, c.normal.y), i.y);
      g.put(c.target.x, c.touch.x, legGoal.x, c.touch.x);
      g.put(c.target.y, c.touch.y, legGoal.y, c.touch.y);
    }
    legStart = c.touch;
    legGoal = c.target;
    prevItem = c.itemRect;
    prevOther = c.otherRect;
    prevTi = c.ti;
  }
}

void Encoder::result(Vec2 position, Vec2 goal, const Rect& start, std::span<const Collision> cs,
                     ItemId self) {
  Group g(out);
  g.put(position.x, goal.x, start.x, start.x);
  g.put(position.y, goal.y, start.y, start.y);
  out.varint(cs.size());
  collisions(cs, self, start, goal);
}

void Encoder::answerBlock(std::span<const Answer> answers, ItemId subject) {
  const bool byPair = answersByPair(answers);
  // By pair, each pair once (answersByPair checked that repeats agree).
  const auto repeat = [&](std::size_t i) {
    if (!byPair) return false;
    for (std::size_t j = 0; j < i; ++j) {
      if (answers[j].item == answers[i].item && answers[j].other == answers[i].other) return true;
    }
    return false;
  };
  std::uint64_t n = 0;
  for (std::size_t i = 0; i < answers.size(); ++i) {
    if (!repeat(i)) ++n;
  }
  out.varint((n << 1) | (byPair ? 0 : 1));
  for (std::size_t i = 0; i < answers.size(); ++i) {
    const Answer& a = answers[i];
    if (repeat(i)) continue;
    const std::uint8_t code = answerCode(a.response);
    const bool explicitItem = a.item != subject;
    out.u8(static_cast<std::uint8_t>(code | (explicitItem ? 8 : 0)));
    if (code == 5) out.varint(a.response);
    if (explicitItem) out.varint(a.item.valid() ? std::uint64_t{a.item.index} + 1 : 0);
    const std::int64_t base = a.item.valid() ? a.item.index : 0;
    out.zigzag(static_cast<std::int64_t>(a.other.index) - base);
  }
}

void Encoder::legBlock(std::span<const Leg> legs) {
  out.varint(legs.size());
  Leg prev;
  for (const Leg& l : legs) {
    out.u8(static_cast<std::uint8_t>((l.passThrough ? 1 : 0) | (l.stop ? 2 : 0)));
    Group g(out);
    g.put(l.start.x, prev.goal.x, prev.start.x);
    g.put(l.start.y, prev.goal.y, prev.start.y);
    g.put(l.goal.x, l.start.x, prev.goal.x, l.start.x);
    g.put(l.goal.y, l.start.y, prev.goal.y, l.start.y);
    prev = l;
  }
}

void Encoder::move(CallKind kind, ItemId id, Vec2 goalPos, const MoveOptions& o,
                   const MoveResult& r, std::span<const Answer> answers,
                   std::span<const Leg> legs) {
  const std::size_t at = out.size();
  out.u8(kindOf(kind));
  std::uint8_t flags = item(id.index);
  std::uint8_t extras = static_cast<std::uint8_t>(
      (o.broad == BroadPhase::bounds ? kBounds : 0) |
      (o.semantics == MoveSemantics::bump ? kBump : 0) |
      (o.maxResponses != kDefaultMaxResponses ? kLimit : 0) | (!answers.empty() ? kHasAnswers : 0) |
      (!legs.empty() ? kHasLegs : 0));
  Model::Slot& s = model.slots[id.index];
  const Rect start = s.rect;
  const bool free = r.collisions.empty() && r.position == goalPos &&
                    sameBits(r.position.x, goalPos.x) && sameBits(r.position.y, goalPos.y);
  if (extras) {
    flags |= kExtras;
    out.u8(extras);
    if (extras & kLimit) out.varint(static_cast<std::uint64_t>(o.maxResponses));
  }
  if (free) flags |= kFree;
  out.at(at) |= flags;
  goal(s, goalPos);
  const Vec2 d = goalPos - start.position();
  if (sameBits(start.x + d.x, goalPos.x) && sameBits(start.y + d.y, goalPos.y)) s.lastDelta = d;
  if (!free) result(r.position, goalPos, start, r.collisions, id);
  if (extras & kHasAnswers) answerBlock(answers, id);
  if (extras & kHasLegs) legBlock(legs);
  if (kind == CallKind::move) s.rect = s.rect.at(r.position);
}

void Encoder::moverMove(std::uint32_t mover, bool define, const MoverSpec& spec, ItemId id,
                        const Rect& start, Vec2 goalPos, const MoveResult& r,
                        std::span<const Answer> answers, std::span<const Leg> legs) {
  const std::size_t at = out.size();
  out.u8(kindOf(CallKind::moverMove));
  std::uint8_t flags = item(id.index);
  out.varint(mover);
  if (define) {
    flags |= kMoverDef;
    out.u8(static_cast<std::uint8_t>(spec.kind));
    out.u8(static_cast<std::uint8_t>(spec.inner));
    out.f64(spec.maxStep);
    out.f64(spec.safetyFraction);
  }
  const std::uint8_t extras = static_cast<std::uint8_t>((!answers.empty() ? kHasAnswers : 0) |
                                                        (!legs.empty() ? kHasLegs : 0));
  if (extras) {
    flags |= kExtras;
    out.u8(extras);
  }
  const bool free = r.collisions.empty() && sameBits(r.position.x, goalPos.x) &&
                    sameBits(r.position.y, goalPos.y);
  if (free) flags |= kFree;
  out.at(at) |= flags;
  Model::Slot& s = model.slots[id.index];
  (void)start;  // the model holds it (the recorder checks they agree)
  goal(s, goalPos);
  const Vec2 d = goalPos - s.rect.position();
  if (sameBits(s.rect.x + d.x, goalPos.x) && sameBits(s.rect.y + d.y, goalPos.y)) s.lastDelta = d;
  if (!free) result(r.position, goalPos, s.rect, r.collisions, id);
  if (extras & kHasAnswers) answerBlock(answers, id);
  if (extras & kHasLegs) legBlock(legs);
  s.rect = s.rect.at(r.position);
}

void Encoder::project(const Rect& rect, Vec2 goalPos, const MoveOptions& o, const MoveResult& r,
                      std::span<const Answer> answers, std::span<const Leg> legs) {
  const std::size_t at = out.size();
  out.u8(kindOf(CallKind::project));
  std::uint8_t flags = 0;
  const std::uint8_t extras = static_cast<std::uint8_t>(
      (o.broad == BroadPhase::bounds ? kBounds : 0) |
      (o.semantics == MoveSemantics::bump ? kBump : 0) |
      (o.maxResponses != kDefaultMaxResponses ? kLimit : 0) | (!answers.empty() ? kHasAnswers : 0) |
      (!legs.empty() ? kHasLegs : 0));
  if (extras) {
    flags |= kExtras;
    out.u8(extras);
    if (extras & kLimit) out.varint(static_cast<std::uint64_t>(o.maxResponses));
  }
  const bool free = r.collisions.empty() && sameBits(r.position.x, goalPos.x) &&
                    sameBits(r.position.y, goalPos.y);
  if (free) flags |= kFree;
  out.at(at) |= flags;
  {
    Group g(out);
    g.put(rect.x, 0, 0);
    g.put(rect.y, 0, 0);
    g.put(rect.w, 0, 0);
    g.put(rect.h, 0, rect.w);
  }
  {
    Group g(out);
    g.put(goalPos.x, rect.x, 0, rect.x);
    g.put(goalPos.y, rect.y, 0, rect.y);
  }
  if (!free) result(r.position, goalPos, rect, r.collisions, {});
  if (extras & kHasAnswers) answerBlock(answers, {});
  if (extras & kHasLegs) legBlock(legs);
}

namespace {
void foundList(Out& out, std::span<const ItemId> found, std::uint32_t base) {
  out.varint(found.size());
  std::int64_t prev = base;
  for (const ItemId f : found) {
    out.zigzag(static_cast<std::int64_t>(f.index) - prev);
    prev = f.index;
  }
}
}  // namespace

void Encoder::queryRect(const Rect& r, ItemId skip, std::span<const ItemId> found) {
  const std::size_t at = out.size();
  out.u8(kindOf(CallKind::queryRect));
  Rect p;
  if (skip.valid()) {
    out.at(at) |= static_cast<std::uint8_t>(kSkipValid | item(skip.index));
    p = model.slots[skip.index].rect;
  }
  Group g(out);
  g.put(r.x, p.x, 0);
  g.put(r.y, p.y, 0);
  g.put(r.w, p.w, 0);
  g.put(r.h, p.h, r.w);
  foundList(out, found, skip.valid() ? skip.index : 0);
}

void Encoder::queryPoint(Vec2 p, std::span<const ItemId> found) {
  out.u8(kindOf(CallKind::queryPoint));
  Group g(out);
  g.put(p.x, 0, 0);
  g.put(p.y, 0, 0);
  foundList(out, found, 0);
}

void Encoder::querySegment(Vec2 a, Vec2 b, std::span<const SegmentHit> hits) {
  out.u8(kindOf(CallKind::querySegment));
  {
    Group g(out);
    g.put(a.x, 0, 0);
    g.put(a.y, 0, 0);
    g.put(b.x, a.x, 0, a.x);
    g.put(b.y, a.y, 0, a.y);
  }
  out.varint(hits.size());
  std::int64_t prev = 0;
  for (const SegmentHit& h : hits) {
    out.zigzag(static_cast<std::int64_t>(h.item.index) - prev);
    prev = h.item.index;
    Group g(out);
    g.put(h.t0, 0.0, 1.0);
    g.put(h.t1, 1.0, 0.0);
    g.put(h.entry.x, a.x, b.x);
    g.put(h.entry.y, a.y, b.y);
    Group e(out);
    e.put(h.exit.x, b.x, h.entry.x);
    e.put(h.exit.y, b.y, h.entry.y);
  }
}

void Encoder::anyOverlap(const Rect& r, ItemId skip, bool any, std::span<const Answer> answers) {
  const std::size_t at = out.size();
  out.u8(kindOf(CallKind::anyOverlap));
  Rect p;
  std::uint8_t flags =
      static_cast<std::uint8_t>((any ? kAny : 0) | (answers.empty() ? 0 : kAnswers));
  if (skip.valid()) {
    flags |= static_cast<std::uint8_t>(kSkipValid | item(skip.index));
    p = model.slots[skip.index].rect;
  }
  out.at(at) |= flags;
  Group g(out);
  g.put(r.x, p.x, 0);
  g.put(r.y, p.y, 0);
  g.put(r.w, p.w, 0);
  g.put(r.h, p.h, r.w);
  if (!answers.empty()) answerBlock(answers, skip);
}

void Encoder::addResponse(std::string_view name) {
  out.u8(kindOf(CallKind::addResponse));
  out.str(name);
  model.responses.emplace_back(name);
}

void Encoder::batch(std::span<const BatchMove> moves, int maxEvents,
                    std::span<const BatchOutcome> outcomes, std::span<const Answer> answers,
                    std::span<const Leg> legs) {
  const std::size_t at = out.size();
  out.u8(kindOf(CallKind::batchStep));
  const std::uint8_t extras = static_cast<std::uint8_t>(
      (maxEvents != kDefaultMaxEvents ? kLimit : 0) | (!answers.empty() ? kHasAnswers : 0) |
      (!legs.empty() ? kHasLegs : 0));
  if (extras) {
    out.at(at) |= kExtras;
    out.u8(extras);
    if (extras & kLimit) out.varint(static_cast<std::uint64_t>(maxEvents));
  }
  out.varint(moves.size());
  for (const BatchMove& m : moves) {
    out.zigzag(static_cast<std::int64_t>(m.item.index) - static_cast<std::int64_t>(model.prevItem));
    model.prevItem = m.item.index;
    Model::Slot& s = model.slots[m.item.index];
    goal(s, m.goal);
    const Vec2 d = m.goal - s.rect.position();
    if (sameBits(s.rect.x + d.x, m.goal.x) && sameBits(s.rect.y + d.y, m.goal.y)) s.lastDelta = d;
  }
  for (std::size_t i = 0; i < moves.size(); ++i) {
    const BatchOutcome& o = outcomes[i];
    result(o.position, moves[i].goal, model.slots[moves[i].item.index].rect, o.collisions,
           moves[i].item);
  }
  if (extras & kHasAnswers) answerBlock(answers, {});
  if (extras & kHasLegs) legBlock(legs);
  for (std::size_t i = 0; i < moves.size(); ++i) {
    Model::Slot& s = model.slots[moves[i].item.index];
    s.rect = s.rect.at(outcomes[i].position);
  }
}

void Encoder::label(ItemId id, std::string_view label, std::string_view category) {
  out.u8(kindOf(CallKind::label));
  out.varint(id.index);
  out.varint(id.generation);
  out.str(label.substr(0, kMaxName));
  out.str(category.substr(0, kMaxName));
}

void Encoder::advance(double frameTime, int ticks) {
  out.u8(kindOf(CallKind::advance));
  Group g(out);
  g.put(frameTime, model.prevFrameTime, 0.0);
  model.prevFrameTime = frameTime;
  out.varint(static_cast<std::uint64_t>(ticks));
}

void Encoder::contacts(ItemId id, bool forget, std::span<const ContactEvent> events,
                       std::span<const Answer> answers) {
  const std::size_t at = out.size();
  out.u8(kindOf(CallKind::contacts));
  out.varint(static_cast<std::uint64_t>(CallKind::contacts) - kExtendedKind);
  std::uint8_t flags = static_cast<std::uint8_t>(answers.empty() ? 0 : kAnswers);
  if (forget) {
    // The body may have left the world: named in full, as a label's item is.
    flags |= kForget;
    out.varint(id.index);
    out.varint(id.generation);
  } else {
    flags |= item(id.index);
  }
  out.at(at) |= flags;
  out.varint(events.size());
  for (const ContactEvent& e : events) {
    const bool alive = e.other.index < model.slots.size() && model.slots[e.other.index].alive &&
                       model.slots[e.other.index].generation == e.other.generation;
    const std::uint8_t nc = normalCode(e.normal);
    out.u8(static_cast<std::uint8_t>(static_cast<std::uint8_t>(e.phase) | (e.met ? 4 : 0) |
                                     (nc << 3) | (alive ? 0 : 0x40)));
    out.zigzag(static_cast<std::int64_t>(e.other.index) - static_cast<std::int64_t>(id.index));
    if (!alive) out.varint(e.other.generation);
    if (nc == 5) {
      Group g(out);
      g.put(e.normal.x, 0, 1);
      g.put(e.normal.y, 0, 1);
    }
  }
  if (!answers.empty()) answerBlock(answers, id);
}

void Encoder::cornerNudge(ItemId id, ItemId ceiling, Vec2 touch, double dx) {
  const std::size_t at = out.size();
  out.u8(kindOf(CallKind::cornerNudge));
  out.varint(static_cast<std::uint64_t>(CallKind::cornerNudge) - kExtendedKind);
  out.at(at) |= item(id.index);
  out.zigzag(static_cast<std::int64_t>(ceiling.index) - static_cast<std::int64_t>(id.index));
  // A ceiling's touch lies on its bottom edge, and its x mostly just past one of its ends.
  const Rect& c = model.slots[ceiling.index].rect;
  Group g(out);
  g.put(touch.y, c.bottom(), c.y);
  g.put(touch.x, c.x, c.right(), c.x);
  g.put(dx, 0.0, 0.0);
}

// [SECTION] decoder ------------------------------------------------------------------------------

namespace {

[[noreturn, gnu::cold, gnu::noinline]] void failAlive(In& in, const Model& m, std::int64_t index,
                                                      std::string_view what) {
  if (index < 0 || static_cast<std::uint64_t>(index) >= m.slots.size()) {
    in.fail(std::string(what) + ": item index " + std::to_string(index) +
            " was never issued (the world has " + std::to_string(m.slots.size()) + " slots)");
  }
  const Model::Slot& s = m.slots[static_cast<std::size_t>(index)];
  in.fail(std::string(what) + ": item " + std::to_string(index) + "." +
          std::to_string(s.generation) + " is not in the world (removed or never added)");
}

[[gnu::always_inline]] inline ItemId aliveAt(In& in, const Model& m, std::int64_t index,
                                             std::string_view what) {
  if (index < 0 || static_cast<std::uint64_t>(index) >= m.slots.size() ||
      !m.slots[static_cast<std::size_t>(index)].alive) [[unlikely]] {
    failAlive(in, m, index, what);
  }
  return {static_cast<std::uint32_t>(index), m.slots[static_cast<std::size_t>(index)].generation};
}

[[gnu::always_inline]] inline ItemId readItem(In& in, Model& m, std::uint8_t kindByte,
                                              std::string_view what) {
  std::int64_t index = m.prevItem;
  if (!(kindByte & kSameItem)) index += in.zigzag(what);
  const ItemId id = aliveAt(in, m, index, what);
  m.prevItem = id.index;
  return id;
}

void requireBudget(In& in, const Model& m, std::uint64_t extra, std::uint64_t maxCells,
                   std::string_view what) {
  if (m.cells + extra > maxCells) {
    in.fail(std::string(what) + " would register " + std::to_string(m.cells + extra) +
            " cells, more than the replay's budget of " + std::to_string(maxCells) +
            " (ReplayOptions::maxCells)");
  }
}

// A replayed call costs time in proportion to the cells it visits: refuse, as hostile, a call
// that would visit more cells than the budget allows (a move of 10^15 px, a query over the
// whole plane), instead of replaying it for hours.
[[noreturn, gnu::cold, gnu::noinline]] void failReach(In& in, std::uint64_t at, double cells,
                                                      std::uint64_t maxCells,
                                                      std::string_view what) {
  in.failAt(at, std::string(what) + " would visit about " + formatNumber(std::floor(cells)) +
                    " cells, more than the replay's budget of " + std::to_string(maxCells) +
                    " (ReplayOptions::maxCells)");
}

// `what`: a name, or the CallKind whose name it is (looked up only for the message).
template <class What>
[[gnu::always_inline]] inline void requireReach(In& in, const Model& m, std::uint64_t at,
                                                const Rect& r, Vec2 goal, bool wholeHull,
                                                std::uint64_t maxCells, What what) {
  const double c = m.cellSize;
  const double budget = static_cast<double>(maxCells);
  // Most moves span a few cells: an estimate by the reciprocal (no division) clears them; one
  // near the budget is decided exactly as always.
  {
    const double k = 1.0 / c;
    const double dx = std::fabs(goal.x - r.x) * k, dy = std::fabs(goal.y - r.y) * k;
    const double w = r.w * k + 2, h = r.h * k + 2;
    const double cells = wholeHull ? (dx + w) * (dy + h) : (dx + dy + 1) * std::max(w, h);
    if (cells <= budget * 0.5) [[likely]]
      return;
  }
  const double dx = std::fabs(goal.x - r.x) / c, dy = std::fabs(goal.y - r.y) / c;
  const double w = r.w / c + 2, h = r.h / c + 2;
  const double cells = wholeHull ? (dx + w) * (dy + h) : (dx + dy + 1) * std::max(w, h);
  if (!(cells <= budget)) {
    if constexpr (std::is_same_v<What, CallKind>) {
      failReach(in, at, cells, maxCells, callKindName(what));
    } else {
      failReach(in, at, cells, maxCells, what);
    }
  }
}

[[gnu::always_inline]] inline Vec2 readGoal(In& in, const Model::Slot& s, std::string_view what) {
  GroupIn g(in, what);
  const double x = g.get(s.rect.x + s.lastDelta.x, s.rect.x, s.rect.x);
  const double y = g.get(s.rect.y + s.lastDelta.y, s.rect.y, s.rect.y);
  return {x, y};
}

void readCollisions(In& in, Model& m, Call& c, std::size_t n, ItemId self, const Rect& start,
                    Vec2 goal) {
  const std::int64_t ref = self.valid() ? self.index : 0;
  Vec2 legStart = start.position(), legGoal = goal;
  Rect prevItem = start, prevOther;
  double prevTi = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    Collision col;
    col.item = self;
    col.other = aliveAt(in, m, ref + in.zigzag("collision other"), "collision other");
    if (self.valid() && col.other.index == self.index)
      in.fail("a collision of an item with itself");
    const std::uint8_t flags = in.u8("collision flags");
    col.overlaps = flags & 1;
    col.corner = flags & 2;
    const std::uint8_t nc = (flags >> 2) & 7;
    const std::uint8_t rc = static_cast<std::uint8_t>(flags >> 5);
    if (nc > 5) in.fail("normal code " + std::to_string(nc) + " is not defined");
    if (rc > 4) in.fail("response code " + std::to_string(rc) + " is not defined");
    if (rc < 4) {
      col.response = rc;
    } else {
      const std::uint64_t r = in.varint("collision response");
      if (r < kCodedResponses || m.fromFile(r) >= m.responses.size()) {
        in.fail("collision response " + std::to_string(r) + " is not registered");
      }
      col.response = static_cast<ResponseId>(m.fromFile(r));
    }
    if (col.response >= m.responses.size()) {
      in.fail("collision response " + std::to_string(col.response) + " is not registered");
    }
    if (nc == 5) {
      GroupIn g(in, "collision normal");
      col.normal.x = g.get(0, 1);
      col.normal.y = g.get(0, 1);
    } else {
      col.normal = kNormals[nc];
    }
    {
      GroupIn g(in, "collision itemRect");
      col.itemRect.x = g.get(legStart.x, prevItem.x);
      col.itemRect.y = g.get(legStart.y, prevItem.y);
      col.itemRect.w = g.get(start.w, start.h);
      col.itemRect.h = g.get(start.h, start.w);
    }
    {
      GroupIn g(in, "collision move/ti");
      col.move.x = g.get(legGoal.x - col.itemRect.x, 0.0);
      col.move.y = g.get(legGoal.y - col.itemRect.y, 0.0);
      col.ti = g.get(0.0, prevTi);
    }
    // bump's rules take a hit up to its margin behind the start (a resting contact).
    const double earliest = c.semantics == MoveSemantics::bump ? -bump::kDelta : 0.0;
    if (!col.overlaps && !(col.ti >= earliest && col.ti <= 1.0)) {
      in.fail("collision ti " + formatNumber(col.ti) + " is outside [" + formatNumber(earliest) +
              ", 1] for a hit that does not overlap");
    }
    {
      const Rect o = m.slots[col.other.index].rect;
      GroupIn g(in, "collision otherRect");
      col.otherRect.x = g.get(o.x, prevOther.x);
      col.otherRect.y = g.get(o.y, prevOther.y);
      col.otherRect.w = g.get(o.w, prevOther.w);
      col.otherRect.h = g.get(o.h, prevOther.h);
    }
    {
      const Rect& i = col.itemRect;
      const Rect& o = col.otherRect;
      GroupIn g(in, "collision touch/target");
      col.touch.x = g.get(i.x, contactPrediction(i.x, i.w, o.x, o.w, col.normal.x), i.x);
      col.touch.y = g.get(i.y, contactPrediction(i.y, i.h, o.y, o.h, col.normal.y), i.y);
      col.target.x = g.get(col.touch.x, legGoal.x, col.touch.x);
      col.target.y = g.get(col.touch.y, legGoal.y, col.touch.y);
    }
    legStart = col.touch;
    legGoal = col.target;
    prevItem = col.itemRect;
    prevOther = col.otherRect;
    prevTi = col.ti;
    c.collisions.push_back(col);
  }
}

// Collisions take at least 6 bytes each (other, flags, four code bytes).
constexpr std::size_t kMinCollision = 6;

void readResult(In& in, Model& m, Call& c, ItemId self, const Rect& start, Vec2 goal,
                Vec2& position) {
  GroupIn g(in, "result position");
  position.x = g.get(goal.x, start.x, start.x);
  position.y = g.get(goal.y, start.y, start.y);
  const std::size_t n = in.count("collision count", kMinCollision);
  readCollisions(in, m, c, n, self, start, goal);
}

void readAnswers(In& in, Model& m, Call& c, ItemId subject) {
  const std::uint64_t at = in.offset();
  const std::uint64_t header = in.varint("answer count");
  const std::uint64_t n = header >> 1;
  c.answersInOrder = header & 1;
  if (n > in.left() / 2) {
    in.failAt(at, "answer count " + std::to_string(n) + " is more than the chunk can hold");
  }
  for (std::uint64_t k = 0; k < n; ++k) {
    const std::uint8_t code = in.u8("answer");
    if ((code & 0xF0) != 0 || (code & 7) > 5)
      in.fail("answer code " + std::to_string(code) + " is not defined");
    Answer a;
    switch (code & 7) {
      case 4:
        a.response = response::ignore;
        break;
      case 5: {
        const std::uint64_t r = in.varint("answer response");
        if (r < kCodedResponses || m.fromFile(r) >= m.responses.size()) {
          in.fail("answer response " + std::to_string(r) + " is not registered");
        }
        a.response = static_cast<ResponseId>(m.fromFile(r));
        break;
      }
      default:
        a.response = static_cast<ResponseId>(code & 7);
    }
    a.item = subject;
    if (code & 8) {
      const std::uint64_t v = in.varint("answer item");
      a.item = v == 0
                   ? ItemId{}
                   : aliveAt(in, m,
                             static_cast<std::int64_t>(std::min<std::uint64_t>(v - 1, 1ull << 40)),
                             "answer item");
    }
    const std::int64_t base = a.item.valid() ? a.item.index : 0;
    a.other = aliveAt(in, m, base + in.zigzag("answer other"), "answer other");
    c.answers.push_back(a);
  }
}

void readLegs(In& in, Call& c) {
  const std::size_t n = in.count("leg count", 2);
  Leg prev;
  for (std::size_t k = 0; k < n; ++k) {
    Leg l;
    const std::uint8_t f = in.u8("leg flags");
    if (f > 3) in.fail("leg flags " + std::to_string(f) + " are not defined");
    l.passThrough = f & 1;
    l.stop = f & 2;
    GroupIn g(in, "leg");
    l.start.x = g.get(prev.goal.x, prev.start.x);
    l.start.y = g.get(prev.goal.y, prev.start.y);
    l.goal.x = g.get(l.start.x, prev.goal.x, l.start.x);
    l.goal.y = g.get(l.start.y, prev.goal.y, l.start.y);
    c.legs.push_back(l);
    prev = l;
  }
}

std::uint8_t readExtras(In& in, std::uint8_t allowed) {
  const std::uint8_t e = in.u8("extras");
  if (e & ~allowed) in.fail("extras byte " + std::to_string(e) + " has undefined bits");
  if (e == 0) in.fail("an empty extras byte");
  return e;
}

int readLimit(In& in, std::string_view what, std::uint64_t max) {
  const std::uint64_t at = in.offset();
  const std::uint64_t v = in.varint(what);
  if (v < 1 || v > max) {
    in.failAt(at, std::string(what) + " " + std::to_string(v) + " is outside [1, " +
                      std::to_string(max) + "]");
  }
  return static_cast<int>(v);
}

void readFound(In& in, Model& m, std::vector<ItemId>& found, std::int64_t base) {
  const std::size_t n = in.count("found count", 1);
  std::int64_t prev = base;
  for (std::size_t k = 0; k < n; ++k) {
    const ItemId id = aliveAt(in, m, prev + in.zigzag("found item"), "found item");
    prev = id.index;
    found.push_back(id);
  }
}

MoverSpec readSpec(In& in) {
  MoverSpec s;
  const std::uint8_t kind = in.u8("mover kind");
  const std::uint8_t inner = in.u8("mover inner");
  if (kind > static_cast<std::uint8_t>(MoverKind::adaptive) ||
      inner > static_cast<std::uint8_t>(MoverKind::adaptive)) {
    in.fail("mover kind " + std::to_string(kind) + "/" + std::to_string(inner) + " is not defined");
  }
  s.kind = static_cast<MoverKind>(kind);
  s.inner = static_cast<MoverKind>(inner);
  s.maxStep = in.f64("mover maxStep");
  s.safetyFraction = in.f64("mover safetyFraction");
  try {
    const Mover check(s);
  } catch (const Error& e) {
    in.fail(std::string("mover spec: ") + e.what());
  }
  return s;
}

}  // namespace

void decodeKeyframe(In& in, Model& m, WorldState& s, std::uint64_t maxCells) {
  const std::uint64_t at = in.offset();
  s = {};
  s.cellSize = in.f64("keyframe cellSize");
  if (!sameBits(s.cellSize, m.cellSize)) {
    in.failAt(at, "keyframe cellSize " + formatNumber(s.cellSize) + " differs from the header's " +
                      formatNumber(m.cellSize));
  }
  const std::size_t nslots = in.count("keyframe slot count", 1);
  s.nextOrder = in.varint("keyframe nextOrder");
  const std::size_t nresp = in.count("keyframe response count", 1);
  if (nresp < m.fileBuiltins || nresp + (response::kBuiltinCount - m.fileBuiltins) >= response::ignore) {
    in.fail("keyframe response count " + std::to_string(nresp) + " is out of range");
  }
  for (std::size_t k = 0; k < nresp; ++k) {
    s.responses.push_back(in.str("response name", kMaxName));
    if (k < m.fileBuiltins && s.responses.back() != kBuiltinResponses[k].name) {
      in.fail("built-in response " + std::to_string(k) + " is named '" + s.responses.back() + "'");
    }
    if (s.responses.back().empty()) in.fail("an empty response name");
  }
  // A file from before a built-in was added: the built-ins it lacks take their places, and its
  // own responses move up (Model::fromFile maps the ids its calls name).
  for (std::uint16_t k = m.fileBuiltins; k < response::kBuiltinCount; ++k) {
    s.responses.insert(s.responses.begin() + k, std::string(kBuiltinResponses[k].name));
  }
  s.slots.resize(nslots);
  Rect prev;
  std::uint64_t prevOrder = 0, cells = 0;
  for (std::size_t k = 0; k < nslots; ++k) {
    WorldState::Slot& slot = s.slots[k];
    const std::uint8_t f = in.u8("slot flags");
    if (f > 3) in.fail("slot flags " + std::to_string(f) + " are not defined");
    slot.alive = f & 1;
    if (f & 2) {
      const std::uint64_t g = in.varint("slot generation");
      if (g > 0xFFFFFFFFu) in.fail("slot generation " + std::to_string(g) + " is over 2^32");
      slot.generation = static_cast<std::uint32_t>(g);
    }
    if (!slot.alive) continue;
    slot.order = prevOrder + static_cast<std::uint64_t>(in.zigzag("slot order"));
    prevOrder = slot.order;
    GroupIn g(in, "slot rect");
    slot.rect.x = g.get(prev.x + prev.w, prev.x);
    slot.rect.y = g.get(prev.y, prev.y + prev.h);
    slot.rect.w = g.get(prev.w, prev.h);
    slot.rect.h = g.get(prev.h, prev.w);
    prev = slot.rect;
    cells += cellCount(s.cellSize, slot.rect);
    if (cells > maxCells) {
      in.fail("the keyframe's items would register more than the replay's budget of " +
              std::to_string(maxCells) + " cells (ReplayOptions::maxCells)");
    }
  }
  const std::size_t nfree = in.count("free slot count", 1);
  for (std::size_t k = 0; k < nfree; ++k) {
    const std::uint64_t f = in.varint("free slot");
    if (f >= nslots) in.fail("free slot " + std::to_string(f) + " is out of range");
    s.freeSlots.push_back(static_cast<std::uint32_t>(f));
  }
  m.reset(s);
}

namespace {
[[noreturn, gnu::cold, gnu::noinline]] void failFlags(In& in, const Call& c, std::uint8_t flags) {
  in.failAt(c.offset, "call kind " + std::string(callKindName(c.kind)) + " with undefined flags " +
                          std::to_string(flags));
}
}  // namespace

void decodeCall(In& in, Model& m, Call& c, std::uint64_t maxCells) {
  c.offset = in.offset();
  c.collisions.clear();
  c.found.clear();
  c.segment.clear();
  c.answers.clear();
  c.legs.clear();
  c.bodies.clear();
  c.answersInOrder = false;
  c.contacts.clear();
  c.forget = false;
  c.nudge = {};
  c.item = c.skip = {};
  c.broad = BroadPhase::swept;
  c.maxResponses = kDefaultMaxResponses;
  c.semantics = MoveSemantics::tunnelvision;
  c.maxEvents = kDefaultMaxEvents;
  const std::uint8_t kb = in.u8("call kind");
  std::uint64_t kindBits = kb & 0x0F;
  if (kindBits == kExtendedKind)
    kindBits += std::min<std::uint64_t>(in.varint("call kind"), 1u << 20);
  if (kindBits >= kCallKindCount) {
    in.failAt(c.offset, "unknown call kind " + std::to_string(kindBits));
  }
  c.kind = static_cast<CallKind>(kindBits);
  const std::uint8_t flags = kb & 0xF0;
  const auto onlyFlags = [&](std::uint8_t allowed) {
    if (flags & ~allowed) [[unlikely]]
      failFlags(in, c, flags);
  };
  switch (c.kind) {
    case CallKind::add: {
      onlyFlags(0);
      const Rect p = m.prevAdd;
      GroupIn g(in, "add rect");
      c.rect.x = g.get(p.x + p.w, p.x);
      c.rect.y = g.get(p.y, p.y + p.h);
      c.rect.w = g.get(p.w, p.h);
      c.rect.h = g.get(p.h, p.w);
      if (!(c.rect.w > 0 && c.rect.h > 0)) in.failAt(c.offset, "add of a rect with w or h <= 0");
      const std::uint64_t cells = cellCount(m.cellSize, c.rect);
      requireBudget(in, m, cells, maxCells, "add");
      std::uint32_t index;
      if (!m.freeSlots.empty()) {
        index = m.freeSlots.back();
        m.freeSlots.pop_back();
      } else {
        if (m.slots.size() >= 0x7FFFFFFFu) in.failAt(c.offset, "more than 2^31 items");
        index = static_cast<std::uint32_t>(m.slots.size());
        m.slots.emplace_back();
      }
      Model::Slot& s = m.slots[index];
      s.rect = c.rect;
      s.alive = true;
      s.order = m.nextOrder++;
      s.lastDelta = {};
      m.prevAdd = c.rect;
      m.prevItem = index;
      m.cells += cells;
      c.item = {index, s.generation};
      return;
    }
    case CallKind::remove: {
      onlyFlags(kSameItem);
      c.item = readItem(in, m, kb, "remove");
      Model::Slot& s = m.slots[c.item.index];
      c.rect = c.start = s.rect;
      m.cells -= std::min(m.cells, cellCount(m.cellSize, s.rect));
      s.alive = false;
      ++s.generation;
      m.freeSlots.push_back(c.item.index);
      return;
    }
    case CallKind::update: {
      onlyFlags(kSameItem);
      c.item = readItem(in, m, kb, "update");
      Model::Slot& s = m.slots[c.item.index];
      c.start = s.rect;
      GroupIn g(in, "update rect");
      c.rect.x = g.get(s.rect.x + s.lastDelta.x, s.rect.x, s.rect.x);
      c.rect.y = g.get(s.rect.y + s.lastDelta.y, s.rect.y, s.rect.y);
      c.rect.w = g.get(s.rect.w, s.rect.h);
      c.rect.h = g.get(s.rect.h, s.rect.w);
      if (!(c.rect.w > 0 && c.rect.h > 0)) in.failAt(c.offset, "update to a rect with w or h <= 0");
      const std::uint64_t before = cellCount(m.cellSize, s.rect);
      const std::uint64_t after = cellCount(m.cellSize, c.rect);
      m.cells -= std::min(m.cells, before);
      requireBudget(in, m, after, maxCells, "update");
      m.cells += after;
      const Vec2 d = c.rect.position() - s.rect.position();
      if (d != Vec2{} && sameBits(s.rect.x + d.x, c.rect.x) && sameBits(s.rect.y + d.y, c.rect.y)) {
        s.lastDelta = d;
      }
      s.rect = c.rect;
      c.position = c.rect.position();
      return;
    }
    case CallKind::move:
    case CallKind::check:
    case CallKind::moverMove: {
      const bool mover = c.kind == CallKind::moverMove;
      onlyFlags(static_cast<std::uint8_t>(kSameItem | kExtras | kFree | (mover ? kMoverDef : 0)));
      c.item = readItem(in, m, kb, "move item");
      if (mover) {
        const std::uint64_t id = in.varint("mover id");
        if (id >= kMaxMovers) in.fail("mover id " + std::to_string(id) + " is out of range");
        c.mover = static_cast<std::uint32_t>(id);
        if (c.mover >= m.movers.size()) {
          m.movers.resize(c.mover + 1);
          m.moverDefined.resize(c.mover + 1, false);
        }
        if (kb & kMoverDef) {
          m.movers[c.mover] = readSpec(in);
          m.moverDefined[c.mover] = true;
        } else if (!m.moverDefined[c.mover]) {
          in.fail("mover " + std::to_string(id) + " is used before its definition");
        }
      }
      std::uint8_t extras = 0;
      if (kb & kExtras) {
        extras = readExtras(in, mover ? static_cast<std::uint8_t>(kHasAnswers | kHasLegs)
                                      : static_cast<std::uint8_t>(kBounds | kLimit | kHasAnswers |
                                                                  kHasLegs | kBump));
        if (extras & kBounds) c.broad = BroadPhase::bounds;
        if (extras & kBump) c.semantics = MoveSemantics::bump;
        if (extras & kLimit) c.maxResponses = readLimit(in, "maxResponses", 4096);
      }
      Model::Slot& s = m.slots[c.item.index];
      c.start = s.rect;
      c.goal = readGoal(in, s, "goal");
      const bool hull = c.broad == BroadPhase::bounds || c.semantics == MoveSemantics::bump ||
                        (mover && m.movers[c.mover].kind == MoverKind::sweep);
      requireReach(in, m, c.offset, s.rect, c.goal, hull, maxCells, c.kind);
      const Vec2 d = c.goal - s.rect.position();
      if (sameBits(s.rect.x + d.x, c.goal.x) && sameBits(s.rect.y + d.y, c.goal.y)) s.lastDelta = d;
      if (kb & kFree) {
        c.position = c.goal;
      } else {
        readResult(in, m, c, c.item, c.start, c.goal, c.position);
      }
      if (extras & kHasAnswers) readAnswers(in, m, c, c.item);
      if (extras & kHasLegs) readLegs(in, c);
      if (c.kind != CallKind::check) s.rect = s.rect.at(c.position);
      return;
    }
    case CallKind::project: {
      onlyFlags(kExtras | kFree);
      std::uint8_t extras = 0;
      if (kb & kExtras) {
        extras = readExtras(in, kBounds | kLimit | kHasAnswers | kHasLegs | kBump);
        if (extras & kBounds) c.broad = BroadPhase::bounds;
        if (extras & kBump) c.semantics = MoveSemantics::bump;
        if (extras & kLimit) c.maxResponses = readLimit(in, "maxResponses", 4096);
      }
      {
        GroupIn g(in, "project rect");
        c.rect.x = g.get(0, 0);
        c.rect.y = g.get(0, 0);
        c.rect.w = g.get(0, 0);
        c.rect.h = g.get(0, c.rect.w);
      }
      c.start = c.rect;
      {
        GroupIn g(in, "project goal");
        c.goal.x = g.get(c.rect.x, 0, c.rect.x);
        c.goal.y = g.get(c.rect.y, 0, c.rect.y);
      }
      if (!(c.rect.w > 0 && c.rect.h > 0))
        in.failAt(c.offset, "project of a rect with w or h <= 0");
      requireReach(in, m, c.offset, c.rect, c.goal,
                   c.broad == BroadPhase::bounds || c.semantics == MoveSemantics::bump, maxCells,
                   "project");
      if (kb & kFree) {
        c.position = c.goal;
      } else {
        readResult(in, m, c, {}, c.rect, c.goal, c.position);
      }
      if (extras & kHasAnswers) readAnswers(in, m, c, {});
      if (extras & kHasLegs) readLegs(in, c);
      return;
    }
    case CallKind::queryRect:
    case CallKind::anyOverlap: {
      const bool any = c.kind == CallKind::anyOverlap;
      onlyFlags(static_cast<std::uint8_t>(kSameItem | kSkipValid | (any ? kAny | kAnswers : 0)));
      Rect p;
      if (kb & kSkipValid) {
        c.skip = readItem(in, m, kb, "query skip");
        c.item = c.skip;
        p = m.slots[c.skip.index].rect;
      } else if (kb & kSameItem) {
        in.failAt(c.offset, "a query marked 'same item' without an item");
      }
      GroupIn g(in, "query rect");
      c.rect.x = g.get(p.x, 0);
      c.rect.y = g.get(p.y, 0);
      c.rect.w = g.get(p.w, 0);
      c.rect.h = g.get(p.h, c.rect.w);
      // The world cannot hold what a negative size means (and would not be asked it).
      if (c.rect.w < 0 || c.rect.h < 0) in.failAt(c.offset, "a query rect with a negative size");
      requireReach(in, m, c.offset, c.rect, c.rect.position(), true, maxCells, c.kind);
      if (any) {
        c.any = kb & kAny;
        if (kb & kAnswers) readAnswers(in, m, c, c.skip);
      } else {
        readFound(in, m, c.found, c.skip.valid() ? c.skip.index : 0);
      }
      return;
    }
    case CallKind::queryPoint: {
      onlyFlags(0);
      GroupIn g(in, "query point");
      c.goal.x = g.get(0, 0);
      c.goal.y = g.get(0, 0);
      readFound(in, m, c.found, 0);
      return;
    }
    case CallKind::querySegment: {
      onlyFlags(0);
      {
        GroupIn g(in, "segment");
        c.goal.x = g.get(0, 0);
        c.goal.y = g.get(0, 0);
        c.b.x = g.get(c.goal.x, 0, c.goal.x);
        c.b.y = g.get(c.goal.y, 0, c.goal.y);
      }
      requireReach(in, m, c.offset, Rect{c.goal.x, c.goal.y, 0, 0}, c.b, false, maxCells,
                   "querySegment");
      const std::size_t n = in.count("segment hit count", 3);
      std::int64_t prev = 0;
      for (std::size_t k = 0; k < n; ++k) {
        SegmentHit h;
        h.item = aliveAt(in, m, prev + in.zigzag("segment hit item"), "segment hit item");
        prev = h.item.index;
        GroupIn g(in, "segment hit");
        h.t0 = g.get(0.0, 1.0);
        h.t1 = g.get(1.0, 0.0);
        h.entry.x = g.get(c.goal.x, c.b.x);
        h.entry.y = g.get(c.goal.y, c.b.y);
        GroupIn e(in, "segment hit exit");
        h.exit.x = e.get(c.b.x, h.entry.x);
        h.exit.y = e.get(c.b.y, h.entry.y);
        c.segment.push_back(h);
      }
      return;
    }
    case CallKind::addResponse: {
      onlyFlags(0);
      c.name = in.str("response name", kMaxName);
      if (c.name.empty()) in.failAt(c.offset, "an empty response name");
      if (std::find(m.responses.begin(), m.responses.end(), c.name) != m.responses.end()) {
        in.failAt(c.offset, "response '" + c.name + "' is registered twice");
      }
      if (m.responses.size() + 1 >= response::ignore) in.failAt(c.offset, "too many responses");
      m.responses.push_back(c.name);
      return;
    }
    case CallKind::batchStep: {
      onlyFlags(kExtras);
      std::uint8_t extras = 0;
      if (kb & kExtras) {
        extras = readExtras(in, kLimit | kHasAnswers | kHasLegs);
        if (extras & kLimit) c.maxEvents = readLimit(in, "maxEvents", 1u << 30);
      }
      const std::size_t n = in.count("batch size", 3);
      for (std::size_t k = 0; k < n; ++k) {
        BodyOut b;
        b.item = aliveAt(in, m, static_cast<std::int64_t>(m.prevItem) + in.zigzag("batch item"),
                         "batch item");
        m.prevItem = b.item.index;
        for (const BodyOut& o : c.bodies) {
          if (o.item == b.item)
            in.fail("batch moves item " + std::to_string(b.item.index) + " twice");
        }
        Model::Slot& s = m.slots[b.item.index];
        b.start = s.rect;
        b.goal = readGoal(in, s, "batch goal");
        // The whole hull: a batch body's search reads every cell of its start-to-goal box.
        requireReach(in, m, c.offset, s.rect, b.goal, true, maxCells, "batch move");
        const Vec2 d = b.goal - s.rect.position();
        if (sameBits(s.rect.x + d.x, b.goal.x) && sameBits(s.rect.y + d.y, b.goal.y))
          s.lastDelta = d;
        c.bodies.push_back(b);
      }
      for (BodyOut& b : c.bodies) {
        b.first = static_cast<std::uint32_t>(c.collisions.size());
        readResult(in, m, c, b.item, b.start, b.goal, b.position);
        b.count = static_cast<std::uint32_t>(c.collisions.size()) - b.first;
      }
      if (extras & kHasAnswers) readAnswers(in, m, c, {});
      if (extras & kHasLegs) readLegs(in, c);
      for (const BodyOut& b : c.bodies) {
        Model::Slot& s = m.slots[b.item.index];
        s.rect = s.rect.at(b.position);
      }
      return;
    }
    case CallKind::label: {
      onlyFlags(0);
      const std::uint64_t index = in.varint("label item index");
      const std::uint64_t gen = in.varint("label item generation");
      if (index >= 0x7FFFFFFFu || gen > 0xFFFFFFFFu)
        in.failAt(c.offset, "label of an impossible item");
      c.item = {static_cast<std::uint32_t>(index), static_cast<std::uint32_t>(gen)};
      c.name = in.str("label", kMaxName);
      c.category = in.str("category", kMaxName);
      return;
    }
    case CallKind::contacts: {
      onlyFlags(static_cast<std::uint8_t>(kSameItem | kForget | kAnswers));
      c.forget = kb & kForget;
      if (c.forget) {
        if (kb & kSameItem) in.failAt(c.offset, "a forget marked 'same item'");
        const std::uint64_t index = in.varint("contacts item index");
        const std::uint64_t gen = in.varint("contacts item generation");
        if (index >= 0x7FFFFFFFu || gen > 0xFFFFFFFFu)
          in.failAt(c.offset, "contacts of an impossible item");
        c.item = {static_cast<std::uint32_t>(index), static_cast<std::uint32_t>(gen)};
      } else {
        c.item = readItem(in, m, kb, "contacts item");
      }
      // Each event takes at least 2 bytes (code, other).
      const std::size_t n = in.count("contact event count", 2);
      c.contacts.reserve(n);
      for (std::size_t k = 0; k < n; ++k) {
        const std::uint8_t code = in.u8("contact event");
        const std::uint8_t phase = code & 3, nc = (code >> 3) & 7;
        if (phase > 2 || nc > 5 || (code & 0x80))
          in.fail("contact event code " + std::to_string(code) + " is not defined");
        ContactEvent e;
        e.item = c.item;
        e.phase = static_cast<ContactPhase>(phase);
        e.met = code & 4;
        const std::int64_t index =
            static_cast<std::int64_t>(c.item.index) + in.zigzag("contact other");
        if (code & 0x40) {
          // An item no longer in the world: only an end can name it.
          const std::uint64_t gen = in.varint("contact other generation");
          if (e.phase != ContactPhase::end || index < 0 || index >= 0x7FFFFFFF || gen > 0xFFFFFFFFu)
            in.fail("a contact with an item not in the world that is not an end");
          e.other = {static_cast<std::uint32_t>(index), static_cast<std::uint32_t>(gen)};
        } else {
          e.other = aliveAt(in, m, index, "contact other");
        }
        if (e.other == c.item) in.fail("a contact of an item with itself");
        if (nc == 5) {
          GroupIn g(in, "contact normal");
          e.normal.x = g.get(0, 1);
          e.normal.y = g.get(0, 1);
        } else {
          e.normal = kNormals[nc];
        }
        c.contacts.push_back(e);
      }
      if (kb & kAnswers) readAnswers(in, m, c, c.item);
      return;
    }
    case CallKind::cornerNudge: {
      onlyFlags(kSameItem);
      c.item = readItem(in, m, kb, "cornerNudge body");
      const ItemId ceiling = aliveAt(
          in, m, static_cast<std::int64_t>(c.item.index) + in.zigzag("cornerNudge ceiling"),
          "cornerNudge ceiling");
      if (ceiling == c.item) in.fail("a corner nudge round the body itself");
      const Rect& cr = m.slots[ceiling.index].rect;
      GroupIn g(in, "cornerNudge");
      Collision& hit = c.nudge.hit;
      hit.touch.y = g.get(cr.bottom(), cr.y);
      hit.touch.x = g.get(cr.x, cr.right(), cr.x);
      c.nudge.dx = g.get(0.0, 0.0);
      if (!isFinite(hit.touch) || !std::isfinite(c.nudge.dx) || c.nudge.dx == 0.0) {
        in.fail("corner nudge touch (" + formatNumber(hit.touch.x) + ", " +
                formatNumber(hit.touch.y) + ") dx " + formatNumber(c.nudge.dx) +
                ": not finite, or no nudge");
      }
      const Rect& body = m.slots[c.item.index].rect;
      hit.item = c.item;
      hit.other = ceiling;
      hit.normal = {0.0, 1.0};
      hit.itemRect = body.at(hit.touch);  // the body where it met the corner
      hit.otherRect = cr;
      hit.target = hit.touch;
      hit.move = {};
      return;
    }
    case CallKind::advance: {
      onlyFlags(0);
      GroupIn g(in, "advance frameTime");
      c.frameTime = g.get(m.prevFrameTime, 0.0);
      if (c.frameTime < 0) in.failAt(c.offset, "advance of a negative frame time");
      m.prevFrameTime = c.frameTime;
      const std::uint64_t t = in.varint("advance ticks");
      if (t > (1u << 20))
        in.failAt(c.offset, "advance of " + std::to_string(t) + " ticks (at most 2^20)");
      c.ticks = static_cast<std::int64_t>(t);
      return;
    }
  }
}

}  // namespace tv::rec
