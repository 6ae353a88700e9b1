#pragma once
// The few socket calls a live stream needs (live_sink.cpp, live_receiver.cpp): parsing
// "HOST:PORT", a non-blocking connect, a listening socket, waiting on a few sockets at once, and
// a waker that another thread uses to end such a wait. POSIX sockets (socket_posix.cpp) or
// Winsock 2 (socket_windows.cpp); this header names no system header, so that the code above it
// is the same on both.
//
// Why plain sockets rather than a library (Asio, from Debian's libasio-dev): each side holds one
// connection on one thread of its own and needs exactly non-blocking connect, poll, send and
// recv — some two hundred lines per system — and full control over what may block (the game's
// side must never). Asio would add a dependency to every game that links tv::record for the
// same few calls; its value, portable asynchronous composition, is not what we need here.

#include <cstddef>
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

// A socket: a file descriptor on POSIX systems, a SOCKET on Windows (which fits: it is a
// pointer-sized handle there, and INVALID_SOCKET is all ones, i.e. -1).
using Handle = std::intptr_t;
inline constexpr Handle kNoSocket = -1;

// Starts the system's socket layer once per process (WSAStartup on Windows; nothing on POSIX
// systems). Every function below that makes a socket calls it. Throws tv::Error with the
// system's reason when it cannot start.
void startSockets();

// A socket, closed with its owner.
class Fd {
 public:
  Fd() = default;
  explicit Fd(Handle fd) : fd_(fd) {}
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
  [[nodiscard]] Handle get() const { return fd_; }
  [[nodiscard]] bool valid() const { return fd_ != kNoSocket; }
  explicit operator bool() const { return valid(); }
  Handle release() {
    const Handle f = fd_;
    fd_ = kNoSocket;
    return f;
  }
  void reset();

 private:
  Handle fd_ = kNoSocket;
};

// What a wait is for and what happened, per socket (poll()'s pollfd, spelled the same on every
// system). A socket of kNoSocket is left out.
struct Watch {
  Handle fd = kNoSocket;
  short events = 0;   // kIn, kOut
  short revents = 0;  // kIn, kOut, kError (a failed connect, a reset), kHangUp
};
inline constexpr short kIn = 1, kOut = 2, kError = 4, kHangUp = 8;

// Waits until one of `n` sockets is ready as asked, or `timeoutMs` pass (-1: no limit); fills
// each revents. poll() on POSIX systems; select() on Windows, where a failed non-blocking connect
// is reported as an exception (kError).
void wait(Watch* watches, int n, int timeoutMs);

// Wakes a wait() from another thread: a pipe on POSIX systems, a UDP socket sending to itself
// on 127.0.0.1 on Windows (where select() waits on sockets only).
class Waker {
 public:
  Waker();
  void wake() const;   // any thread; never blocks
  void drain() const;  // the waiting thread, after it woke
  [[nodiscard]] Handle fd() const { return read_.get(); }

 private:
  Fd read_, write_;
};

// Starts a non-blocking connect; the socket is writable (or in error) once it completes.
// Returns an invalid Fd and sets `error` when it fails at once (no such host, refused...).
Fd startConnect(const Address& a, std::string& error);
// The outcome of a connect started above, once wait() said it is writable (or failed): "" or
// the reason.
std::string connectResult(Handle fd);

// A non-blocking socket listening at `a`. Throws tv::Error naming the address and the reason
// ("is in use by another program", "cannot be listened on here: ...").
Fd listenOn(const Address& a);
// The next connection waiting on a listening socket, non-blocking; invalid when none waits.
Fd acceptNext(Handle listener);
// The port a listening socket was given (for port 0).
std::uint16_t localPort(Handle fd);
// The peer of a connected socket, "127.0.0.1:53122".
std::string peerName(Handle fd);

// Non-blocking send and receive: bytes moved, 0 when the socket would block, -1 on an error or
// (recv) the peer's end of stream, with `error` saying which.
long sendSome(Handle fd, const void* data, std::size_t n, std::string& error);
long recvSome(Handle fd, void* data, std::size_t n, std::string& error);
// No more to send (a FIN after the data); the socket still receives.
void shutdownSend(Handle fd);

// Monotonic seconds.
double now();

}  // namespace tv::rec::net
