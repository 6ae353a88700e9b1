// Replay: open and index a recording (checksums, structure, totals), rebuild the world at any
// frame from its keyframe, re-execute calls and compare them with the recording bit for bit, or
// make the moves again with another mover (what-if, whatif.cpp).

#include "tv/record/replay.hpp"

#include <zlib.h>

#include <algorithm>
#include <bit>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <new>
#include <stdexcept>
#include <system_error>
#include <unordered_map>

#include "format.hpp"
#include "replay_impl.hpp"

namespace tv {

namespace {
// A frame's time for a person: 1/60 s reads 0.0166667, not 0.016666666666666666 (the value
// that reads back exactly belongs in the file, not in a summary line).
std::string readableSeconds(double s) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", s);
  return text;
}
}  // namespace

std::string Divergence::report() const {
  std::string s = "divergence at frame " + std::to_string(frame) + ", call " +
                  std::to_string(call) + " (" + std::string(callKindName(kind));
  if (!item.empty()) s += " " + item;
  s += ", byte " + std::to_string(offset) + ")\n";
  s += "  " + what + ": recorded " + expected + ", replayed " + got + "\n";
  return s;
}

// [SECTION] opening and indexing
// -------------------------------------------------------------------

namespace {

std::uint32_t le32(const std::uint8_t* p) {
  return std::uint32_t{p[0]} | std::uint32_t{p[1]} << 8 | std::uint32_t{p[2]} << 16 |
         std::uint32_t{p[3]} << 24;
}

[[noreturn]] void fileFail(std::uint64_t at, std::uint64_t frame, const std::string& what) {
  fail("tv::Replay",
       "byte " + std::to_string(at) + " (frame " + std::to_string(frame) + "): " + what);
}

}  // namespace

