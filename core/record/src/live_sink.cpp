// The game's side of a live stream (live_sink.hpp).
//
// Index: [SECTION] life · [SECTION] the game's thread · [SECTION] the writer's thread ·
//        [SECTION] the connection

#include "live_sink.hpp"

#include <zlib.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "stream_reader.hpp"

namespace tv::rec {

namespace {

constexpr double kConnectTimeout = 3.0;  // seconds for a connect to complete
constexpr double kReplyTimeout = 5.0;    // seconds for the receiver to say it is one
constexpr double kFlushOnStop = 1.0;     // seconds to send what is queued when the game stops

std::string mib(std::size_t bytes) {
  char text[32];
  std::snprintf(text, sizeof text, "%.0f MiB", static_cast<double>(bytes) / (1 << 20));
  return text;
}

}  // namespace

// [SECTION] life ----------------------------------------------------------------------------------

LiveSink::LiveSink(LiveOptions options) : options_(std::move(options)) {
  address_ = net::parseAddress(options_.address, "tv::LiveOptions::address", false);
  addressText_ = address_.text();
  if (!(options_.retrySeconds >= 0.05 && options_.retrySeconds <= 3600)) {
    fail("tv::LiveOptions",
         "retrySeconds must be in [0.05, 3600], but was " + formatNumber(options_.retrySeconds));
  }
  if (options_.maxPendingBytes < (std::size_t{1} << 20)) {
    fail("tv::LiveOptions", "maxPendingBytes must be at least 1 MiB, but was " +
                                std::to_string(options_.maxPendingBytes));
  }
  thread_ = std::thread([this] { run(); });
}

LiveSink::~LiveSink() {
  stop();
}

void LiveSink::stop() {
  if (!thread_.joinable()) return;
  stopping_.store(true, std::memory_order_release);
  waker_.wake();
  {
    std::lock_guard lock(m_);
    resumed_.notify_all();
  }
  thread_.join();
}

void LiveSink::say(const std::string& message) {
  {
    std::lock_guard lock(m_);
    status_.message = message;
  }
  if (options_.onMessage) {
    options_.onMessage(message);
  } else {
    std::fprintf(stderr, "tv live: %s\n", message.c_str());
  }
}

// [SECTION] the game's thread ---------------------------------------------------------------------

void LiveSink::waitWhilePaused() {
  if (!options_.control) return;
  std::unique_lock lock(m_);
  resumed_.wait(lock, [&] {
    return !paused_ || steps_ > 0 || !connected_.load(std::memory_order_acquire) ||
           stopping_.load(std::memory_order_acquire);
  });
  if (paused_ && steps_ > 0) --steps_;  // a step: this frame goes, the next mark holds again
}

LiveStatus LiveSink::status() const {
  std::lock_guard lock(m_);
  LiveStatus s = status_;
  s.connected = connected_.load(std::memory_order_acquire);
  s.paused = paused_;
  return s;
}

// [SECTION] the writer's thread -------------------------------------------------------------------

void LiveSink::header(const std::array<std::uint8_t, kHeaderSize>& header) {
  header_ = header;
}

void LiveSink::keyframe(std::uint64_t frame, std::size_t callsAt, bool mayStart) {
  if (!mayStart) return;
  {
    std::lock_guard lock(m_);
    if (!awaitingKeyframe_) return;
  }
  // Any keyframe can begin the run; the labels are those of the items as the frame begins.
  startFrame_ = frame;
  startCallsAt_ = callsAt;
  Out out;
  for (const auto& [id, l] : labels_) writeLabel(out, id, l.first, l.second);
  startLabels_ = out.bytes();
}

void LiveSink::chunk(std::uint64_t frame, const std::uint8_t (&)[8],
                     std::span<const std::uint8_t> payload, const Model&) {
  std::lock_guard lock(m_);
  if (awaitingKeyframe_ && startFrame_ == frame) {
    awaitingKeyframe_ = false;
    base_ = frame;
    enqueue({header_.begin(), header_.end()});
    enqueue(renumberChunk(payload, 0, startLabels_, startCallsAt_));
    startFrame_.reset();
    status_.framesSent = 1;
    return;
  }
  if (!base_ || frame < *base_) return;
  enqueue(renumberChunk(payload, frame - *base_));
  ++status_.framesSent;
}

void LiveSink::end(const std::uint8_t (&endMark)[8]) {
  std::lock_guard lock(m_);
  if (base_) enqueue({endMark, endMark + 8});
}

void LiveSink::label(ItemId id, std::string_view label, std::string_view category) {
  labels_[id] = {std::string(label.substr(0, kMaxName)), std::string(category.substr(0, kMaxName))};
}

void LiveSink::removed(ItemId id) {
  labels_.erase(id);
}

void LiveSink::enqueue(std::vector<std::uint8_t> bytes) {
  if (!connected_.load(std::memory_order_acquire) || overflow_) return;
  pending_ += bytes.size();
  queue_.push_back(std::move(bytes));
  if (pending_ > options_.maxPendingBytes) overflow_ = true;  // the thread drops the receiver
  waker_.wake();
}

// [SECTION] the connection ------------------------------------------------------------------------

void LiveSink::run() {
  while (!stopping_.load(std::memory_order_acquire)) {
    const double t = net::now();
    if (!sock_) {
      if (t >= nextTry_) {
        tryConnect();
        continue;
      }
      net::Watch w{waker_.fd(), net::kIn};
      net::wait(&w, 1, static_cast<int>(std::ceil((nextTry_ - t) * 1000)));
      waker_.drain();
      continue;
    }
    bool wantWrite = connecting_, overflow = false;
    {
      std::lock_guard lock(m_);
      overflow = overflow_;
      wantWrite = wantWrite || !queue_.empty();
    }
    if (overflow) {
      disconnect("it fell more than " + mib(options_.maxPendingBytes) +
                 " behind (the game goes on, and connects again)");
      continue;
    }
    net::Watch fds[2] = {{sock_.get(), static_cast<short>(net::kIn | (wantWrite ? net::kOut : 0))},
                         {waker_.fd(), net::kIn}};
    if (connecting_) fds[0].events = net::kOut;
    int timeout = -1;
    if (connecting_ || !replied_) timeout = std::max(0, static_cast<int>((deadline_ - t) * 1000));
    net::wait(fds, 2, timeout);
    if (fds[1].revents) waker_.drain();
    if (connecting_) {
      if (fds[0].revents) {
        const std::string why = net::connectResult(sock_.get());
        if (why.empty()) {
          connectedNow();
        } else {
          sock_.reset();
          connecting_ = false;
          if (why != lastFailure_) {
            lastFailure_ = why;
            say("no receiver at " + addressText_ + " (" + why + "); the game goes on, trying " +
                "again every " + formatNumber(options_.retrySeconds) + " s");
          }
          nextTry_ = net::now() + options_.retrySeconds;
        }
      } else if (net::now() >= deadline_) {
        sock_.reset();
        connecting_ = false;
        if (lastFailure_ != "timeout") {
          lastFailure_ = "timeout";
          say("no answer from " + addressText_ + " within " + formatNumber(kConnectTimeout) +
              " s; the game goes on, trying again every " + formatNumber(options_.retrySeconds) +
              " s");
        }
        nextTry_ = net::now() + options_.retrySeconds;
      }
      continue;
    }
    if (fds[0].revents & (net::kIn | net::kHangUp | net::kError)) readCommands();
    if (sock_ && !sendQueued()) continue;
    if (sock_ && !replied_ && net::now() >= deadline_) {
      disconnect(addressText_ + " did not answer as a tunnelvision receiver within " +
                 formatNumber(kReplyTimeout) + " s");
    }
  }
  // Stopping: what the writer queued last (the final frame, the end mark) goes out first.
  if (sock_ && !connecting_) {
    const double until = net::now() + kFlushOnStop;
    for (;;) {
      bool empty;
      {
        std::lock_guard lock(m_);
        empty = queue_.empty();
      }
      if (empty || !sendQueued() || net::now() >= until) break;
      net::Watch p{sock_.get(), net::kOut};
      net::wait(&p, 1, 50);
    }
  }
  if (sock_ && !connecting_) {
    // A graceful end: no more to send (FIN after the data), then what the receiver still says
    // is read until it closes too. Closing with unread bytes would reset the connection, and a
    // reset can throw away the last frames before the receiver has read them.
    net::shutdownSend(sock_.get());
    const double until = net::now() + kFlushOnStop;
    std::uint8_t buf[256];
    std::string why;
    while (net::now() < until) {
      net::Watch p{sock_.get(), net::kIn};
      net::wait(&p, 1, 50);
      if (net::recvSome(sock_.get(), buf, sizeof buf, why) < 0) break;
    }
  }
  if (sock_) {
    std::lock_guard lock(m_);
    connected_.store(false, std::memory_order_release);
    resumed_.notify_all();
  }
  sock_.reset();
}

void LiveSink::tryConnect() {
  std::string why;
  sock_ = net::startConnect(address_, why);
  if (!sock_) {
    if (why != lastFailure_) {
      lastFailure_ = why;
      say("no receiver at " + addressText_ + " (" + why + "); the game goes on, trying again " +
          "every " + formatNumber(options_.retrySeconds) + " s");
    }
    nextTry_ = net::now() + options_.retrySeconds;
    return;
  }
  connecting_ = true;
  deadline_ = net::now() + kConnectTimeout;
}

void LiveSink::connectedNow() {
  connecting_ = false;
  replied_ = false;
  replyBytes_ = 0;
  sentOfFront_ = 0;
  lastFailure_.clear();
  deadline_ = net::now() + kReplyTimeout;
  std::vector<std::uint8_t> hello(kLiveHello, kLiveHello + 8);
  const std::uint32_t flags = options_.control ? kHelloControl : 0;
  for (int i = 0; i < 4; ++i) hello.push_back(static_cast<std::uint8_t>(flags >> (8 * i)));
  for (int i = 0; i < 4; ++i) hello.push_back(0);
  {
    std::lock_guard lock(m_);
    ++epoch_;
    queue_.clear();
    pending_ = 0;
    overflow_ = false;
    base_.reset();
    awaitingKeyframe_ = true;
    paused_ = false;
    steps_ = 0;
    status_.runs = epoch_;
    status_.framesSent = 0;
    status_.peer = addressText_;
    connected_.store(true, std::memory_order_release);
    queue_.push_back(std::move(hello));
    pending_ = kHelloSize;
  }
  keyframeWanted_.store(true, std::memory_order_release);  // the run begins at a keyframe
  say("connected to " + addressText_ +
      (options_.control ? " (it may pause and step the game)" : ""));
}

void LiveSink::readCommands() {
  std::uint8_t buf[256];
  std::string why;
  for (;;) {
    const long n = net::recvSome(sock_.get(), buf, sizeof buf, why);
    if (n < 0) {
      disconnect(why == "closed" ? "the receiver closed the connection" : why);
      return;
    }
    if (n == 0) return;
    for (long i = 0; i < n; ++i) {
      const std::uint8_t b = buf[i];
      if (!replied_) {
        if (b != kLiveReply[replyBytes_]) {
          disconnect(addressText_ + " is not a tunnelvision receiver (it answered with other " +
                     "bytes)");
          return;
        }
        if (++replyBytes_ == sizeof kLiveReply) replied_ = true;
        continue;
      }
      if (b != kCommandPause && b != kCommandStep && b != kCommandResume && b != kCommandKeyframe) {
        disconnect("the receiver sent an unknown command (byte " + std::to_string(b) + ")");
        return;
      }
      std::lock_guard lock(m_);
      if (b == kCommandPause && options_.control) {
        paused_ = true;
        steps_ = 0;
      } else if (b == kCommandStep && options_.control) {
        paused_ = true;
        steps_ = 1;
      } else if (b == kCommandResume) {
        paused_ = false;
        steps_ = 0;
      } else if (b == kCommandKeyframe) {
        keyframeWanted_.store(true, std::memory_order_release);
      }
      resumed_.notify_all();
    }
  }
}

bool LiveSink::sendQueued() {
  for (;;) {
    const std::vector<std::uint8_t>* front;
    {
      std::lock_guard lock(m_);
      if (queue_.empty()) return true;
      front = &queue_.front();  // only this thread pops: stays valid outside the lock
    }
    std::string why;
    const long n =
        net::sendSome(sock_.get(), front->data() + sentOfFront_, front->size() - sentOfFront_, why);
    if (n < 0) {
      disconnect(why);
      return false;
    }
    if (n == 0) return true;  // the socket is full: wait() says when to go on
    sentOfFront_ += static_cast<std::size_t>(n);
    if (sentOfFront_ == front->size()) {
      std::lock_guard lock(m_);
      pending_ -= front->size();
      queue_.pop_front();
      sentOfFront_ = 0;
    }
  }
}

void LiveSink::disconnect(const std::string& why) {
  sock_.reset();
  connecting_ = false;
  {
    std::lock_guard lock(m_);
    connected_.store(false, std::memory_order_release);
    queue_.clear();
    pending_ = 0;
    overflow_ = false;
    base_.reset();
    awaitingKeyframe_ = false;
    paused_ = false;  // never leave the game held by a receiver that is gone
    steps_ = 0;
    status_.peer.clear();
    resumed_.notify_all();
  }
  say("disconnected from " + addressText_ + ": " + why);
  nextTry_ = net::now() + options_.retrySeconds;
}

}  // namespace tv::rec

namespace tv {

std::optional<LiveOptions> liveFromEnvironment(const char* name) {
  const char* value = std::getenv(name);
  if (!value || !*value) return std::nullopt;
  LiveOptions o;
  o.address = value;
  (void)rec::net::parseAddress(o.address, name, false);  // throws naming the variable
  return o;
}

}  // namespace tv
