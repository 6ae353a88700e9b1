// The recorder's writer (writer.hpp): capture records in, whole chunks out.

#include "writer.hpp"

#include <zlib.h>

#include <cerrno>
#include <cstring>

#include "live_out.hpp"

namespace tv::rec {

Writer::Writer(std::uint32_t keyframeEvery, std::FILE* file, std::string path,
               std::vector<std::uint8_t>* memory, LiveOut* live)
    : keyframeEvery_(keyframeEvery),
      file_(file),
      path_(std::move(path)),
      memory_(memory),
      live_(live) {}

Writer::~Writer() {
  if (file_) std::fclose(file_);
}

std::string Writer::error() const {
  std::lock_guard lock(errorMutex_);
  return error_;
}

void Writer::fail(std::string message) {
  {
    std::lock_guard lock(errorMutex_);
    if (error_.empty()) error_ = std::move(message);
  }
  stopped_ = true;
  failed_.store(true, std::memory_order_release);
}

void Writer::out(const std::uint8_t* data, std::size_t n) {
  if (file_) {
    if (std::fwrite(data, 1, n, file_) != n) {
      fail("tv::Recorder: writing '" + path_ + "' failed: " + std::strerror(errno));
      return;
    }
  }
  if (memory_) memory_->insert(memory_->end(), data, data + n);
  size_.fetch_add(n, std::memory_order_release);
}

void Writer::header(double cellSize) {
  const std::array<std::uint8_t, kHeaderSize> h = fileHeader(cellSize, keyframeEvery_);
  out(h.data(), h.size());
  if (live_) live_->header(h);
}

void Writer::beginFrame(std::uint8_t flags, WorldState* state) {
  Out& o = enc_.out;
  o.clear();
  o.reserve(lastPayload_ + lastPayload_ / 4 + 256);  // the next frame is likely as big: grow once
  o.varint(frame_);
  o.u8(state ? 1 : 0);
  if (state) {
    enc_.keyframe(*state);
    defined_.assign(specs_.size(), false);
    if (live_) live_->keyframe(frame_, o.size(), (flags & kNoLiveStart) == 0);
  }
}

void Writer::endFrame() {
  const Out& o = enc_.out;
  const auto len = static_cast<std::uint32_t>(o.size());
  const auto crc = static_cast<std::uint32_t>(::crc32(0, o.data(), static_cast<uInt>(len)));
  std::uint8_t head[8];
  for (int i = 0; i < 4; ++i) {
    head[i] = static_cast<std::uint8_t>(len >> (8 * i));
    head[4 + i] = static_cast<std::uint8_t>(crc >> (8 * i));
  }
  out(head, 8);
  out(o.data(), o.size());
  if (file_ && !stopped_ && std::fflush(file_) != 0) {
    fail("tv::Recorder: writing '" + path_ + "' failed: " + std::strerror(errno));
  }
  if (live_) live_->chunk(frame_, head, {o.data(), o.size()}, enc_.model);
  lastPayload_ = o.size();
  written_.fetch_add(1, std::memory_order_release);
}

bool Writer::tracks(ItemId id) const {
  return id.index < enc_.model.slots.size() && enc_.model.slots[id.index].alive;
}

void Writer::consume(const Block& block) {
  const std::byte* p = block.data.get();
  const std::byte* end = p + block.used;
  while (p < end) {
    Head h;
    std::memcpy(&h, p, sizeof h);
    if (!stopped_) {
      try {
        record(p);
      } catch (const std::exception& e) {  // out of memory: the recording stops, the game goes on
        fail(std::string("tv::Recorder: ") + e.what());
      }
    } else if (h.tag == Tag::start || h.tag == Tag::frame) {
      RecordReader r(p);
      delete r.body<StateRec>().state;
    }
    p += h.bytes;
  }
}

void Writer::record(const std::byte* p) {
  Head h;
  std::memcpy(&h, p, sizeof h);
  RecordReader r(p);
  Encoder& e = enc_;
  const auto lost = [&](ItemId id) {
    fail("tv::Recorder: lost track of the world's item " + std::to_string(id.index) + "." +
         std::to_string(id.generation));
  };
  switch (h.tag) {
    case Tag::start: {
      const StateRec s = r.body<StateRec>();
      std::unique_ptr<WorldState> state(s.state);
      started_ = true;
      e.model.cellSize = s.cellSize;
      header(s.cellSize);
      frame_ = 0;
      beginFrame(h.flag, state.get());
      return;
    }
    case Tag::frame: {
      const StateRec s = r.body<StateRec>();
      std::unique_ptr<WorldState> state(s.state);
      if (!started_) return;
      endFrame();
      ++frame_;
      beginFrame(h.flag, state.get());
      return;
    }
    case Tag::close: {
      if (!started_) return;
      endFrame();
      std::uint8_t endMark[8] = {0, 0, 0, 0};
      for (int i = 0; i < 4; ++i) endMark[4 + i] = static_cast<std::uint8_t>(kEndMark >> (8 * i));
      out(endMark, 8);
      if (live_) live_->end(endMark);
      stopped_ = true;
      if (file_) {
        const int rc = std::fclose(file_);
        file_ = nullptr;
        if (rc != 0) fail("tv::Recorder: closing '" + path_ + "' failed: " + std::strerror(errno));
      }
      return;
    }
    case Tag::moverSpec: {
      const SpecRec s = r.body<SpecRec>();
      if (s.id >= specs_.size()) {
        specs_.resize(s.id + 1);
        defined_.resize(s.id + 1, false);
      }
      specs_[s.id] = s.spec;
      defined_[s.id] = false;
      return;
    }
    case Tag::add: {
      const ItemRectRec a = r.body<ItemRectRec>();
      const std::size_t expect =
          e.model.freeSlots.empty() ? e.model.slots.size() : e.model.freeSlots.back();
      if (a.id.index != expect) {
        fail("tv::Recorder: lost track of the world's slots (add returned " +
             std::to_string(a.id.index) + ", expected " + std::to_string(expect) + ")");
        return;
      }
      e.add(a.id, a.rect);
      return;
    }
    case Tag::remove: {
      const ItemRectRec a = r.body<ItemRectRec>();
      if (!tracks(a.id)) return lost(a.id);
      e.remove(a.id);
      if (live_) live_->removed(a.id);
      return;
    }
    case Tag::update: {
      const ItemRectRec a = r.body<ItemRectRec>();
      if (!tracks(a.id)) return lost(a.id);
      e.update(a.id, a.rect);
      return;
    }
    case Tag::move:
    case Tag::check:
    case Tag::project:
    case Tag::moverMove: {
      const MoveRec m = r.body<MoveRec>();
      const auto cs = r.array<Collision>(m.collisions);
      const auto as = r.array<Answer>(m.answers);
      const auto ls = r.array<Leg>(m.legs);
      const MoveResult result{m.position, cs};
      if (h.tag == Tag::project) {
        MoveOptions o;
        o.broad = m.broad;
        o.maxResponses = m.maxResponses;
        o.semantics = m.semantics;
        e.project(m.rect, m.goal, o, result, as, ls);
        return;
      }
      if (!tracks(m.id)) return lost(m.id);
      if (h.tag == Tag::moverMove) {
        if (m.mover >= specs_.size()) return fail("tv::Recorder: a mover without its spec");
        if (!(e.model.slots[m.id.index].rect == m.rect)) {
          return fail("tv::Recorder: lost track of item " + std::to_string(m.id.index) +
                      "'s position");
        }
        const bool define = !defined_[m.mover];
        defined_[m.mover] = true;
        e.moverMove(m.mover, define, specs_[m.mover], m.id, m.rect, m.goal, result, as, ls);
        return;
      }
      MoveOptions o;
      o.broad = m.broad;
      o.maxResponses = m.maxResponses;
      o.semantics = m.semantics;
      e.move(h.tag == Tag::move ? CallKind::move : CallKind::check, m.id, m.goal, o, result, as,
             ls);
      return;
    }
    case Tag::queryRect:
    case Tag::queryPoint:
    case Tag::anyOverlap: {
      const QueryRec q = r.body<QueryRec>();
      const auto found = r.array<ItemId>(q.found);
      const auto as = r.array<Answer>(q.answers);
      if (q.skip.valid() && !tracks(q.skip)) return lost(q.skip);
      if (h.tag == Tag::queryRect) {
        e.queryRect(q.rect, q.skip, found);
      } else if (h.tag == Tag::queryPoint) {
        e.queryPoint(q.a, found);
      } else {
        e.anyOverlap(q.rect, q.skip, q.any, as);
      }
      return;
    }
    case Tag::querySegment: {
      const QueryRec q = r.body<QueryRec>();
      e.querySegment(q.a, q.b, r.array<SegmentHit>(q.found));
      return;
    }
    case Tag::addResponse: {
      const TextRec t = r.body<TextRec>();
      e.addResponse(r.text(t.a));
      return;
    }
    case Tag::label: {
      const TextRec t = r.body<TextRec>();
      const std::string_view label = r.text(t.a), category = r.text(t.b);
      e.label(t.id, label, category);
      if (live_) live_->label(t.id, label, category);
      return;
    }
    case Tag::contacts: {
      const ContactsRec c = r.body<ContactsRec>();
      const auto events = r.array<ContactEvent>(c.events);
      const auto as = r.array<Answer>(c.answers);
      if (!c.forget && !tracks(c.id)) return lost(c.id);
      e.contacts(c.id, c.forget, events, as);
      return;
    }
    case Tag::cornerNudge: {
      const NudgeRec n = r.body<NudgeRec>();
      if (!tracks(n.id)) return lost(n.id);
      if (!tracks(n.ceiling)) return lost(n.ceiling);
      e.cornerNudge(n.id, n.ceiling, n.touch, n.dx);
      return;
    }
    case Tag::advance: {
      const AdvanceRec a = r.body<AdvanceRec>();
      e.advance(a.frameTime, a.ticks);
      return;
    }
    case Tag::batchStep: {
      const BatchRec b = r.body<BatchRec>();
      const auto moves = r.array<BatchMove>(b.moves);
      const auto bodies = r.array<BodyRec>(b.moves);
      const auto cs = r.array<Collision>(b.collisions);
      const auto as = r.array<Answer>(b.answers);
      const auto ls = r.array<Leg>(b.legs);
      for (const BatchMove& m : moves) {
        if (!tracks(m.item)) return lost(m.item);
      }
      outcomes_.clear();
      for (const BodyRec& body : bodies) {
        outcomes_.push_back({body.position, cs.subspan(body.first, body.count)});
      }
      e.batch(moves, b.maxEvents, outcomes_, as, ls);
      return;
    }
  }
}

}  // namespace tv::rec