void Replay::Impl::index() {
  const std::size_t size = bytes.size();
  summary.bytes = size;
  if (size < rec::kHeaderSize) {
    fileFail(0, 0,
             "the file is " + std::to_string(size) + " bytes, shorter than the 32-byte header");
  }
  if (std::memcmp(bytes.data(), rec::kMagic, 8) != 0)
    fileFail(0, 0, "not a .tvrec file (wrong magic)");
  const unsigned major = unsigned{bytes[8]} | (unsigned{bytes[9]} << 8u);
  const unsigned minor = unsigned{bytes[10]} | (unsigned{bytes[11]} << 8u);
  if (major != rec::kVersionMajor) {
    fileFail(8, 0,
             "format version " + std::to_string(major) + "." + std::to_string(minor) +
                 " is not readable by this reader (version " + std::to_string(rec::kVersionMajor) +
                 "." + std::to_string(rec::kVersionMinor) + ")");
  }
  if (le32(bytes.data() + 28) != static_cast<std::uint32_t>(::crc32(0, bytes.data(), 28))) {
    fileFail(28, 0, "header checksum mismatch");
  }
  std::uint64_t cs = 0;
  for (std::size_t i = 0; i < 8; ++i) cs |= std::uint64_t{bytes[12 + i]} << (8 * i);
  cellSize = std::bit_cast<double>(cs);
  if (!std::isfinite(cellSize) || !(cellSize > 0)) {
    fileFail(12, 0, "cell size " + formatNumber(cellSize) + " is not finite and > 0");
  }
  keyframeEvery = le32(bytes.data() + 20);
  if (keyframeEvery < 1 || keyframeEvery > (1u << 20)) {
    fileFail(20, 0, "keyframe interval " + std::to_string(keyframeEvery) + " is outside [1, 2^20]");
  }
  if (le32(bytes.data() + 24) != 0) fileFail(24, 0, "unknown header flags");
  model.cellSize = cellSize;
  fileBuiltins = rec::builtinsOf(minor);
  model.fileBuiltins = fileBuiltins;

  rec::Model m;
  m.cellSize = cellSize;
  m.fileBuiltins = fileBuiltins;
  rec::Call c;
  WorldState ws;
  std::size_t pos = rec::kHeaderSize;
  bool ended = false;
  std::unordered_map<ItemId, std::vector<std::pair<ResponseId, std::uint64_t>>> answerCounts;
  while (pos < size) {
    const std::uint64_t f = frames.size();
    if (size - pos < 8) {
      warnings.push_back("frame " + std::to_string(f) + " at byte " + std::to_string(pos) +
                         " is cut (" + std::to_string(size - pos) +
                         " bytes of its chunk header): replaying up to frame " +
                         std::to_string(f == 0 ? 0 : f - 1));
      summary.damagedAt = pos;
      break;
    }
    const std::uint32_t len = le32(bytes.data() + pos), crc = le32(bytes.data() + pos + 4);
    if (len == 0 && crc == rec::kEndMark) {
      ended = true;
      if (pos + 8 != size) {
        const std::string what = std::to_string(size - pos - 8) + " bytes after the end mark";
        if (!options.tolerant) fileFail(pos + 8, f, what);
        warnings.push_back(what + " (byte " + std::to_string(pos + 8) + ") ignored");
      }
      break;
    }
    if (len > rec::kMaxChunk || len > size - pos - 8) {
      if (len <= rec::kMaxChunk || pos + 8 + 64 > size) {
        warnings.push_back("frame " + std::to_string(f) + " at byte " + std::to_string(pos) +
                           " is cut (" + std::to_string(size - pos - 8) + " of its " +
                           std::to_string(len) + " bytes): replaying up to frame " +
                           std::to_string(f == 0 ? 0 : f - 1));
        summary.damagedAt = pos;
        break;
      }
      const std::string what = "chunk length " + std::to_string(len) + " is over the 2^30 limit";
      if (!options.tolerant) fileFail(pos, f, what);
      warnings.push_back("byte " + std::to_string(pos) + " (frame " + std::to_string(f) +
                         "): " + what + "; stopped there");
      summary.damagedAt = pos;
      break;
    }
    const std::uint8_t* payload = bytes.data() + pos + 8;
    if (static_cast<std::uint32_t>(::crc32(0, payload, len)) != crc) {
      const std::string what = "checksum mismatch in frame " + std::to_string(f) + "'s chunk";
      if (!options.tolerant) fileFail(pos, f, what);
      warnings.push_back("byte " + std::to_string(pos) + ": " + what + "; stopped there");
      summary.damagedAt = pos;
      break;
    }
    FrameInfo info;
    info.offset = pos + 8;
    info.size = len;
    try {
      rec::In src(payload, len, pos + 8, f);
      info.keyframe = beginFrame(src, m, ws, f);
      if (info.keyframe) {
        keyframes.push_back(f);
        ++summary.keyframes;
        if (f == 0) {
          for (std::uint32_t i = 0; i < ws.slots.size(); ++i) {
            if (ws.slots[i].alive) itemFor({i, ws.slots[i].generation}, 0);
          }
        }
      }
      while (!src.done()) {
        rec::decodeCall(src, m, c, options.maxCells);
        ++info.calls;
        // A pixel mover keeps sub-pixel remainders that no keyframe holds: seek from frame 0.
        if (c.kind == CallKind::moverMove && m.movers[c.mover].kind == MoverKind::pixel) {
          statefulMovers = true;
        }
        tally(c, f, answerCounts);
      }
    } catch (const Error& e) {
      if (!options.tolerant) throw;
      warnings.push_back(std::string(e.what()) + "; stopped before that frame");
      summary.damagedAt = pos;
      break;
    }
    frames.push_back(info);
    pos += 8 + len;
  }
  summary.bytesRead = pos;
  summary.closed = ended;
  if (!ended && (warnings.empty())) {
    warnings.push_back("the recording has no end mark: the game stopped without closing it");
  }
  if (frames.empty()) {
    fileFail(rec::kHeaderSize, 0, "the recording holds no whole frame");
  }
  summary.frames = frames.size();
  for (std::size_t k = 0; k < items.size(); ++k) items[k].maxSpeed = length(longest[k].d);
  for (auto& [id, counts] : answerCounts) {
    const auto best =
        std::max_element(counts.begin(), counts.end(), [](const auto& a, const auto& b) {
          return a.second < b.second || (a.second == b.second && a.first > b.first);
        });
    commonAnswer[id] = best->first;
  }
}

bool Replay::Impl::beginFrame(rec::In& src, rec::Model& m, WorldState& ws, std::uint64_t f) {
  const std::uint64_t at = src.offset();
  const std::uint64_t n = src.varint("frame number");
  if (n != f)
    src.failAt(
        at, "frame number " + std::to_string(n) + " where frame " + std::to_string(f) + " was due");
  const std::uint8_t flags = src.u8("frame flags");
  if (flags > 1) src.fail("frame flags " + std::to_string(flags) + " are not defined");
  if (f == 0 && flags == 0) src.fail("frame 0 does not open with a keyframe");
  if (flags) rec::decodeKeyframe(src, m, ws, options.maxCells);
  return flags;
}

