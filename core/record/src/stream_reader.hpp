#pragma once
// Reading a live stream (FORMAT.md, "Live streams") from bytes as they arrive, in pieces of any
// size: the game's hello, then a .tvrec file — header, chunks, end mark — checked as a file is
// (checksums, structure, every call decoded against the model). No sockets here: the receiver
// feeds it what it reads, and the fuzzer feeds it anything.
//
// Memory: one item (hello, header or chunk, at most Limits::maxChunk) being read, the model of
// the world the stream describes (bounded by the cell budget), and the labels of the items in
// it (at most kMaxLabelBytes).

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "format.hpp"
#include "tv/record/live.hpp"

namespace tv::rec {

// Game to receiver, first: magic and protocol version (8 bytes), u32 flags, u32 zero.
inline constexpr std::uint8_t kLiveHello[8] = {'T', 'V', 'L', 'I', 'V', 'E', 0, 1};
inline constexpr std::size_t kHelloSize = 16;
inline constexpr std::uint32_t kHelloControl = 1;  // the game accepts pause and step
// Receiver to game, first: its own 8 bytes; then one byte per command.
inline constexpr std::uint8_t kLiveReply[8] = {'T', 'V', 'L', 'I', 'V', 'E', 'C', 1};
enum : std::uint8_t {
  kCommandPause = 'P',
  kCommandStep = 'S',
  kCommandResume = 'R',
  kCommandKeyframe = 'K',  // a keyframe at the next frame mark, please (the receiver's window)
};
inline constexpr std::size_t kMaxLabelBytes = std::size_t{16} << 20;

struct HeaderInfo {
  double cellSize = 64.0;
  std::uint32_t keyframeEvery = 64;
  unsigned minorVersion = kVersionMinor;
};
// Checks a file header (FORMAT.md); throws tv::Error naming the byte and what is wrong.
HeaderInfo readHeader(const std::uint8_t* h, std::size_t size);

// A chunk (8-byte head and payload) with another frame number: the payload's leading varint
// replaced, its length and CRC made again; `extra` (label calls) goes in at `insertAt` of the
// payload when it is not empty.
std::vector<std::uint8_t> renumberChunk(std::span<const std::uint8_t> payload, std::uint64_t number,
                                        std::span<const std::uint8_t> extra = {},
                                        std::size_t insertAt = 0);

// The label call bytes (FORMAT.md, kind 13) of an item.
void writeLabel(Out& out, ItemId id, std::string_view label, std::string_view category);

class StreamReader {
 public:
  struct Limits {
    std::uint32_t maxChunk = std::uint32_t{64} << 20;
    std::uint64_t maxCells = std::uint64_t{1} << 22;
  };
  class Sink {
   public:
    virtual ~Sink() = default;
    virtual void hello(std::uint32_t flags) = 0;
    virtual void header(const std::array<std::uint8_t, kHeaderSize>& bytes,
                        const HeaderInfo& info) = 0;
    virtual void frame(LiveFrame&& frame) = 0;
    virtual void end() = 0;  // the end mark: nothing may follow
  };

  explicit StreamReader(Limits limits) : limits_(limits) {}

  // Reads `n` bytes; calls `sink` for each whole item. Throws tv::Error ("byte 1234 (frame 7):
  // checksum mismatch in frame 7's chunk") at anything a recorder would not have sent; the
  // reader is then done with.
  void feed(const std::uint8_t* data, std::size_t n, Sink& sink);
  // Some bytes of an item have come, not all of it.
  [[nodiscard]] bool midItem() const { return !buf_.empty(); }
  [[nodiscard]] bool ended() const { return want_ == Want::done; }
  [[nodiscard]] std::uint64_t frames() const { return frame_; }
  // What is awaited, for a message: "frame 7's chunk (1200 of 5000 bytes)".
  [[nodiscard]] std::string awaiting() const;

 private:
  enum class Want : std::uint8_t { hello, header, chunkHead, payload, done };
  void item(Sink& sink);
  void decodeFrame(LiveFrame& f, const std::uint8_t* payload, std::uint32_t len);

  Limits limits_;
  Want want_ = Want::hello;
  std::size_t need_ = kHelloSize;
  std::vector<std::uint8_t> buf_;  // the item being read
  std::uint64_t offset_ = 0;       // file offset of the item being read (the hello is not in it)
  std::uint32_t chunkLen_ = 0, chunkCrc_ = 0;
  std::uint64_t frame_ = 0;  // the next frame's number
  HeaderInfo info_;
  Model model_;
  Call call_;
  WorldState state_;
  std::unordered_map<ItemId, std::pair<std::string, std::string>> labels_;
  std::size_t labelBytes_ = 0;
};

}  // namespace tv::rec
