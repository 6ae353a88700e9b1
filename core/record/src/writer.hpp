#pragma once
// The recorder's writer: it consumes the blocks the game's thread captured (capture.hpp),
// encodes each record with the Encoder (format.hpp), and when a frame ends writes its chunk —
// length, CRC-32, payload — to the file (flushed), to memory, and to a live stream. It runs on
// its own thread; everything the game's thread may read of it is atomic or behind a mutex.

#include <atomic>
#include <cstdint>
#include <cstdio>
#include <mutex>
#include <span>
#include <string>
#include <vector>

#include "capture.hpp"
#include "format.hpp"

namespace tv::rec {

class LiveOut;

class Writer {
 public:
  // `file` (owned, may be null), `memory` (may be null), `live` (may be null).
  Writer(std::uint32_t keyframeEvery, std::FILE* file, std::string path,
         std::vector<std::uint8_t>* memory, LiveOut* live);
  ~Writer();
  Writer(const Writer&) = delete;
  Writer& operator=(const Writer&) = delete;

  // Writer's thread (or the game's, unthreaded).
  void consume(const Block& block);
  // Before the first record is handed over (the pipe's lock orders it before the writer reads).
  void setLive(LiveOut* live) { live_ = live; }

  // -- read by the game's thread ------------------------------------------------------------
  [[nodiscard]] bool failed() const { return failed_.load(std::memory_order_acquire); }
  [[nodiscard]] std::string error() const;
  [[nodiscard]] std::uint64_t size() const { return size_.load(std::memory_order_acquire); }
  // Frames whose chunk is written (and flushed, to a file): what a crash keeps.
  [[nodiscard]] const std::atomic<std::uint64_t>& framesWritten() const { return written_; }

 private:
  void record(const std::byte* r);
  void fail(std::string message);
  void out(const std::uint8_t* data, std::size_t n);
  void header(double cellSize);
  void beginFrame(std::uint8_t flags, WorldState* state);
  void endFrame();
  [[nodiscard]] bool tracks(ItemId id) const;

  std::uint32_t keyframeEvery_;
  std::FILE* file_;
  std::string path_;
  std::vector<std::uint8_t>* memory_;
  LiveOut* live_;
  Encoder enc_;
  std::uint64_t frame_ = 0;
  bool started_ = false, stopped_ = false;
  std::vector<MoverSpec> specs_;  // by id
  std::vector<bool> defined_;     // since the last keyframe
  std::vector<BatchOutcome> outcomes_;
  std::size_t lastPayload_ = 0;

  std::atomic<bool> failed_{false};
  std::atomic<std::uint64_t> size_{0}, written_{0};
  mutable std::mutex errorMutex_;
  std::string error_;
};

}  // namespace tv::rec