std::size_t Replay::Impl::itemFor(ItemId id, std::uint64_t when) {
  // Most calls name the item their slot held last time: no hashing.
  if (id.index < slotItem.size() && slotItem[id.index] != 0) {
    const std::size_t k = slotItem[id.index] - 1;
    if (items[k].id == id) [[likely]] {
      items[k].lastFrame = std::max(items[k].lastFrame, when);
      return k;
    }
  }
  auto [it, fresh] = itemIndex.try_emplace(id, items.size());
  if (fresh) {
    RecordedItem r;
    r.id = id;
    r.firstFrame = r.lastFrame = when;
    items.push_back(r);
    longest.push_back({});
    isMoving.push_back(false);
  }
  if (id.index >= slotItem.size()) slotItem.resize(std::size_t{id.index} + 1, 0);
  slotItem[id.index] = static_cast<std::uint32_t>(it->second + 1);
  RecordedItem& r = items[it->second];
  r.lastFrame = std::max(r.lastFrame, when);
  return it->second;
}

void Replay::Impl::markMoving(std::size_t k) {
  if (isMoving[k]) return;
  isMoving[k] = true;
  moving.insert(items[k].id);
}

void Replay::Impl::moveLength(std::size_t k, Vec2 d) {
  // The longest move by its squared length; its length (hypot) once, when the index is done.
  const double sq = d.x * d.x + d.y * d.y;
  Longest& l = longest[k];
  if (std::isfinite(sq) && std::isfinite(l.sq)) {
    if (sq > l.sq) l = {sq, d};
  } else if (length(d) > length(l.d)) {
    l = {sq, d};
  }
}

void Replay::Impl::tally(
    const rec::Call& c, std::uint64_t f,
    std::unordered_map<ItemId, std::vector<std::pair<ResponseId, std::uint64_t>>>& answers) {
  switch (callRole(c.kind)) {
    case CallRole::note:
      if (c.kind == CallKind::label) labels[c.item] = {c.name, c.category};
      if (c.kind == CallKind::cornerNudge) ++items[itemFor(c.item, f)].nudges;
      return;
    case CallRole::move: {
      ++summary.moves;
      const std::size_t k = itemFor(c.item, f);
      markMoving(k);
      RecordedItem& r = items[k];
      ++r.moves;
      r.hits += c.collisions.size();
      moveLength(k, c.position - c.start.position());
      break;
    }
    case CallRole::batch:
      summary.moves += c.bodies.size();
      for (const rec::BodyOut& b : c.bodies) {
        const std::size_t k = itemFor(b.item, f);
        markMoving(k);
        RecordedItem& r = items[k];
        ++r.moves;
        r.hits += b.count;
        moveLength(k, b.position - b.start.position());
      }
      break;
    case CallRole::item: {
      const std::size_t k = itemFor(c.item, f);
      if (c.kind == CallKind::update && !(c.rect == c.start)) {
        markMoving(k);
        ++items[k].updates;
      }
      break;
    }
    case CallRole::sweep:
    case CallRole::query:
    case CallRole::setup:
      ++summary.queries;
      if (c.item.valid()) itemFor(c.item, f);
      break;
  }
  ++summary.calls;
  summary.collisions += c.collisions.size();
  for (const rec::Answer& a : c.answers) {
    if (!a.item.valid()) continue;
    auto& v = answers[a.item];
    auto it =
        std::find_if(v.begin(), v.end(), [&](const auto& p) { return p.first == a.response; });
    if (it == v.end()) {
      v.emplace_back(a.response, 1);
    } else {
      ++it->second;
    }
  }
}

