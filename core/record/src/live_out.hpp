#pragma once
// What the recorder's writer tells a live stream (live_sink.cpp), on the writer's thread: the
// file's header, each keyframe as it begins, each whole chunk, the end mark, and the labels it
// must repeat when a receiver joins mid-game. The stream decides what of it to send.

#include <array>
#include <cstdint>
#include <span>
#include <string_view>

#include "format.hpp"

namespace tv::rec {

class LiveOut {
 public:
  virtual ~LiveOut() = default;
  virtual void header(const std::array<std::uint8_t, kHeaderSize>& header) = 0;
  // Frame `frame` begins with a keyframe whose bytes end at `callsAt` in its payload.
  // `mayStart`: a live run may begin with it (false when the game stops copying calls).
  virtual void keyframe(std::uint64_t frame, std::size_t callsAt, bool mayStart) = 0;
  // Frame `frame`'s chunk: its 8-byte head (length, CRC) and payload.
  virtual void chunk(std::uint64_t frame, const std::uint8_t (&head)[8],
                     std::span<const std::uint8_t> payload, const Model& model) = 0;
  virtual void end(const std::uint8_t (&endMark)[8]) = 0;
  virtual void label(ItemId id, std::string_view label, std::string_view category) = 0;
  virtual void removed(ItemId id) = 0;
};

}  // namespace tv::rec
