#pragma once
// The few POSIX socket calls a live stream needs (live_sink.cpp, live_receiver.cpp): parsing
// "HOST:PORT", a non-blocking connect, a listening socket, and a pipe that wakes a poll().
//
// Why plain POSIX sockets rather than a library (Asio, from Debian's libasio-dev): each side
// holds one connection on one thread of its own and needs exactly non-blocking connect, poll,
// send and recv — some two hundred lines — and full control over what may block (the game's
// side must never). Asio would add a dependency to every game that links tv::record for the
// same few calls; its value, portable asynchronous composition, is not what we need here.

#include <poll.h>

#include <cstdint>
#include <string>
#include <string_view>

namespace tv::rec::net {

// Where to connect or listen: a host (name, IPv4, or [IPv6]) and a port.
struct Address {
  std::string host;  // as written, without brackets
  std::uint16_t port = 0;
  [[nodiscard]] std::string text() const;  // "127.0.0.1:7720", "[::1]:7720"
};

// "HOST:PORT", "[V6]:PORT" or "PORT" (host 127.0.0.1: loopback unless the user names another).
// Throws tv::Error naming `what` and the text when it is none of these; `allowZero` lets a
// listener ask for any free port.
Address parseAddress(std::string_view text, std::string_view what, bool allowZero);

// A file descriptor, closed with its owner.
class Fd {
 public:
  Fd() = default;
  explicit Fd(int fd) : fd_(fd) {}
  ~Fd() { reset(); }
  Fd(Fd&& o) noexcept : fd_(o.release()) {}
  Fd& operator=(Fd&& o) noexcept {
    if (this != &o) {
      reset();
      fd_ = o.release();
    }
    return *this;
  }
  Fd(const Fd&) = delete;
  Fd& operator=(const Fd&) = delete;
  [[nodiscard]] int get() const { return fd_; }
  [[nodiscard]] bool valid() const { return fd_ >= 0; }
  explicit operator bool() const { return valid(); }
  int release() {
    const int f = fd_;
    fd_ = -1;
    return f;
  }
  void reset();

 private:
  int fd_ = -1;
};

// A pipe whose read end a poll() watches, so that another thread can wake it.
class Waker {
 public:
  Waker();
  void wake() const;   // any thread; never blocks
  void drain() const;  // the polling thread, after it woke
  [[nodiscard]] int fd() const { return read_.get(); }

 private:
  Fd read_, write_;
};

// Starts a non-blocking connect; the socket is writable (or in error) once it completes.
// Returns an invalid Fd and sets `error` when it fails at once (no such host, refused...).
Fd startConnect(const Address& a, std::string& error);
// The outcome of a connect started above, once poll() said it is writable: "" or the reason.
std::string connectResult(int fd);

// A non-blocking socket listening at `a`. Throws tv::Error naming the address and the reason
// ("is in use by another program", "cannot be listened on here: ...").
Fd listenOn(const Address& a);
// The port a listening socket was given (for port 0).
std::uint16_t localPort(int fd);
// The peer of a connected socket, "127.0.0.1:53122".
std::string peerName(int fd);

// Non-blocking send and receive: bytes moved, 0 when the socket would block, -1 on an error or
// (recv) the peer's end of stream, with `error` saying which.
long sendSome(int fd, const void* data, std::size_t n, std::string& error);
long recvSome(int fd, void* data, std::size_t n, std::string& error);

// Monotonic seconds.
double now();

}  // namespace tv::rec::net
