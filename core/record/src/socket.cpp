// POSIX sockets for the live stream (socket.hpp).

#include "socket.hpp"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <chrono>
#include <cstring>

#include "tv/error.hpp"

namespace tv::rec::net {

namespace {

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

std::string Address::text() const {
  if (host.find(':') != std::string::npos) return "[" + host + "]:" + std::to_string(port);
  return host + ":" + std::to_string(port);
}

Address parseAddress(std::string_view text, std::string_view what, bool allowZero) {
  const auto bad = [&](const std::string& why) -> Address {
    std::string message = "'";  // appended, not added: GCC 12's false -Wrestrict (bug 105329)
    message.append(text).append("' ").append(why).append(
        " (expected HOST:PORT or PORT, e.g. 127.0.0.1:7720)");
    fail(what, message);
  };
  Address a;
  std::string_view port = text;
  if (!text.empty() && text.front() == '[') {
    const std::size_t close = text.find(']');
    if (close == std::string_view::npos || close + 1 >= text.size() || text[close + 1] != ':') {
      return bad("is not an address");
    }
    a.host = std::string(text.substr(1, close - 1));
    port = text.substr(close + 2);
  } else if (const std::size_t colon = text.rfind(':'); colon != std::string_view::npos) {
    a.host = std::string(text.substr(0, colon));
    port = text.substr(colon + 1);
    if (a.host.find(':') != std::string::npos) return bad("is an IPv6 address without [ ]");
  } else {
    a.host = "127.0.0.1";  // loopback unless the user names another host
  }
  if (a.host.empty()) return bad("has no host before ':'");
  unsigned value = 0;
  const auto [end, ec] = std::from_chars(port.data(), port.data() + port.size(), value);
  if (port.empty() || ec != std::errc() || end != port.data() + port.size()) {
    return bad("has no port number");
  }
  if (value > 65535 || (value == 0 && !allowZero)) return bad("has a port outside 1..65535");
  a.port = static_cast<std::uint16_t>(value);
  return a;
}

void Fd::reset() {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
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
  (void)!::write(write_.get(), &c, 1);  // full already: it will wake anyway
}

void Waker::drain() const {
  char buf[64];
  while (::read(read_.get(), buf, sizeof buf) > 0) {
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
    setNonBlocking(s.get());
    const int one = 1;
    setsockopt(s.get(), IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
    if (::connect(s.get(), ai->ai_addr, ai->ai_addrlen) == 0 || errno == EINPROGRESS) {
      fd = std::move(s);
      error.clear();
      break;
    }
    error = errno == ECONNREFUSED ? "connection refused" : std::strerror(errno);
  }
  freeaddrinfo(list);
  return fd;
}

std::string connectResult(int fd) {
  int err = 0;
  socklen_t len = sizeof err;
  if (getsockopt(fd, SOL_SOCKET, SO_ERROR, &err, &len) != 0) err = errno;
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
    setsockopt(s.get(), SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);  // a restart, not a twin
    if (::bind(s.get(), ai->ai_addr, ai->ai_addrlen) != 0) {
      error = errno == EADDRINUSE
                  ? "is in use by another program (another receiver or debugger?)"
                  : std::string("cannot be listened on here: ") + std::strerror(errno);
      continue;
    }
    if (::listen(s.get(), 4) != 0) {
      error = std::string("cannot be listened on: ") + std::strerror(errno);
      continue;
    }
    setNonBlocking(s.get());
    fd = std::move(s);
    break;
  }
  freeaddrinfo(list);
  if (!fd) fail("tv::LiveReceiver", a.text() + " " + error);
  return fd;
}

std::uint16_t localPort(int fd) {
  sockaddr_storage ss{};
  socklen_t len = sizeof ss;
  if (getsockname(fd, reinterpret_cast<sockaddr*>(&ss), &len) != 0) return 0;
  if (ss.ss_family == AF_INET) return ntohs(reinterpret_cast<sockaddr_in*>(&ss)->sin_port);
  if (ss.ss_family == AF_INET6) return ntohs(reinterpret_cast<sockaddr_in6*>(&ss)->sin6_port);
  return 0;
}

std::string peerName(int fd) {
  sockaddr_storage ss{};
  socklen_t len = sizeof ss;
  if (getpeername(fd, reinterpret_cast<sockaddr*>(&ss), &len) != 0) return "?";
  char host[NI_MAXHOST], serv[NI_MAXSERV];
  if (getnameinfo(reinterpret_cast<sockaddr*>(&ss), len, host, sizeof host, serv, sizeof serv,
                  NI_NUMERICHOST | NI_NUMERICSERV) != 0) {
    return "?";
  }
  const std::string h = host;
  return (h.find(':') != std::string::npos ? "[" + h + "]" : h) + ":" + serv;
}

long sendSome(int fd, const void* data, std::size_t n, std::string& error) {
  const ssize_t r = ::send(fd, data, n, MSG_NOSIGNAL | MSG_DONTWAIT);  // no SIGPIPE: a message
  if (r >= 0) return static_cast<long>(r);
  if (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR) return 0;
  error = errno == EPIPE || errno == ECONNRESET ? "the other side closed the connection"
                                                : std::strerror(errno);
  return -1;
}

long recvSome(int fd, void* data, std::size_t n, std::string& error) {
  const ssize_t r = ::recv(fd, data, n, MSG_DONTWAIT);
  if (r > 0) return static_cast<long>(r);
  if (r == 0) {
    error = "closed";
    return -1;
  }
  if (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR) return 0;
  error = errno == ECONNRESET ? "the connection was reset" : std::strerror(errno);
  return -1;
}

double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace tv::rec::net
