// Running a replay: seeking through keyframes, re-executing each recorded call on the replay's
// world and comparing it with the recording (the first difference is a Divergence), and the
// what-if run in which another mover makes the recorded moves.

#include <algorithm>

#include "replay_impl.hpp"

namespace tv {

namespace rec {
namespace {

// Registered under every recorded user response's name, with the replay's own cursor as its
// context: hands back the recorded legs in order.
Leg replayedResponse(void* context, const Collision& c, Vec2 goal) {
  LegCursor& cur = *static_cast<LegCursor*>(context);
  if (!cur.whatIf && cur.legs && cur.next < cur.legs->size()) return (*cur.legs)[cur.next++];
  if (!cur.whatIf) cur.overrun = true;
  return slideResponse(c, goal);
}

}  // namespace
}  // namespace rec

namespace {

std::string fmt(double v) {
  return formatNumber(v);
}
std::string fmt(Vec2 v) {
  std::string s = "(";
  s += formatNumber(v.x);
  s += ", ";
  s += formatNumber(v.y);
  s += ")";
  return s;
}
std::string fmt(const Rect& r) {
  std::string s = "{";
  s += formatNumber(r.x);
  s += ", ";
  s += formatNumber(r.y);
  s += ", ";
  s += formatNumber(r.w);
  s += ", ";
  s += formatNumber(r.h);
  s += "}";
  return s;
}
std::string fmt(ItemId id) {
  return id.valid() ? std::to_string(id.index) + "." + std::to_string(id.generation) : "none";
}
bool same(Vec2 a, Vec2 b) {
  return rec::sameBits(a.x, b.x) && rec::sameBits(a.y, b.y);
}
bool same(const Rect& a, const Rect& b) {
  return rec::sameBits(a.x, b.x) && rec::sameBits(a.y, b.y) && rec::sameBits(a.w, b.w) &&
         rec::sameBits(a.h, b.h);
}
// Bit for bit, every field a replay compares.
bool sameCollision(const Collision& g, const Collision& e) {
  return g.other == e.other && g.item == e.item && g.overlaps == e.overlaps &&
         g.corner == e.corner && rec::sameBits(g.ti, e.ti) && same(g.move, e.move) &&
         same(g.normal, e.normal) && same(g.touch, e.touch) && same(g.itemRect, e.itemRect) &&
         same(g.otherRect, e.otherRect) && g.response == e.response && same(g.target, e.target);
}
bool sameMove(Vec2 pos, std::span<const Collision> got, Vec2 expPos,
              std::span<const Collision> exp) {
  return same(pos, expPos) && got.size() == exp.size() &&
         std::equal(got.begin(), got.end(), exp.begin(), sameCollision);
}
// The same mover: what its name says (kind, and a substep's inner mover) and its numbers.
bool sameSpec(const MoverSpec& a, const MoverSpec& b) {
  return a.kind == b.kind && (a.kind != MoverKind::substep || a.inner == b.inner) &&
         rec::sameBits(a.maxStep, b.maxStep) && rec::sameBits(a.safetyFraction, b.safetyFraction);
}

// The user's filter, answered from the recording: by pair, or in the recorded order.
struct ReplayFilter {
  const rec::Call& c;
  const Replay::Impl& d;
  bool exact;
  std::size_t next = 0;
  std::string mismatch;

