// Reading a live stream as it arrives (stream_reader.hpp).

#include "stream_reader.hpp"

#include <zlib.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>

namespace tv::rec {

namespace {

std::uint32_t le32(const std::uint8_t* p) {
  return std::uint32_t{p[0]} | std::uint32_t{p[1]} << 8 | std::uint32_t{p[2]} << 16 |
         std::uint32_t{p[3]} << 24;
}

[[noreturn]] void streamFail(std::uint64_t at, std::uint64_t frame, const std::string& what) {
  fail("tv live stream",
       "byte " + std::to_string(at) + " (frame " + std::to_string(frame) + "): " + what);
}

}  // namespace

HeaderInfo readHeader(const std::uint8_t* h, std::size_t size) {
  const auto bad = [](std::uint64_t at, const std::string& what) {
    fail("tv::Replay", "byte " + std::to_string(at) + " (frame 0): " + what);
  };
  if (size < kHeaderSize) {
    bad(0, "the file is " + std::to_string(size) + " bytes, shorter than the 32-byte header");
  }
  if (std::memcmp(h, kMagic, 8) != 0) bad(0, "not a .tvrec file (wrong magic)");
  const unsigned major = unsigned{h[8]} | (unsigned{h[9]} << 8u);
  const unsigned minor = unsigned{h[10]} | (unsigned{h[11]} << 8u);
  if (major != kVersionMajor) {
    bad(8, "format version " + std::to_string(major) + "." + std::to_string(minor) +
               " is not readable by this reader (version " + std::to_string(kVersionMajor) + "." +
               std::to_string(kVersionMinor) + ")");
  }
  if (le32(h + 28) != static_cast<std::uint32_t>(::crc32(0, h, 28))) {
    bad(28, "header checksum mismatch");
  }
  HeaderInfo info;
  info.minorVersion = minor;
  std::uint64_t cs = 0;
  for (std::size_t i = 0; i < 8; ++i) cs |= std::uint64_t{h[12 + i]} << (8 * i);
  info.cellSize = std::bit_cast<double>(cs);
  if (!std::isfinite(info.cellSize) || !(info.cellSize > 0)) {
    bad(12, "cell size " + formatNumber(info.cellSize) + " is not finite and > 0");
  }
  info.keyframeEvery = le32(h + 20);
  if (info.keyframeEvery < 1 || info.keyframeEvery > (1u << 20)) {
    bad(20, "keyframe interval " + std::to_string(info.keyframeEvery) + " is outside [1, 2^20]");
  }
  if (le32(h + 24) != 0) bad(24, "unknown header flags");
  return info;
}

std::vector<std::uint8_t> renumberChunk(std::span<const std::uint8_t> payload, std::uint64_t number,
                                        std::span<const std::uint8_t> extra, std::size_t insertAt) {
  std::size_t skip = 0;
  while (skip < payload.size() && (payload[skip] & 0x80)) ++skip;
  ++skip;  // the old frame number: a well-formed varint (the chunk was checked, or ours)
  Out p;
  p.reserve(payload.size() + extra.size() + 24);
  for (int i = 0; i < 8; ++i) p.u8(0);  // the head, filled in below
  p.varint(number);
  if (!extra.empty() && insertAt >= skip && insertAt <= payload.size()) {
    p.raw(payload.data() + skip, insertAt - skip);
    p.raw(extra.data(), extra.size());
    p.raw(payload.data() + insertAt, payload.size() - insertAt);
  } else {
    p.raw(payload.data() + skip, payload.size() - skip);
  }
  std::vector<std::uint8_t> out = p.bytes();
  const auto len = static_cast<std::uint32_t>(out.size() - 8);
  const auto crc = static_cast<std::uint32_t>(::crc32(0, out.data() + 8, static_cast<uInt>(len)));
  for (std::size_t i = 0; i < 4; ++i) {
    out[i] = static_cast<std::uint8_t>(len >> (8 * i));
    out[4 + i] = static_cast<std::uint8_t>(crc >> (8 * i));
  }
  return out;
}

void writeLabel(Out& out, ItemId id, std::string_view label, std::string_view category) {
  out.u8(static_cast<std::uint8_t>(CallKind::label));
  out.varint(id.index);
  out.varint(id.generation);
  out.str(label.substr(0, kMaxName));
  out.str(category.substr(0, kMaxName));
}

std::string StreamReader::awaiting() const {
  const auto of = [&](const char* what) {
    return std::string(what) + " (" + std::to_string(buf_.size()) + " of " + std::to_string(need_) +
           " bytes)";
  };
  switch (want_) {
    case Want::hello:
      return of("the game's hello");
    case Want::header:
      return of("the recording's header");
    case Want::chunkHead:
      return of(("frame " + std::to_string(frame_) + "'s chunk head").c_str());
    case Want::payload:
      return of(("frame " + std::to_string(frame_) + "'s chunk").c_str());
    case Want::done:
      return "nothing (the recording ended)";
  }
  return {};
}

void StreamReader::feed(const std::uint8_t* data, std::size_t n, Sink& sink) {
  while (n > 0) {
    if (want_ == Want::done) {
      streamFail(offset_, frame_, std::to_string(n) + " bytes after the end mark");
    }
    const std::size_t take = std::min(n, need_ - buf_.size());
    buf_.insert(buf_.end(), data, data + take);
    data += take;
    n -= take;
    if (buf_.size() == need_) {
      item(sink);
    }
  }
}

void StreamReader::item(Sink& sink) {
  switch (want_) {
    case Want::hello: {
      if (std::memcmp(buf_.data(), kLiveHello, 6) != 0 || buf_[6] != 0) {
        fail("tv live stream",
             "the peer is not a tunnelvision game (its first bytes are not a "
             "live stream's hello)");
      }
      if (buf_[7] != kLiveHello[7]) {
        fail("tv live stream", "the game speaks live protocol " + std::to_string(buf_[7]) +
                                   ", this receiver " + std::to_string(kLiveHello[7]));
      }
      const std::uint32_t flags = le32(buf_.data() + 8);
      if ((flags & ~kHelloControl) != 0 || le32(buf_.data() + 12) != 0) {
        fail("tv live stream", "the game's hello has unknown flags " + std::to_string(flags));
      }
      sink.hello(flags);
      want_ = Want::header;
      need_ = kHeaderSize;
      break;
    }
    case Want::header: {
      info_ = readHeader(buf_.data(), buf_.size());
      model_ = Model{};
      model_.cellSize = info_.cellSize;
      model_.fileBuiltins = builtinsOf(info_.minorVersion);
      std::array<std::uint8_t, kHeaderSize> h{};
      std::memcpy(h.data(), buf_.data(), kHeaderSize);
      sink.header(h, info_);
      offset_ = kHeaderSize;
      want_ = Want::chunkHead;
      need_ = 8;
      break;
    }
    case Want::chunkHead: {
      chunkLen_ = le32(buf_.data());
      chunkCrc_ = le32(buf_.data() + 4);
      if (chunkLen_ == 0 && chunkCrc_ == kEndMark) {
        if (frame_ == 0) streamFail(offset_, 0, "the recording ended before its first frame");
        sink.end();
        want_ = Want::done;
        offset_ += 8;
        buf_.clear();
        return;
      }
      if (chunkLen_ == 0)
        streamFail(offset_, frame_, "a chunk of 0 bytes that is not the end mark");
      if (chunkLen_ > limits_.maxChunk || chunkLen_ > kMaxChunk) {
        streamFail(offset_, frame_,
                   "chunk length " + std::to_string(chunkLen_) +
                       " is over this receiver's limit of " +
                       std::to_string(std::min(limits_.maxChunk, kMaxChunk)) + " bytes");
      }
      want_ = Want::payload;
      need_ = 8 + std::size_t{chunkLen_};
      // The head stays in buf_, in front of its payload; buf_ grows as the payload comes, so a
      // peer that only announces a big chunk costs nothing.
      return;
    }
    case Want::payload: {
      const std::uint8_t* payload = buf_.data() + 8;
      if (static_cast<std::uint32_t>(::crc32(0, payload, chunkLen_)) != chunkCrc_) {
        streamFail(offset_, frame_,
                   "checksum mismatch in frame " + std::to_string(frame_) + "'s chunk");
      }
      LiveFrame f;
      f.number = frame_;
      decodeFrame(f, payload, chunkLen_);
      f.chunk = std::move(buf_);
      buf_ = {};
      offset_ += 8 + std::uint64_t{chunkLen_};
      ++frame_;
      want_ = Want::chunkHead;
      need_ = 8;
      sink.frame(std::move(f));
      return;
    }
    case Want::done:
      return;
  }
  buf_.clear();
}

void StreamReader::decodeFrame(LiveFrame& f, const std::uint8_t* payload, std::uint32_t len) {
  In in(payload, len, offset_ + 8, frame_);
  const std::uint64_t at = in.offset();
  const std::uint64_t n = in.varint("frame number");
  if (n != frame_) {
    in.failAt(at, "frame number " + std::to_string(n) + " where frame " + std::to_string(frame_) +
                      " was due");
  }
  const std::uint8_t flags = in.u8("frame flags");
  if (flags > 1) in.fail("frame flags " + std::to_string(flags) + " are not defined");
  if (frame_ == 0 && flags == 0) in.fail("frame 0 does not open with a keyframe");
  f.keyframe = flags != 0;
  if (f.keyframe) {
    decodeKeyframe(in, model_, state_, limits_.maxCells);
    // The labels of the items now in the world, for a recording that starts here.
    Out out;
    for (std::uint32_t i = 0; i < state_.slots.size(); ++i) {
      if (!state_.slots[i].alive) continue;
      const auto it = labels_.find({i, state_.slots[i].generation});
      if (it != labels_.end()) writeLabel(out, it->first, it->second.first, it->second.second);
    }
    f.labels = out.bytes();
    f.keyframeEnd = static_cast<std::uint32_t>(in.offset() - (offset_ + 8));
  }
  while (!in.done()) {
    decodeCall(in, model_, call_, limits_.maxCells);
    ++f.calls;
    if (callRole(call_.kind) == CallRole::move) ++f.moves;
    if (callRole(call_.kind) == CallRole::batch) f.moves += call_.bodies.size();
    switch (call_.kind) {
      case CallKind::remove: {
        const auto it = labels_.find(call_.item);
        if (it != labels_.end()) {
          labelBytes_ -= it->second.first.size() + it->second.second.size();
          labels_.erase(it);
        }
        break;
      }
      case CallKind::label: {
        // Kept only for an item in the world, within the budget: a peer cannot grow it at will.
        const ItemId id = call_.item;
        const bool alive = id.index < model_.slots.size() && model_.slots[id.index].alive &&
                           model_.slots[id.index].generation == id.generation;
        if (!alive) break;
        const std::size_t bytes = call_.name.size() + call_.category.size();
        auto it = labels_.find(id);
        if (it != labels_.end()) {
          labelBytes_ -= it->second.first.size() + it->second.second.size();
          labels_.erase(it);
        }
        if (labelBytes_ + bytes > kMaxLabelBytes) break;
        labelBytes_ += bytes;
        labels_.emplace(id, std::make_pair(call_.name, call_.category));
        break;
      }
      default:
        break;
    }
  }
}

}  // namespace tv::rec
