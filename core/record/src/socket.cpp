// Addresses and time for the live stream (socket.hpp): the same on every system. The sockets
// themselves are in socket_posix.cpp and socket_windows.cpp.

#include <charconv>
#include <chrono>

#include "socket.hpp"
#include "tv/error.hpp"

namespace tv::rec::net {

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

double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace tv::rec::net
