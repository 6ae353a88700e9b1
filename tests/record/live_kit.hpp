#pragma once
// Helpers for the live-stream tests: waiting for a condition with a deadline, a free port, a raw
// TCP peer that sends whatever a test wants (hostile streams), and a game that plays frames on a
// thread of its own until told to stop.

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <zlib.h>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <mutex>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include "tv/mover.hpp"
#include "tv/record/live.hpp"
#include "tv/record/recorder.hpp"
#include "tv/world.hpp"

namespace tvtest {

// What a live stream said (LiveOptions::onMessage, called on the stream's thread).
class Said {
 public:
  std::function<void(std::string_view)> sink() {
    return [this](std::string_view m) {
      std::lock_guard lock(m_);
      lines_.emplace_back(m);
    };
  }
  [[nodiscard]] std::vector<std::string> lines() const {
    std::lock_guard lock(m_);
    return lines_;
  }
  [[nodiscard]] bool contains(const std::string& text) const {
    std::lock_guard lock(m_);
    for (const std::string& l : lines_) {
      if (l.find(text) != std::string::npos) return true;
    }
    return false;
  }

 private:
  mutable std::mutex m_;
  std::vector<std::string> lines_;
};

// A recording's chunk (its head at `start`) appended to `out` with another frame number.
inline void appendRenumbered(std::vector<std::uint8_t>& out, const std::vector<std::uint8_t>& b,
                             std::size_t start, std::uint64_t number) {
  const std::uint32_t len = std::uint32_t{b[start]} | std::uint32_t{b[start + 1]} << 8 |
                            std::uint32_t{b[start + 2]} << 16 | std::uint32_t{b[start + 3]} << 24;
  std::size_t skip = start + 8;
  while (b[skip] & 0x80) ++skip;
  ++skip;
  std::vector<std::uint8_t> payload;
  std::uint64_t v = number;
  while (v >= 0x80) {
    payload.push_back(static_cast<std::uint8_t>(v | 0x80));
    v >>= 7;
  }
  payload.push_back(static_cast<std::uint8_t>(v));
  payload.insert(payload.end(), b.begin() + static_cast<std::ptrdiff_t>(skip),
                 b.begin() + static_cast<std::ptrdiff_t>(start + 8 + len));
  const auto n = static_cast<std::uint32_t>(payload.size());
  const auto crc = static_cast<std::uint32_t>(::crc32(0, payload.data(), n));
  for (int i = 0; i < 4; ++i) out.push_back(static_cast<std::uint8_t>(n >> (8 * i)));
  for (int i = 0; i < 4; ++i) out.push_back(static_cast<std::uint8_t>(crc >> (8 * i)));
  out.insert(out.end(), payload.begin(), payload.end());
}

// Polls `ok` every 5 ms for up to `seconds`; true once it holds.
inline bool eventually(const std::function<bool()>& ok, double seconds = 10.0) {
  const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (std::chrono::steady_clock::now() < until) {
    if (ok()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return ok();
}

// A port nobody listens on (one a receiver had a moment ago).
inline std::uint16_t freePort() {
  tv::LiveReceiverOptions o;
  o.address = "127.0.0.1:0";
  tv::LiveReceiver rx(o);
  return rx.port();
}

// A TCP peer under the test's control.
class RawPeer {
 public:
  explicit RawPeer(std::uint16_t port) {
    fd_ = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_port = htons(port);
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    connected_ = ::connect(fd_, reinterpret_cast<sockaddr*>(&a), sizeof a) == 0;
  }
  ~RawPeer() {
    if (fd_ >= 0) ::close(fd_);
  }
  RawPeer(const RawPeer&) = delete;
  RawPeer& operator=(const RawPeer&) = delete;
  [[nodiscard]] bool connected() const { return connected_; }
  // False once the other side has closed the connection.
  bool send(const std::vector<std::uint8_t>& bytes) {
    std::size_t at = 0;
    while (at < bytes.size()) {
      const ssize_t n = ::send(fd_, bytes.data() + at, bytes.size() - at, MSG_NOSIGNAL);
      if (n <= 0) return false;
      at += static_cast<std::size_t>(n);
    }
    return true;
  }
  // True when the other side closed the connection within `seconds` (what it sent is read).
  bool closedByTheOtherSide(double seconds = 10.0) {
    timeval tv{};
    tv.tv_sec = static_cast<long>(seconds);
    tv.tv_usec = static_cast<long>((seconds - static_cast<double>(tv.tv_sec)) * 1e6);
    setsockopt(fd_, SOL_SOCKET, SO_RCVTIMEO, &tv, sizeof tv);
    std::uint8_t buf[4096];
    for (;;) {
      const ssize_t n = ::recv(fd_, buf, sizeof buf, 0);
      if (n == 0) return true;
      if (n < 0) return errno == ECONNRESET;
    }
  }

 private:
  int fd_ = -1;
  bool connected_ = false;
};

// The hello a game sends first (FORMAT.md, "Live streams").
inline std::vector<std::uint8_t> gameHello(bool control = false) {
  std::vector<std::uint8_t> h = {'T', 'V', 'L', 'I', 'V', 'E', 0, 1};
  h.push_back(control ? 1 : 0);
  for (int i = 0; i < 7; ++i) h.push_back(0);
  return h;
}

// A game on a thread of its own: 200 walkers, each moved by a continuous mover every frame
// (one frame mark per frame), until stop(). `played` counts frames finished.
class ThreadedGame {
 public:
  explicit ThreadedGame(tv::Recorder& rec, int bodies = 200) : rec_(rec) {
    for (int i = 0; i < bodies; ++i) {
      ids_.push_back(world_.add({(i % 20) * 10.0, (i / 20) * 10.0, 4, 4}));
    }
    wall_ = world_.add({-50, -50, 4, 400});
    world_.attach(rec_);
    rec_.label(ids_[0], "walker 0", "walker");
    thread_ = std::thread([this] {
      while (!stop_.load()) {
        for (const tv::ItemId id : ids_) {
          const tv::Rect r = world_.rect(id);
          (void)mover_.move(world_, id, {r.x + 0.25, r.y});
        }
        rec_.frame();  // where a receiver's pause holds the game
        played_.fetch_add(1);
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
      }
    });
  }
  ~ThreadedGame() { stop(); }
  void stop() {
    stop_.store(true);
    if (thread_.joinable()) thread_.join();
  }
  [[nodiscard]] std::uint64_t played() const { return played_.load(); }
  [[nodiscard]] tv::ItemId first() const { return ids_[0]; }

 private:
  tv::Recorder& rec_;
  tv::World world_{16};
  tv::Mover mover_{tv::MoverSpec{}};
  std::vector<tv::ItemId> ids_;
  tv::ItemId wall_;
  std::atomic<bool> stop_{false};
  std::atomic<std::uint64_t> played_{0};
  std::thread thread_;
};

}  // namespace tvtest