  [[nodiscard]] const rec::Answer* find(ItemId item, ItemId other) const {
    for (const rec::Answer& a : c.answers) {
      if (a.item == item && a.other == other) return &a;
    }
    return nullptr;
  }
  [[nodiscard]] ResponseId recordedOr(ItemId item, ItemId other) const {
    const rec::Answer* a = find(item, other);
    return a ? a->response : d.fallbackAnswer(item, other);
  }
  ResponseId operator()(ItemId item, ItemId other) {
    if (c.answersInOrder && exact) {
      if (next < c.answers.size() && c.answers[next].item == item &&
          c.answers[next].other == other) {
        return c.answers[next++].response;
      }
    } else if (const rec::Answer* a = find(item, other)) {
      return a->response;
    }
    if (exact && mismatch.empty()) {
      mismatch = "the filter was asked about (" + d.labelOf(item) + ", " + d.labelOf(other) + ")";
    }
    return d.fallbackAnswer(item, other);
  }
};

// A move from S to E against the world as it is after it: did it pass through, or end inside,
// something its filter neither ignores nor crosses? `solid`: the first such item (in add order)
// it passed through, else the first it ended inside.
void classify(const World& w, ItemId item, const Rect& S, const Rect& E, const ReplayFilter& f,
              std::vector<ItemId>& scratch, bool& tunnelled, bool& overlapping, ItemId& solid) {
  tunnelled = overlapping = false;
  solid = {};
  ItemId inside;
  const Rect hull = unite(S, E);
  if (rec::cellCount(w.cellSize(), hull) > 65536) return;  // a teleport across the world
  w.queryRect(hull, scratch, item);
  for (const ItemId o : scratch) {
    const ResponseId a = f.recordedOr(item, o);
    if (a == response::ignore || a == response::cross) continue;
    const Rect O = w.rect(o);
    if (overlaps(E, O) && !overlaps(S, O)) {
      overlapping = true;
      if (!inside.valid()) inside = o;
    }
    const bool before = tunnelled;
    const auto through = [](double s0, double s1, double e0, double e1, double o0, double o1) {
      return (s1 <= o0 && e0 >= o1) || (e1 <= o0 && s0 >= o1);
    };
    const auto spans = [](double a0, double a1, double o0, double o1) {
      return a0 < o1 && o0 < a1;
    };
    if (through(S.x, S.right(), E.x, E.right(), O.x, O.right()) &&
        spans(S.y, S.bottom(), O.y, O.bottom()) && spans(E.y, E.bottom(), O.y, O.bottom())) {
      tunnelled = true;
    }
    if (through(S.y, S.bottom(), E.y, E.bottom(), O.y, O.bottom()) &&
        spans(S.x, S.right(), O.x, O.right()) && spans(E.x, E.right(), O.x, O.right())) {
      tunnelled = true;
    }
    if (tunnelled && !before) solid = o;
  }
  if (!solid.valid()) solid = inside;
}

}  // namespace

ResponseId Replay::Impl::fallbackAnswer(ItemId item, ItemId other) const {
  auto it = commonAnswer.find(item);
  if (it != commonAnswer.end()) return it->second;
  return moving.count(other) ? response::ignore : response::slide;
}

void Replay::Impl::restoreWorld(const WorldState& ws) {
  auto w = std::make_unique<World>(cellSize);
  for (std::size_t i = response::kBuiltinCount; i < ws.responses.size(); ++i) {
    w->addResponse(ws.responses[i], &rec::replayedResponse, &legs);
  }
  try {
    w->restore(ws);
  } catch (const Error& e) {
    in.fail(std::string("the keyframe cannot be restored: ") + e.what());
  }
  world = std::move(w);
  movers.clear();
  contacts = Contacts{};
  contactsSeen.clear();
  if (whatIfMover) whatIfMover->reset();
}

void Replay::Impl::enterFrame(std::uint64_t f, bool restore) {
  const FrameInfo& fi = frames[f];
  in = rec::In(bytes.data() + fi.offset, fi.size, fi.offset, f);
  frame = f;
  callIndex = 0;
  WorldState ws;
  if (!beginFrame(in, model, ws, f)) return;
  if (restore || !world) {
    restoreWorld(ws);
    return;
  }
  if (whatIf()) return;
  // Replaying on: the world must already be what the keyframe says.
  const WorldState got = world->state();
  std::string what, expected, actual;
  if (got.slots.size() != ws.slots.size()) {
    what = "keyframe slot count";
    expected = std::to_string(ws.slots.size());
    actual = std::to_string(got.slots.size());
  } else {
    for (std::size_t i = 0; i < ws.slots.size() && what.empty(); ++i) {
      const WorldState::Slot &a = ws.slots[i], &b = got.slots[i];
      if (a.alive != b.alive || a.generation != b.generation || a.order != b.order ||
          (a.alive && !same(a.rect, b.rect))) {
        what = "keyframe slot " + std::to_string(i);
        expected = fmt(a.rect);
        actual = fmt(b.rect);
      }
    }
  }
  if (what.empty() && (got.freeSlots != ws.freeSlots || got.nextOrder != ws.nextOrder)) {
    what = "keyframe free slots";
    expected = std::to_string(ws.freeSlots.size());
    actual = std::to_string(got.freeSlots.size());
  }
  if (!what.empty()) {
    pendingDivergence = Divergence{f, 0, CallKind::advance, {}, what, expected, actual, fi.offset};
  } else if (restoreAtKeyframes && !statefulMovers) {
    // Go on from the keyframe, as a seek does: a world rebuilt from a snapshot, whose cells list
    // their items in another order than the world that got here call by call.
    restoreWorld(ws);
  }
}

void Replay::Impl::setDivergence(std::optional<Divergence>& out, std::uint32_t index,
                                 const std::string& what, const std::string& expected,
                                 const std::string& got) const {
  if (out) return;
  out = Divergence{frame, index, call.kind, labelOf(call.item), what, expected, got, call.offset};
}

void Replay::Impl::describeMove(std::optional<Divergence>& out, std::uint32_t index,
                                std::string_view prefix, Vec2 pos, std::span<const Collision> got,
                                Vec2 expPos, std::span<const Collision> exp) const {
  const auto diverge = [&](const std::string& what, const std::string& expected,
                           const std::string& g) { setDivergence(out, index, what, expected, g); };
  const std::string pre(prefix);
  if (!same(pos, expPos)) diverge(pre + "position", fmt(expPos), fmt(pos));
  if (got.size() != exp.size()) {
    diverge(pre + "collision count", std::to_string(exp.size()), std::to_string(got.size()));
  }
  for (std::size_t i = 0; i < std::min(got.size(), exp.size()) && !out; ++i) {
    const Collision &g = got[i], &e = exp[i];
    const std::string p = pre + "collision " + std::to_string(i) + " ";
    if (g.other != e.other) diverge(p + "other", labelOf(e.other), labelOf(g.other));
    if (g.item != e.item) diverge(p + "item", fmt(e.item), fmt(g.item));
    if (g.overlaps != e.overlaps)
      diverge(p + "overlaps", e.overlaps ? "yes" : "no", g.overlaps ? "yes" : "no");
    if (g.corner != e.corner)
      diverge(p + "corner", e.corner ? "yes" : "no", g.corner ? "yes" : "no");
    if (!rec::sameBits(g.ti, e.ti)) diverge(p + "ti", fmt(e.ti), fmt(g.ti));
    if (!same(g.move, e.move)) diverge(p + "move", fmt(e.move), fmt(g.move));
    if (!same(g.normal, e.normal)) diverge(p + "normal", fmt(e.normal), fmt(g.normal));
    if (!same(g.touch, e.touch)) diverge(p + "touch", fmt(e.touch), fmt(g.touch));
    if (!same(g.itemRect, e.itemRect)) diverge(p + "itemRect", fmt(e.itemRect), fmt(g.itemRect));
    if (!same(g.otherRect, e.otherRect))
      diverge(p + "otherRect", fmt(e.otherRect), fmt(g.otherRect));
    if (g.response != e.response)
      diverge(p + "response", std::to_string(e.response), std::to_string(g.response));
    if (!same(g.target, e.target)) diverge(p + "target", fmt(e.target), fmt(g.target));
  }
}

Mover& Replay::Impl::recordedMover(std::uint32_t id) {
  const MoverSpec& spec = model.movers[id];
  if (id < movers.size() && movers[id] && sameSpec(movers[id]->spec(), spec)) [[likely]] {
    return *movers[id];
  }
  if (id >= movers.size()) movers.resize(id + 1);
  movers[id] = std::make_unique<Mover>(spec);
  return *movers[id];
}

// Most of a replay: a recorded move made again and compared, without the what-if and the
// statistics that execute() also serves. The same results and the same words as execute().
std::optional<Divergence> Replay::Impl::replayMove(MoveTrace* trace, bool compare,
                                                   std::uint32_t index) {
  rec::Call& c = call;
  ReplayFilter rf{c, *this, true, 0, {}};
  const Filter filter(rf);
  legs = {&c.legs, 0, false, false};
  struct ResetLegs {
    rec::LegCursor& cursor;
    ~ResetLegs() { cursor = {}; }
  } resetLegs{legs};
  MoveResult r;
  try {
    if (c.kind == CallKind::move) {
      MoveOptions o;
      o.broad = c.broad;
      o.maxResponses = c.maxResponses;
      o.semantics = c.semantics;
      o.trace = trace;
      r = world->move(c.item, c.goal, filter, o);
    } else {
      r = recordedMover(c.mover).move(*world, c.item, c.goal, filter, trace);
    }
  } catch (const Error& e) {
    if (!compare) return std::nullopt;
    std::optional<Divergence> out;
    setDivergence(out, index, "the call", "succeeded", std::string("refused: ") + e.what());
    return out;
  }
  if (!compare) return std::nullopt;
  const bool legsAgree = !legs.overrun && legs.next == c.legs.size();
  if (sameMove(r.position, r.collisions, c.position, c.collisions) && rf.mismatch.empty() &&
      legsAgree) [[likely]] {
    return std::nullopt;
  }
  std::optional<Divergence> out;
  describeMove(out, index, "", r.position, r.collisions, c.position, c.collisions);
  if (!rf.mismatch.empty()) setDivergence(out, index, "filter", "not asked", rf.mismatch);
  if (!legsAgree) {
    setDivergence(out, index, "user response legs", std::to_string(c.legs.size()),
                  legs.overrun ? "more" : std::to_string(legs.next));
  }
  return out;
}

std::optional<Divergence> Replay::Impl::execute(MoveTrace* trace, bool compare) {
  rec::decodeCall(in, model, call, options.maxCells);
  const std::uint32_t index = callIndex++;
  if ((call.kind == CallKind::moverMove || call.kind == CallKind::move) && !whatIf() &&
      !classifyRecorded && !options.itemStats) [[likely]] {
    return replayMove(trace, compare, index);
  }
  return executeOther(trace, compare, index);
}

std::optional<Divergence> Replay::Impl::executeOther(MoveTrace* trace, bool compare,
                                                     std::uint32_t index) {
  rec::Call& c = call;
  std::optional<Divergence> out;
  const auto diverge = [&](const std::string& what, const std::string& expected,
                           const std::string& got) {
    setDivergence(out, index, what, expected, got);
  };
  // Every move is compared; the words are made only for a difference.
  const auto compareMove = [&](std::string_view prefix, Vec2 pos, std::span<const Collision> got,
                               Vec2 expPos, std::span<const Collision> exp) {
    if (sameMove(pos, got, expPos, exp)) [[likely]]
      return;
    describeMove(out, index, prefix, pos, got, expPos, exp);
  };
  const auto compareFound = [&](std::span<const ItemId> got) {
    if (got.size() != c.found.size()) {
      diverge(std::string(callKindName(c.kind)) + " result count", std::to_string(c.found.size()),
              std::to_string(got.size()));
      return;
    }
    for (std::size_t i = 0; i < got.size(); ++i) {
      if (got[i] != c.found[i]) {
        diverge(std::string(callKindName(c.kind)) + " result " + std::to_string(i),
                labelOf(c.found[i]), labelOf(got[i]));
        return;
      }
    }
  };

  const bool exact = !whatIf();
  ReplayFilter rf{c, *this, exact, 0, {}};
  const Filter filter(rf);
  legs = {&c.legs, 0, false, !exact};
  struct ResetLegs {
    rec::LegCursor& cursor;
    ~ResetLegs() { cursor = {}; }
  } resetLegs{legs};

  // What-if: one move by the other mover, measured against the recording.
  const auto whatIfMove = [&](ItemId item, Vec2 goal, Vec2 recorded) {
    const Rect S = world->rect(item);
    if (whatIfMover->spec().kind == MoverKind::sweep &&
        rec::cellCount(cellSize, unite(S, S.at(goal))) > options.maxCells) {
      if (report) ++report->failedCalls;  // its hull alone would take the budget's time
      return;
    }
    whatIfMover->move(*world, item, goal, filter, trace);
    if (!report) return;
    const Rect E = world->rect(item);
    bool tunnelled = false, overlapping = false;
    ItemId solid;
    classify(*world, item, S, E, rf, found, tunnelled, overlapping, solid);
    ++report->moves;
    const double distance = length(E.position() - recorded);
    const bool differs = !same(E.position(), recorded);
    if (differs || tunnelled || overlapping) {
      report->differences.push_back(
          {frame, index, item, recorded, E.position(), distance, tunnelled, overlapping, solid});
    }
    if (tunnelled) ++report->tunnelled;
    if (overlapping) ++report->overlapping;
    if (differs && !report->firstDifferentFrame) report->firstDifferentFrame = frame;
    if (distance > farAway && !report->firstImplausibleFrame) report->firstImplausibleFrame = frame;
  };
  // The recorded run's own moves, classified the same way (whatIf's first pass) and counted.
  const auto afterRecordedMove = [&](ItemId item, const Rect& S) {
    if (!classifyRecorded && !options.itemStats) return;
    const Rect E = world->rect(item);
    bool tunnelled = false, overlapping = false;
    ItemId solid;
    classify(*world, item, S, E, rf, found, tunnelled, overlapping, solid);
    if (classifyRecorded && report) {
      if (tunnelled) ++report->recordedTunnelled;
      if (overlapping) ++report->recordedOverlapping;
      if (tunnelled || overlapping) {
        report->recordedFailures.push_back(
            {frame, index, item, E.position(), E.position(), 0.0, tunnelled, overlapping, solid});
      }
    }
    if (options.itemStats && !classifyRecorded) {
      bool ends = false;
      world->queryRect(E, found, item);
      for (const ItemId o : found) {
        const ResponseId a = rf.recordedOr(item, o);
        if (a != response::ignore && a != response::cross) ends = true;
      }
      auto it = itemIndex.find(item);
      if (ends && it != itemIndex.end()) ++items[it->second].endedOverlapping;
    }
  };

  try {
    switch (c.kind) {
      case CallKind::add: {
        const ItemId id = world->add(c.rect);
        if (id != c.item) diverge("item id", fmt(c.item), fmt(id));
        break;
      }
      case CallKind::remove:
        world->remove(c.item);
        break;
      case CallKind::update: {
        const bool asMove = !exact && options.updatesAsMoves && c.rect.w == c.start.w &&
                            c.rect.h == c.start.h && !same(c.rect.position(), c.start.position());
        if (asMove) {
          whatIfMove(c.item, c.rect.position(), c.rect.position());
        } else {
          world->update(c.item, c.rect);
          if (classifyRecorded && options.updatesAsMoves) afterRecordedMove(c.item, c.start);
        }
        break;
      }
      case CallKind::move: {
        if (!exact) {
          whatIfMove(c.item, c.goal, c.position);
          break;
        }
        MoveOptions o;
        o.broad = c.broad;
        o.maxResponses = c.maxResponses;
        o.semantics = c.semantics;
        o.trace = trace;
        const MoveResult r = world->move(c.item, c.goal, filter, o);
        if (compare) compareMove("", r.position, r.collisions, c.position, c.collisions);
        afterRecordedMove(c.item, c.start);
        break;
      }
      case CallKind::moverMove: {
        if (!exact) {
          whatIfMove(c.item, c.goal, c.position);
          break;
        }
        const MoveResult r = recordedMover(c.mover).move(*world, c.item, c.goal, filter, trace);
        if (compare) compareMove("", r.position, r.collisions, c.position, c.collisions);
        afterRecordedMove(c.item, c.start);
        break;
      }
      case CallKind::check:
      case CallKind::project: {
        if (!exact && !trace) break;
        MoveOptions o;
        o.broad = c.broad;
        o.maxResponses = c.maxResponses;
        o.semantics = c.semantics;
        o.trace = trace;
        const MoveResult r = c.kind == CallKind::check ? world->check(c.item, c.goal, filter, o)
                                                       : world->project(c.rect, c.goal, filter, o);
        if (compare && exact) compareMove("", r.position, r.collisions, c.position, c.collisions);
        break;
      }
      case CallKind::queryRect:
        if (!exact) break;
        world->queryRect(c.rect, found, c.skip);
        if (compare) compareFound(found);
        break;
      case CallKind::queryPoint: {
        if (!exact) break;
        const std::vector<ItemId> got = world->queryPoint(c.goal);
        if (compare) compareFound(got);
        break;
      }
      case CallKind::querySegment: {
        if (!exact) break;
        const std::vector<SegmentHit> got = world->querySegment(c.goal, c.b);
        if (!compare) break;
        if (got.size() != c.segment.size()) {
          diverge("querySegment result count", std::to_string(c.segment.size()),
                  std::to_string(got.size()));
        }
        for (std::size_t i = 0; i < std::min(got.size(), c.segment.size()); ++i) {
          const SegmentHit &g = got[i], &e = c.segment[i];
          const std::string p = "querySegment hit " + std::to_string(i) + " ";
          if (g.item != e.item) diverge(p + "item", labelOf(e.item), labelOf(g.item));
          if (!rec::sameBits(g.t0, e.t0) || !rec::sameBits(g.t1, e.t1)) {
            diverge(p + "t0..t1", fmt(e.t0) + ".." + fmt(e.t1), fmt(g.t0) + ".." + fmt(g.t1));
          }
          if (!same(g.entry, e.entry)) diverge(p + "entry", fmt(e.entry), fmt(g.entry));
          if (!same(g.exit, e.exit)) diverge(p + "exit", fmt(e.exit), fmt(g.exit));
        }
        break;
      }
      case CallKind::anyOverlap: {
        if (!exact) break;
        const bool any = world->anyOverlap(c.rect, c.skip, filter);
        if (compare && any != c.any)
          diverge("anyOverlap result", c.any ? "yes" : "no", any ? "yes" : "no");
        break;
      }
      case CallKind::addResponse:
        world->addResponse(c.name, &rec::replayedResponse, &legs);
        break;
      case CallKind::batchStep: {
        batchMoves.clear();
        for (const rec::BodyOut& b : c.bodies) {
          // The file's budget was checked against the recording's positions; a world that has
          // diverged from them (a seek goes on past a divergence) may hold the body elsewhere,
          // and a batch body's search reads every cell of its start-to-goal box.
          const Rect S = world->rect(b.item);
          if (rec::cellCount(cellSize, unite(S, S.at(b.goal))) > options.maxCells) {
            in.fail("batch body " + labelOf(b.item) +
                    " would search more cells than the replay's budget from where the replayed "
                    "world holds it (it differs from the recording there)");
          }
          batchMoves.push_back({b.item, b.goal});
        }
        batch.step(*world, batchMoves, filter, c.maxEvents);
        for (std::size_t i = 0; i < c.bodies.size(); ++i) {
          const rec::BodyOut& b = c.bodies[i];
          const BatchOutcome o = batch.outcome(i);
          if (exact && compare) {
            const auto recorded =
                std::span<const Collision>(c.collisions).subspan(b.first, b.count);
            if (!sameMove(o.position, o.collisions, b.position, recorded)) {
              compareMove("body " + labelOf(b.item) + " ", o.position, o.collisions, b.position,
                          recorded);
            }
          } else if (!exact && report) {
            ++report->moves;
            const double distance = length(o.position - b.position);
            if (!same(o.position, b.position)) {
              report->differences.push_back(
                  {frame, index, b.item, b.position, o.position, distance, false, false, ItemId{}});
              if (!report->firstDifferentFrame) report->firstDifferentFrame = frame;
            }
            if (distance > farAway && !report->firstImplausibleFrame)
              report->firstImplausibleFrame = frame;
          }
        }
        break;
      }
      case CallKind::contacts: {
        if (!exact) break;
        const bool had = contactsSeen.count(c.item) > 0;
        std::span<const ContactEvent> got;
        if (c.forget) {
          got = contacts.forget(*world, c.item);
          contactsSeen.erase(c.item);
        } else {
          // What the move met in passing is in the recorded events (met), not in the call.
          contactsMet.clear();
          for (const ContactEvent& e : c.contacts) {
            if (!e.met || e.phase == ContactPhase::end) continue;
            Collision m;
            m.item = c.item;
            m.other = e.other;
            m.normal = e.normal;
            contactsMet.push_back(m);
          }
          ContactOptions o;
          o.filter = filter;
          got = contacts.update(*world, c.item, o, contactsMet);
          contactsSeen.insert(c.item);
        }
        if (!compare) break;
        // Without the body's history (a replay from a keyframe after its last update), only
        // what it touches now can be checked: the recorded begins and persists, as begins.
        const auto phaseName = [](ContactPhase p) {
          return p == ContactPhase::begin     ? "begin"
                 : p == ContactPhase::persist ? "persist"
                                              : "end";
        };
        const auto word = [&](const ContactEvent& e, bool withPhase) {
          return (withPhase ? std::string(phaseName(e.phase)) + " " : std::string()) +
                 labelOf(e.other) + " normal " + fmt(e.normal) + (e.met ? " met" : "");
        };
        std::vector<const ContactEvent*> expected;
        for (const ContactEvent& e : c.contacts) {
          if (had || c.forget ? true : e.phase != ContactPhase::end) expected.push_back(&e);
        }
        const bool phases = had;
        if (!had && c.forget) expected.clear();  // nothing to end in a replay without history
        if (got.size() != expected.size()) {
          diverge("contact events", std::to_string(expected.size()), std::to_string(got.size()));
          break;
        }
        for (std::size_t i = 0; i < got.size(); ++i) {
          const ContactEvent &g = got[i], &e = *expected[i];
          if (g.other != e.other || !same(g.normal, e.normal) || g.met != e.met ||
              (phases && g.phase != e.phase)) {
            diverge("contact event " + std::to_string(i), word(e, phases), word(g, phases));
            break;
          }
        }
        break;
      }
      case CallKind::cornerNudge: {
        // The World calls before this one made the correction, and were compared; this call says
        // they were one. The replayed world must give that nudge: the body, at the recorded
        // touch, on the ceiling's bottom edge, sticking out past the end it was nudged round by
        // exactly dx (tv::cornerNudgeDx, the rule moveCornered nudged by).
        if (!exact || !compare) break;
        const CornerNudge& n = c.nudge;
        const Rect ceiling = world->rect(n.hit.other);
        if (!rec::sameBits(n.hit.touch.y, ceiling.bottom())) {
          diverge("corner nudge: the ceiling's bottom", fmt(n.hit.touch.y), fmt(ceiling.bottom()));
          break;
        }
        const double dx = cornerNudgeDx(world->rect(c.item).at(n.hit.touch), ceiling);
        if (!rec::sameBits(dx, n.dx)) diverge("corner nudge dx", fmt(n.dx), fmt(dx));
        break;
      }
      case CallKind::label:
      case CallKind::advance:
        break;
    }
  } catch (const Error& e) {
    if (!exact) {
      if (report) ++report->failedCalls;
      return std::nullopt;
    }
    diverge("the call", "succeeded", std::string("refused: ") + e.what());
  }
  if (!compare || !exact) return std::nullopt;
  if (!rf.mismatch.empty()) diverge("filter", "not asked", rf.mismatch);
  if (legs.overrun || legs.next != c.legs.size()) {
    diverge("user response legs", std::to_string(c.legs.size()),
            legs.overrun ? "more" : std::to_string(legs.next));
  }
  return out;
}

// [SECTION] public
// ---------------------------------------------------------------------------------

void Replay::seek(std::uint64_t frame, std::uint32_t call) {
  Impl& d = *impl_;
  if (frame >= d.frames.size()) {
    fail("tv::Replay::seek", "frame " + std::to_string(frame) + " is past the last (" +
                                 std::to_string(d.frames.size() - 1) + ")");
  }
  const std::uint32_t target = std::min(call, d.frames[frame].calls);
  std::uint64_t from = 0;
  if (!d.whatIf() && !d.statefulMovers) {
    from = *(std::upper_bound(d.keyframes.begin(), d.keyframes.end(), frame) - 1);
  }
  // Forward within reach: go on from here rather than from the keyframe.
  const bool ahead = d.world && (frame > d.frame || (frame == d.frame && target >= d.callIndex));
  if (!(ahead && from <= d.frame)) d.enterFrame(from, true);
  while (d.frame < frame) {
    while (d.callIndex < d.frames[d.frame].calls) (void)d.execute(nullptr, false);
    d.enterFrame(d.frame + 1, false);
  }
  while (d.callIndex < target) (void)d.execute(nullptr, false);
  d.pendingDivergence.reset();
}

std::uint64_t Replay::seekStart(std::uint64_t frame) const {
  const Impl& d = *impl_;
  if (d.whatIf() || d.statefulMovers || d.keyframes.empty()) return 0;
  frame = std::min<std::uint64_t>(frame, d.frames.empty() ? 0 : d.frames.size() - 1);
  return *(std::upper_bound(d.keyframes.begin(), d.keyframes.end(), frame) - 1);
}

std::uint64_t Replay::frame() const {
  return impl_->frame;
}
std::uint32_t Replay::call() const {
  return impl_->callIndex;
}
std::optional<Ground> Replay::ground(ItemId id) const {
  const Impl& d = *impl_;
  if (d.whatIf() || d.contactsSeen.count(id) == 0) return std::nullopt;
  return d.contacts.ground(id);
}

const World& Replay::world() const {
  return *impl_->world;
}
bool Replay::cancelled() const {
  return impl_->cancelled;
}

bool Replay::atEnd() const {
  const Impl& d = *impl_;
  return d.frame + 1 >= d.frames.size() && d.callIndex >= d.frames[d.frame].calls;
}

std::optional<Divergence> Replay::step(MoveTrace* trace) {
  Impl& d = *impl_;
  if (d.callIndex >= d.frames[d.frame].calls) {
    if (d.frame + 1 >= d.frames.size()) return std::nullopt;
    d.enterFrame(d.frame + 1, false);
    if (d.pendingDivergence) {
      std::optional<Divergence> dv = std::move(d.pendingDivergence);
      d.pendingDivergence.reset();
      return dv;
    }
    if (d.frames[d.frame].calls == 0) return std::nullopt;
  }
  return d.execute(trace, true);
}

std::optional<Divergence> Replay::validate(const std::function<bool(std::uint64_t)>& progress,
                                           Tracing tracing) {
  Impl& d = *impl_;
  d.cancelled = false;
  const bool traced = tracing == Tracing::on;
  MoveTrace trace;
  d.restoreAtKeyframes = traced;
  struct Reset {
    Impl& d;
    ~Reset() { d.restoreAtKeyframes = false; }
  } reset{d};
  for (RecordedItem& r : d.items) r.endedOverlapping = 0;
  d.enterFrame(0, true);
  std::uint64_t reported = ~std::uint64_t{0};
  while (true) {
    if (progress && d.frame != reported) {
      reported = d.frame;
      if (!progress(d.frame)) {
        d.cancelled = true;
        return std::nullopt;
      }
    }
    if (atEnd()) return std::nullopt;
    trace.clear();
    if (std::optional<Divergence> dv = step(traced ? &trace : nullptr)) return dv;
  }
}

WhatIfReport Replay::checkRecorded() {
  Impl& d = *impl_;
  WhatIfReport report;
  // whatIf's first pass alone: the recorded calls replayed exactly, each move classified.
  struct Done {
    Replay::Impl& d;
    std::optional<MoverSpec> spec;
    ~Done() {
      d.report = nullptr;
      d.classifyRecorded = false;
      d.options.mover = spec;
    }
  } done{d, d.options.mover};
  d.report = &report;
  d.options.mover.reset();
  d.classifyRecorded = true;
  d.enterFrame(0, true);
  while (!atEnd()) (void)step(nullptr);
  return report;
}

WhatIfReport Replay::whatIf(double farAway) {
  Impl& d = *impl_;
  if (!d.whatIf()) fail("tv::Replay::whatIf", "no mover to re-run with: set ReplayOptions::mover");
  if (!(farAway >= 0) || !std::isfinite(farAway)) {
    fail("tv::Replay::whatIf", "farAway must be finite and >= 0, but was " + formatNumber(farAway));
  }
  WhatIfReport report;
  d.report = &report;
  d.farAway = farAway;
  struct Done {
    Replay::Impl& d;
    ~Done() {
      d.report = nullptr;
      d.classifyRecorded = false;
    }
  } done{d};
  // The recorded run first, classified the same way: what the what-if run is set against.
  const std::optional<MoverSpec> spec = d.options.mover;
  d.options.mover.reset();
  d.classifyRecorded = true;
  try {
    d.enterFrame(0, true);
    while (!atEnd()) (void)step(nullptr);
  } catch (...) {
    d.options.mover = spec;
    throw;
  }
  d.options.mover = spec;
  d.classifyRecorded = false;
  d.whatIfMover = std::make_unique<Mover>(*spec);
  d.enterFrame(0, true);
  while (!atEnd()) (void)step(nullptr);
  return report;
}

}  // namespace tv