Replay::Replay(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Replay::Replay(Replay&&) noexcept = default;
Replay& Replay::operator=(Replay&&) noexcept = default;
Replay::~Replay() = default;

Replay Replay::open(const std::string& path, ReplayOptions options) {
  namespace fs = std::filesystem;
  const auto refuse = [&path](const std::string& why) {
    fail("tv::Replay", "cannot open '" + path + "': " + why);
  };
  // The file is read whole, by the size the file system gives. A directory opens as a stream
  // on Linux and reports a size of 2^63 - 1 (an allocation that throws bad_alloc), and a pipe or
  // a device has no size at all: only a regular file is read.
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  // (A path that cannot be looked at is left to the open below, which names the system's reason.)
  if (!ec && st.type() == fs::file_type::directory) refuse("is a directory, not a recording");
  if (!ec && st.type() != fs::file_type::regular) {
    const char* kind = st.type() == fs::file_type::fifo        ? "a pipe (FIFO)"
                       : st.type() == fs::file_type::character ? "a character device"
                       : st.type() == fs::file_type::block     ? "a block device"
                       : st.type() == fs::file_type::socket    ? "a socket"
                                                               : "a special file";
    refuse(std::string(kind) + ", not a recording file (save the stream to a file first)");
  }
  errno = 0;
  std::ifstream f(path, std::ios::binary | std::ios::ate);
  // The system's reason (no such file, permission denied) is what the user fixes.
  if (!f) {
    const int why = errno;
    fail("tv::Replay", "cannot open '" + path + "'" + (why ? std::string(": ") + std::strerror(why)
                                                           : std::string()));
  }
  const auto cannotRead = [&path]() {
    const int why = errno;
    fail("tv::Replay", "cannot read '" + path + "'" + (why ? std::string(": ") + std::strerror(why)
                                                           : std::string()));
  };
  const std::streamoff n = f.tellg();
  if (n < 0) cannotRead();
  std::vector<std::uint8_t> bytes;
  try {
    bytes.resize(static_cast<std::size_t>(n));
  } catch (const std::bad_alloc&) {
    refuse(std::to_string(n) + " bytes, more than this machine can hold in memory");
  } catch (const std::length_error&) {
    refuse(std::to_string(n) + " bytes, more than this machine can hold in memory");
  }
  f.seekg(0);
  errno = 0;
  if (n > 0 && !f.read(reinterpret_cast<char*>(bytes.data()), n)) cannotRead();
  return fromBytes(std::move(bytes), options);
}

Replay Replay::fromBytes(std::vector<std::uint8_t> bytes, ReplayOptions options) {
  if (options.mover) {
    const Mover check(*options.mover);  // throws on a bad spec
  }
  auto impl = std::make_unique<Impl>();
  impl->bytes = std::move(bytes);
  impl->options = options;
  if (options.mover) impl->whatIfMover = std::make_unique<Mover>(*options.mover);
  impl->index();
  Replay r(std::move(impl));
  r.seek(0, 0);
  return r;
}

// [SECTION] what is in it
// --------------------------------------------------------------------------

std::uint64_t Replay::frames() const {
  return impl_->frames.size();
}
double Replay::cellSize() const {
  return impl_->cellSize;
}
std::uint64_t Replay::fileSize() const {
  return impl_->bytes.size();
}
std::span<const std::string> Replay::warnings() const {
  return impl_->warnings;
}
std::span<const RecordedItem> Replay::items() const {
  for (RecordedItem& r : impl_->items) {
    auto it = impl_->labels.find(r.id);
    if (it != impl_->labels.end()) {
      r.label = it->second.first;
      r.category = it->second.second;
    } else {
      r.label = label(r.id);
    }
  }
  return impl_->items;
}
const ReplayOptions& Replay::options() const {
  return impl_->options;
}
const ReplaySummary& Replay::summary() const {
  return impl_->summary;
}
std::uint32_t Replay::callCount(std::uint64_t frame) const {
  if (frame >= impl_->frames.size()) {
    fail("tv::Replay::callCount", "frame " + std::to_string(frame) + " is past the last (" +
                                      std::to_string(impl_->frames.size() - 1) + ")");
  }
  return impl_->frames[frame].calls;
}

std::string Replay::label(ItemId id) const {
  return impl_->labelOf(id);
}

std::string Replay::Impl::labelOf(ItemId id) const {
  if (!id.valid()) return {};
  auto it = labels.find(id);
  if (it != labels.end() && !it->second.first.empty()) return it->second.first;
  return "item " + std::to_string(id.index) + "." + std::to_string(id.generation);
}

std::string Replay::category(ItemId id) const {
  auto it = impl_->labels.find(id);
  return it == impl_->labels.end() ? std::string{} : it->second.second;
}

namespace {

std::string fmt(Vec2 v) {
  std::string s = "(";
  s += formatNumber(v.x);
  s += ", ";
  s += formatNumber(v.y);
  s += ")";
  return s;
}

}  // namespace

std::vector<CallInfo> Replay::calls(std::uint64_t frame) const {
  const Impl& d = *impl_;
  if (frame >= d.frames.size()) {
    fail("tv::Replay::calls", "frame " + std::to_string(frame) + " is past the last (" +
                                  std::to_string(d.frames.size() - 1) + ")");
  }
  if (d.callsFrame == frame) return d.callsCache;
  // Decode from the nearest keyframe: the model (not the world) gives each call's context.
  const auto kf = std::upper_bound(d.keyframes.begin(), d.keyframes.end(), frame);
  const std::uint64_t from = *(kf - 1);
  rec::Model m;
  m.cellSize = d.cellSize;
  m.fileBuiltins = d.fileBuiltins;
  WorldState ws;
  rec::Call c;
  std::vector<CallInfo> out;
  for (std::uint64_t f = from; f <= frame; ++f) {
    const FrameInfo& fi = d.frames[f];
    rec::In in(d.bytes.data() + fi.offset, fi.size, fi.offset, f);
    const_cast<Impl&>(d).beginFrame(in, m, ws, f);
    std::uint32_t index = 0;
    while (!in.done()) {
      rec::decodeCall(in, m, c, d.options.maxCells);
      if (f == frame) {
        CallInfo info;
        info.kind = c.kind;
        info.frame = f;
        info.index = index;
        info.item = c.item;
        info.offset = c.offset;
        const std::string name = std::string(callKindName(c.kind));
        const std::string who = d.labelOf(c.item);
        switch (c.kind) {
          case CallKind::move:
          case CallKind::check:
          case CallKind::moverMove:
          case CallKind::project:
            info.start = c.start;
            info.goal = c.goal;
            info.position = c.position;
            info.hits = static_cast<std::uint32_t>(c.collisions.size());
            if (c.kind == CallKind::moverMove) info.mover = m.movers[c.mover].name();
            info.summary =
                (c.kind == CallKind::moverMove ? info.mover + " move" : name) +
                (who.empty() ? "" : " " + who) + " " + fmt(c.start.position()) + " -> " +
                fmt(c.goal) + ": " +
                (info.hits ? std::to_string(info.hits) + (info.hits == 1 ? " hit" : " hits")
                           : "free") +
                (c.position == c.goal ? "" : ", ended at " + fmt(c.position));
            break;
          case CallKind::batchStep:
            info.hits = static_cast<std::uint32_t>(c.collisions.size());
            info.summary = "batch of " + std::to_string(c.bodies.size()) +
                           " moves: " + std::to_string(info.hits) + " hits";
            break;
          case CallKind::queryRect:
          case CallKind::queryPoint:
            info.hits = static_cast<std::uint32_t>(c.found.size());
            info.summary = name + ": " + std::to_string(info.hits) + " found";
            break;
          case CallKind::querySegment:
            info.hits = static_cast<std::uint32_t>(c.segment.size());
            info.summary = name + " " + fmt(c.goal) + " -> " + fmt(c.b) + ": " +
                           std::to_string(info.hits) + " crossed";
            break;
          case CallKind::anyOverlap:
            info.hits = c.any ? 1 : 0;
            info.summary = name + (who.empty() ? "" : " " + who) + ": " + (c.any ? "yes" : "no");
            break;
          case CallKind::add:
          case CallKind::update:
            info.start = c.start;
            info.position = c.rect.position();
            info.summary = name + " " + who + " {" + formatNumber(c.rect.x) + ", " +
                           formatNumber(c.rect.y) + ", " + formatNumber(c.rect.w) + ", " +
                           formatNumber(c.rect.h) + "}";
            break;
          case CallKind::remove:
            info.summary = name + " " + who;
            break;
          case CallKind::addResponse:
            info.summary = name + " '" + c.name + "'";
            break;
          case CallKind::label:
            info.summary = "label item " + std::to_string(c.item.index) + "." +
                           std::to_string(c.item.generation) + " '" + c.name + "'" +
                           (c.category.empty() ? "" : " (" + c.category + ")");
            break;
          case CallKind::contacts: {
            std::size_t begins = 0, ends = 0;
            for (const ContactEvent& e : c.contacts) {
              begins += e.phase == ContactPhase::begin;
              ends += e.phase == ContactPhase::end;
            }
            info.hits = static_cast<std::uint32_t>(c.contacts.size());
            info.contacts = c.contacts;
            info.summary = std::string(c.forget ? "Contacts::forget " : "Contacts::update ") + who +
                           ": " + std::to_string(begins) + " begin, " +
                           std::to_string(c.contacts.size() - begins - ends) + " persist, " +
                           std::to_string(ends) + " end";
            break;
          }
          case CallKind::cornerNudge:
            info.start = c.nudge.hit.itemRect;
            info.position = {c.nudge.hit.touch.x + c.nudge.dx, c.nudge.hit.touch.y};
            info.nudge = c.nudge;
            info.summary = "moveCornered " + who + ": nudged " + formatNumber(c.nudge.dx) +
                           " round the corner of " + d.labelOf(c.nudge.hit.other) + " at " +
                           fmt(c.nudge.hit.touch);
            break;
          case CallKind::advance:
            info.summary = "advance " + readableSeconds(c.frameTime) +
                           " s: " + std::to_string(c.ticks) + " ticks";
            break;
        }
        out.push_back(std::move(info));
      }
      ++index;
    }
  }
  impl_->callsFrame = frame;
  impl_->callsCache = out;
  return out;
}

}  // namespace tv
