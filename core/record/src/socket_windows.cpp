// Winsock 2 for the live stream (socket.hpp); POSIX systems have socket_posix.cpp. What differs
// from POSIX, and how it is met here:
//   - the socket layer must be started (WSAStartup, once per process; never cleaned up, since a
//     recorder may stream until the process ends);
//   - non-blocking is set with ioctlsocket(FIONBIO); a connect in progress fails with
//     WSAEWOULDBLOCK, and its outcome is seen by select(): writable when it succeeded, an
//     exception when it failed (WSAPoll misses failed connects on older Windows 10);
//   - errors come from WSAGetLastError, worded by the system (FormatMessage);
//   - SO_REUSEADDR would let a second program take a port in use: SO_EXCLUSIVEADDRUSE is asked
//     for instead, so that a busy port is reported as it is on POSIX systems;
//   - there is no pipe select() can wait on: the waker is a UDP socket on 127.0.0.1 that sends
//     to itself;
//   - send() raises no SIGPIPE, so no flag is needed to suppress it.

#include <winsock2.h>
#include <ws2tcpip.h>

#include <cstring>
#include <mutex>

#include "socket.hpp"
#include "tv/error.hpp"

namespace tv::rec::net {

namespace {

SOCKET sockOf(Handle h) {
  return static_cast<SOCKET>(h);
}

Handle handleOf(SOCKET s) {
  return s == INVALID_SOCKET ? kNoSocket : static_cast<Handle>(s);
}

// The system's words for a Winsock error, with its number ("... (WSA error 10061)").
std::string wsaText(int code) {
  switch (code) {
    case WSAECONNREFUSED: return "connection refused";
    case WSAECONNRESET: return "the connection was reset";
    case WSAECONNABORTED: return "the connection was aborted";
    default: break;
  }
  char buf[512] = {};
  const DWORD n = FormatMessageA(FORMAT_MESSAGE_FROM_SYSTEM | FORMAT_MESSAGE_IGNORE_INSERTS,
                                 nullptr, static_cast<DWORD>(code), 0, buf, sizeof buf, nullptr);
  std::string text(buf, n);
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r' || text.back() == ' ' ||
                           text.back() == '.')) {
    text.pop_back();
  }
  if (text.empty()) text = "Winsock error";
  return text + " (WSA error " + std::to_string(code) + ")";
}

std::string lastError() {
  return wsaText(WSAGetLastError());
}

void setNonBlocking(SOCKET s) {
  u_long on = 1;
  // FIONBIO is an unsigned code that ioctlsocket takes as a long (the same bits).
  ioctlsocket(s, static_cast<long>(static_cast<unsigned long>(FIONBIO)), &on);
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
    error = "cannot resolve '" + a.host + "': " + wsaText(rc);
    return nullptr;
  }
  return out;
}

}  // namespace

void startSockets() {
  static std::once_flag once;
  static int failed = 0;
  std::call_once(once, [] {
    WSADATA data;
    failed = WSAStartup(MAKEWORD(2, 2), &data);
  });
  if (failed != 0) fail("tv live", "cannot start Winsock 2.2: " + wsaText(failed));
}

void Fd::reset() {
  if (fd_ != kNoSocket) closesocket(sockOf(fd_));
  fd_ = kNoSocket;
}

