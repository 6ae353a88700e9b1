// The pipe between the game's thread and the recorder's writer (capture.hpp).

#include "capture.hpp"

#include <algorithm>

#include "crash_flush.hpp"

namespace tv::rec {

namespace {
// Not zeroed: every byte the writer reads was written by the game first.
Block newBlock(std::size_t capacity) {
  Block b;
  b.data.reset(new std::byte[capacity]);
  b.capacity = capacity;
  return b;
}
}  // namespace

Pipe::Pipe(Consume consume, bool threaded, std::size_t maxBytes)
    : consume_(std::move(consume)), maxBytes_(std::max(maxBytes, 2 * kBlockSize)) {
  cur_ = newBlock(kBlockSize);
  if (threaded) {
    try {
      thread_ = std::thread([this] { run(); });
      writerId_ = thread_.get_id();
    } catch (const std::system_error&) {
      // No thread to be had (a sandbox, a thread limit): write on the game's thread instead.
    }
  }
}

Pipe::~Pipe() {
  stop();
}

void Pipe::handOver() {
  if (cur_.used == 0) return;
  if (!thread_.joinable()) {
    if (!stopping_) consume_(cur_);
    cur_.used = 0;
    return;
  }
  std::unique_lock lock(m_);
  inFlight_ += cur_.capacity;
  ++handed_;
  const std::size_t need = kBlockSize;
  full_.push_back(std::move(cur_));
  work_.notify_one();
  cur_ = takeFree(need, lock);
}

void Pipe::nextBlock(std::size_t bytes) {
  if (cur_.used == 0 && cur_.capacity < bytes) {
    // A record larger than a block (a query that found 10^5 items): a block of its own.
    cur_ = newBlock(bytes);
    return;
  }
  handOver();
  if (cur_.capacity < bytes) cur_ = newBlock(bytes);
}

Block Pipe::takeFree(std::size_t bytes, std::unique_lock<std::mutex>& lock) {
  // (A record bigger than the whole budget waits only until the writer has caught up.)
  const auto room = [&] { return inFlight_ + bytes <= maxBytes_ || inFlight_ == 0 || stopping_; };
  if (!room()) {
    ++stalls_;
    room_.wait(lock, room);
  }
  Block b;
  if (!free_.empty() && bytes <= kBlockSize) {
    b = std::move(free_.back());
    free_.pop_back();
  } else {
    lock.unlock();
    b = newBlock(std::max(bytes, kBlockSize));
    lock.lock();
  }
  b.used = 0;
  return b;
}

void Pipe::drain() {
  handOver();
  if (!thread_.joinable()) return;
  std::unique_lock lock(m_);
  room_.wait(lock, [&] { return consumed_ == handed_; });
}

void Pipe::stop() {
  if (thread_.joinable()) {
    handOver();
    {
      std::lock_guard lock(m_);
      stopping_ = true;
    }
    work_.notify_one();
    thread_.join();
  } else {
    handOver();
  }
  stopping_ = true;
}

void Pipe::run() {
  systemId_.store(systemThreadId(), std::memory_order_release);
  std::unique_lock lock(m_);
  for (;;) {
    work_.wait(lock, [&] { return !full_.empty() || stopping_; });
    if (full_.empty()) return;  // stopping, and everything handed over is consumed
    Block b = std::move(full_.front());
    full_.pop_front();
    lock.unlock();
    consume_(b);
    lock.lock();
    inFlight_ -= b.capacity;
    ++consumed_;
    // Keep a few blocks of the usual size for the game to fill again; let big ones go.
    if (b.capacity == kBlockSize && free_.size() < 4) {
      b.used = 0;
      free_.push_back(std::move(b));
    } else {
      lock.unlock();
      b.data.reset();
      lock.lock();
    }
    room_.notify_all();
  }
}

}  // namespace tv::rec
