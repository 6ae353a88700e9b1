// POSIX sockets for the live stream (socket.hpp); Windows has socket_windows.cpp.

#include <arpa/inet.h>
#include <fcntl.h>
#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "socket.hpp"
#include "tv/error.hpp"

namespace tv::rec::net {

namespace {

// A Handle holds an int here.
int fdOf(Handle h) {
  return static_cast<int>(h);
}

void setNonBlocking(int fd) {
  const int flags = fcntl(fd, F_GETFL, 0);
  fcntl(fd, F_SETFL, flags | O_NONBLOCK);
  fcntl(fd, F_SETFD, FD_CLOEXEC);
}

// Resolves `a` (numerically when it can; names such as "localhost" through the resolver).
addrinfo* resolve(const Address& a, bool passive, std::string& error) {
  addrinfo hints{};
  hints.ai_family = AF_UNSPEC;
  hints.ai_socktype = SOCK_STREAM;
  hints.ai_flags = AI_NUMERICSERV | (passive ? AI_PASSIVE : 0);
  addrinfo* out = nullptr;
  const std::string port = std::to_string(a.port);
  const int rc = getaddrinfo(a.host.c_str(), port.c_str(), &hints, &out);
  if (rc != 0) {
    error = "cannot resolve '" + a.host + "': " + gai_strerror(rc);
    return nullptr;
  }
  return out;
}

}  // namespace

void startSockets() {}

void Fd::reset() {
  if (fd_ != kNoSocket) ::close(fdOf(fd_));
  fd_ = kNoSocket;
}

void wait(Watch* watches, int n, int timeoutMs) {
  constexpr int kMost = 8;
  if (n > kMost) fail("tv live", "a wait on more than 8 sockets");
  pollfd fds[kMost];
  for (int i = 0; i < n; ++i) {
    const short e = watches[i].events;
    fds[i] = {watches[i].fd == kNoSocket ? -1 : fdOf(watches[i].fd),
              static_cast<short>(((e & kIn) ? POLLIN : 0) | ((e & kOut) ? POLLOUT : 0)), 0};
  }
  ::poll(fds, static_cast<nfds_t>(n), timeoutMs);
  for (int i = 0; i < n; ++i) {
    const short r = fds[i].revents;
    watches[i].revents =
        static_cast<short>(((r & POLLIN) ? kIn : 0) | ((r & POLLOUT) ? kOut : 0) |
                           ((r & (POLLERR | POLLNVAL)) ? kError : 0) | ((r & POLLHUP) ? kHangUp : 0));
  }
}

Waker::Waker() {
  int p[2];
  if (::pipe(p) != 0) fail("tv live", std::string("cannot make a pipe: ") + std::strerror(errno));
  read_ = Fd(p[0]);
  write_ = Fd(p[1]);
  setNonBlocking(p[0]);
  setNonBlocking(p[1]);
}

void Waker::wake() const {
  const char c = 1;
  (void)!::write(fdOf(write_.get()), &c, 1);  // full already: it will wake anyway
}

void Waker::drain() const {
  char buf[64];
  while (::read(fdOf(read_.get()), buf, sizeof buf) > 0) {
  }
}

Fd startConnect(const Address& a, std::string& error) {
  addrinfo* list = resolve(a, false, error);
  if (!list) return {};
  Fd fd;
  for (addrinfo* ai = list; ai; ai = ai->ai_next) {
    Fd s(::socket(ai->ai_family, ai->ai_socktype, ai->ai_protocol));
    if (!s) {
      error = std::strerror(errno);
      continue;
    }
    setNonBlocking(fdOf(s.get()));
    const int one = 1;
    setsockopt(fdOf(s.get()), IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
    if (::connect(fdOf(s.get()), ai->ai_addr, ai->ai_addrlen) == 0 || errno == EINPROGRESS) {
      fd = std::move(s);
      error.clear();
      break;
    }
    error = errno == ECONNREFUSED ? "connection refused" : std::strerror(errno);
  }
  freeaddrinfo(list);
  return fd;
}

std::string connectResult(Handle fd) {
  int err = 0;
  socklen_t len = sizeof err;
  if (getsockopt(fdOf(fd), SOL_SOCKET, SO_ERROR, &err, &len) != 0) err = errno;
  if (err == 0) return {};
  return err == ECONNREFUSED ? "connection refused" : std::strerror(err);
}

Fd listenOn(const Address& a) {
  std::string error;
  addrinfo* list = resolve(a, true, error);
  if (!list) fail("tv::LiveReceiver", a.text() + ": " + error);
  Fd fd;
  for (addrinfo* ai = list; ai; ai = ai->ai_next) {
    Fd s(::socket(ai->ai_family, ai->ai_socktype, ai->ai_protocol));
    if (!s) {
      error = std::strerror(errno);
      continue;
    }
    const int one = 1;
    // A restart, not a twin: only a socket in TIME_WAIT may be shared (two listeners still
    // cannot bind the same port on Linux).
    setsockopt(fdOf(s.get()), SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
    if (::bind(fdOf(s.get()), ai->ai_addr, ai->ai_addrlen) != 0) {
      error = errno == EADDRINUSE
                  ? "is in use by another program (another receiver or debugger?)"
                  : std::string("cannot be listened on here: ") + std::strerror(errno);
      continue;
    }
    if (::listen(fdOf(s.get()), 4) != 0) {
      error = std::string("cannot be listened on: ") + std::strerror(errno);
      continue;
    }
    setNonBlocking(fdOf(s.get()));
    fd = std::move(s);
    break;
  }
  freeaddrinfo(list);
  if (!fd) fail("tv::LiveReceiver", a.text() + " " + error);
  return fd;
}

Fd acceptNext(Handle listener) {
  // Blocking here (an accepted socket does not inherit O_NONBLOCK on Linux): sendSome and
  // recvSome pass MSG_DONTWAIT instead.
  return Fd(::accept(fdOf(listener), nullptr, nullptr));
}

std::uint16_t localPort(Handle fd) {
  sockaddr_storage ss{};
  socklen_t len = sizeof ss;
  if (getsockname(fdOf(fd), reinterpret_cast<sockaddr*>(&ss), &len) != 0) return 0;
  if (ss.ss_family == AF_INET) return ntohs(reinterpret_cast<sockaddr_in*>(&ss)->sin_port);
  if (ss.ss_family == AF_INET6) return ntohs(reinterpret_cast<sockaddr_in6*>(&ss)->sin6_port);
  return 0;
}

std::string peerName(Handle fd) {
  sockaddr_storage ss{};
  socklen_t len = sizeof ss;
  if (getpeername(fdOf(fd), reinterpret_cast<sockaddr*>(&ss), &len) != 0) return "?";
  char host[NI_MAXHOST], serv[NI_MAXSERV];
  if (getnameinfo(reinterpret_cast<sockaddr*>(&ss), len, host, sizeof host, serv, sizeof serv,
                  NI_NUMERICHOST | NI_NUMERICSERV) != 0) {
    return "?";
  }
  const std::string h = host;
  return (h.find(':') != std::string::npos ? "[" + h + "]" : h) + ":" + serv;
}

long sendSome(Handle fd, const void* data, std::size_t n, std::string& error) {
  const ssize_t r = ::send(fdOf(fd), data, n, MSG_NOSIGNAL | MSG_DONTWAIT);  // no SIGPIPE
  if (r >= 0) return static_cast<long>(r);
  if (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR) return 0;
  error = errno == EPIPE || errno == ECONNRESET ? "the other side closed the connection"
                                                : std::strerror(errno);
  return -1;
}

long recvSome(Handle fd, void* data, std::size_t n, std::string& error) {
  const ssize_t r = ::recv(fdOf(fd), data, n, MSG_DONTWAIT);
  if (r > 0) return static_cast<long>(r);
  if (r == 0) {
    error = "closed";
    return -1;
  }
  if (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR) return 0;
  error = errno == ECONNRESET ? "the connection was reset" : std::strerror(errno);
  return -1;
}

void shutdownSend(Handle fd) {
  ::shutdown(fdOf(fd), SHUT_WR);
}

}  // namespace tv::rec::net