void wait(Watch* watches, int n, int timeoutMs) {
  fd_set readable, writable, failed;
  FD_ZERO(&readable);
  FD_ZERO(&writable);
  FD_ZERO(&failed);
  bool any = false;
  for (int i = 0; i < n; ++i) {
    watches[i].revents = 0;
    if (watches[i].fd == kNoSocket) continue;
    const SOCKET s = sockOf(watches[i].fd);
    if (watches[i].events & kIn) FD_SET(s, &readable);
    if (watches[i].events & kOut) FD_SET(s, &writable);
    FD_SET(s, &failed);  // a failed connect, out-of-band data
    any = true;
  }
  if (!any) {  // select() refuses three empty sets: just wait
    if (timeoutMs != 0) Sleep(timeoutMs < 0 ? INFINITE : static_cast<DWORD>(timeoutMs));
    return;
  }
  timeval tv{timeoutMs / 1000, (timeoutMs % 1000) * 1000};
  if (select(0, &readable, &writable, &failed, timeoutMs < 0 ? nullptr : &tv) == SOCKET_ERROR) {
    // A socket closed under us: report every one as failed rather than spin.
    for (int i = 0; i < n; ++i) {
      if (watches[i].fd != kNoSocket) watches[i].revents = kError;
    }
    return;
  }
  for (int i = 0; i < n; ++i) {
    if (watches[i].fd == kNoSocket) continue;
    const SOCKET s = sockOf(watches[i].fd);
    short r = 0;
    if (FD_ISSET(s, &readable)) r |= kIn;  // data, or the peer's end (recv returns 0)
    if (FD_ISSET(s, &writable)) r |= kOut;
    if (FD_ISSET(s, &failed)) r |= kError;
    watches[i].revents = r;
  }
}

Waker::Waker() {
  startSockets();
  const SOCKET s = socket(AF_INET, SOCK_DGRAM, IPPROTO_UDP);
  if (s == INVALID_SOCKET) fail("tv live", "cannot make the waker's socket: " + lastError());
  read_ = Fd(handleOf(s));
  sockaddr_in at{};
  at.sin_family = AF_INET;
  at.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  at.sin_port = 0;
  int len = sizeof at;
  if (bind(s, reinterpret_cast<sockaddr*>(&at), sizeof at) != 0 ||
      getsockname(s, reinterpret_cast<sockaddr*>(&at), &len) != 0 ||
      connect(s, reinterpret_cast<sockaddr*>(&at), sizeof at) != 0) {
    fail("tv live", "cannot bind the waker's socket on 127.0.0.1: " + lastError());
  }
  setNonBlocking(s);
  // One socket both ends: write_ stays empty.
}

void Waker::wake() const {
  const char c = 1;
  send(sockOf(read_.get()), &c, 1, 0);  // full already: it will wake anyway
}

void Waker::drain() const {
  char buf[64];
  while (recv(sockOf(read_.get()), buf, sizeof buf, 0) > 0) {
  }
}

Fd startConnect(const Address& a, std::string& error) {
  startSockets();
  addrinfo* list = resolve(a, false, error);
  if (!list) return {};
  Fd fd;
  for (addrinfo* ai = list; ai; ai = ai->ai_next) {
    const SOCKET raw = socket(ai->ai_family, ai->ai_socktype, ai->ai_protocol);
    if (raw == INVALID_SOCKET) {
      error = lastError();
      continue;
    }
    Fd s(handleOf(raw));
    setNonBlocking(raw);
    const BOOL one = TRUE;
    setsockopt(raw, IPPROTO_TCP, TCP_NODELAY, reinterpret_cast<const char*>(&one), sizeof one);
    if (connect(raw, ai->ai_addr, static_cast<int>(ai->ai_addrlen)) == 0 ||
        WSAGetLastError() == WSAEWOULDBLOCK) {
      fd = std::move(s);
      error.clear();
      break;
    }
    error = lastError();
  }
  freeaddrinfo(list);
  return fd;
}

std::string connectResult(Handle fd) {
  int err = 0;
  int len = sizeof err;
  if (getsockopt(sockOf(fd), SOL_SOCKET, SO_ERROR, reinterpret_cast<char*>(&err), &len) != 0) {
    err = WSAGetLastError();
  }
  return err == 0 ? std::string() : wsaText(err);
}

Fd listenOn(const Address& a) {
  startSockets();
  std::string error;
  addrinfo* list = resolve(a, true, error);
  if (!list) fail("tv::LiveReceiver", a.text() + ": " + error);
  Fd fd;
  for (addrinfo* ai = list; ai; ai = ai->ai_next) {
    const SOCKET raw = socket(ai->ai_family, ai->ai_socktype, ai->ai_protocol);
    if (raw == INVALID_SOCKET) {
      error = lastError();
      continue;
    }
    Fd s(handleOf(raw));
    const BOOL one = TRUE;
    setsockopt(raw, SOL_SOCKET, SO_EXCLUSIVEADDRUSE, reinterpret_cast<const char*>(&one),
               sizeof one);
    if (bind(raw, ai->ai_addr, static_cast<int>(ai->ai_addrlen)) != 0) {
      const int code = WSAGetLastError();
      error = code == WSAEADDRINUSE || code == WSAEACCES
                  ? "is in use by another program (another receiver or debugger?)"
                  : "cannot be listened on here: " + wsaText(code);
      continue;
    }
    if (listen(raw, 4) != 0) {
      error = "cannot be listened on: " + lastError();
      continue;
    }
    setNonBlocking(raw);
    fd = std::move(s);
    break;
  }
  freeaddrinfo(list);
  if (!fd) fail("tv::LiveReceiver", a.text() + " " + error);
  return fd;
}

Fd acceptNext(Handle listener) {
  const SOCKET s = accept(sockOf(listener), nullptr, nullptr);
  if (s == INVALID_SOCKET) return {};
  setNonBlocking(s);  // whatever it inherited: recv and send must never wait
  return Fd(handleOf(s));
}

std::uint16_t localPort(Handle fd) {
  sockaddr_storage ss{};
  int len = sizeof ss;
  if (getsockname(sockOf(fd), reinterpret_cast<sockaddr*>(&ss), &len) != 0) return 0;
  if (ss.ss_family == AF_INET) return ntohs(reinterpret_cast<sockaddr_in*>(&ss)->sin_port);
  if (ss.ss_family == AF_INET6) return ntohs(reinterpret_cast<sockaddr_in6*>(&ss)->sin6_port);
  return 0;
}

std::string peerName(Handle fd) {
  sockaddr_storage ss{};
  int len = sizeof ss;
  if (getpeername(sockOf(fd), reinterpret_cast<sockaddr*>(&ss), &len) != 0) return "?";
  char host[NI_MAXHOST], serv[NI_MAXSERV];
  if (getnameinfo(reinterpret_cast<sockaddr*>(&ss), len, host, sizeof host, serv, sizeof serv,
                  NI_NUMERICHOST | NI_NUMERICSERV) != 0) {
    return "?";
  }
  const std::string h = host;
  return (h.find(':') != std::string::npos ? "[" + h + "]" : h) + ":" + serv;
}

long sendSome(Handle fd, const void* data, std::size_t n, std::string& error) {
  const int chunk = n > (1u << 30) ? (1 << 30) : static_cast<int>(n);
  const int r = send(sockOf(fd), static_cast<const char*>(data), chunk, 0);
  if (r != SOCKET_ERROR) return r;
  const int code = WSAGetLastError();
  if (code == WSAEWOULDBLOCK || code == WSAEINTR) return 0;
  error = code == WSAECONNRESET || code == WSAECONNABORTED || code == WSAESHUTDOWN
              ? "the other side closed the connection"
              : wsaText(code);
  return -1;
}

long recvSome(Handle fd, void* data, std::size_t n, std::string& error) {
  const int chunk = n > (1u << 30) ? (1 << 30) : static_cast<int>(n);
  const int r = recv(sockOf(fd), static_cast<char*>(data), chunk, 0);
  if (r > 0) return r;
  if (r == 0) {
    error = "closed";
    return -1;
  }
  const int code = WSAGetLastError();
  if (code == WSAEWOULDBLOCK || code == WSAEINTR) return 0;
  error = wsaText(code);
  return -1;
}

void shutdownSend(Handle fd) {
  shutdown(sockOf(fd), SD_SEND);
}

}  // namespace tv::rec::net
