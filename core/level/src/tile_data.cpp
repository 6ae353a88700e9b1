#include "tile_data.hpp"

#include <stdexcept>

#include <zlib.h>

namespace tv::level::detail {

std::vector<std::uint8_t> decodeBase64(std::string_view text) {
  const auto value = [](char c) -> int {
    if (c >= 'A' && c <= 'Z') return c - 'A';
    if (c >= 'a' && c <= 'z') return c - 'a' + 26;
    if (c >= '0' && c <= '9') return c - '0' + 52;
    if (c == '+') return 62;
    if (c == '/') return 63;
    return -1;
  };
  std::vector<std::uint8_t> out;
  out.reserve(text.size() / 4 * 3 + 3);
  std::uint32_t acc = 0;
  int n = 0;
  std::size_t padding = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    // Tiled writes base64 on one line, but editors and other exporters wrap it.
    if (c == '\n' || c == '\r' || c == ' ' || c == '\t') continue;
    if (c == '=') {
      ++padding;
      continue;
    }
    const int v = value(c);
    if (v < 0 || padding > 0) {
      throw std::runtime_error("not base64: character " + std::to_string(i) + " is '" +
                               std::string(1, c) + "'");
    }
    acc = (acc << 6) | static_cast<std::uint32_t>(v);
    if (++n == 4) {
      out.push_back(static_cast<std::uint8_t>(acc >> 16));
      out.push_back(static_cast<std::uint8_t>(acc >> 8));
      out.push_back(static_cast<std::uint8_t>(acc));
      acc = 0;
      n = 0;
    }
  }
  if (n == 1 || padding > 2) throw std::runtime_error("not base64: its length is impossible");
  if (n == 2) out.push_back(static_cast<std::uint8_t>(acc >> 4));
  if (n == 3) {
    out.push_back(static_cast<std::uint8_t>(acc >> 10));
    out.push_back(static_cast<std::uint8_t>(acc >> 2));
  }
  return out;
}

std::vector<std::uint8_t> inflateExactly(const std::vector<std::uint8_t>& in, std::size_t expected,
                                         bool gzip) {
  z_stream z{};
  if (inflateInit2(&z, gzip ? 15 + 16 : 15) != Z_OK) throw std::runtime_error("zlib: no memory");
  std::vector<std::uint8_t> out;
  z.next_in = const_cast<Bytef*>(in.data());  // zlib's API is not const-correct
  z.avail_in = static_cast<uInt>(in.size());
  int rc = Z_OK;
  // Grow as the stream delivers, never past what the layer declares (plus one byte to notice
  // a stream that holds more).
  constexpr std::size_t kStep = 1 << 16;
  while (rc != Z_STREAM_END) {
    const std::size_t have = out.size();
    const std::size_t room = std::min(kStep, expected + 1 - have);
    if (room == 0) break;
    out.resize(have + room);
    z.next_out = out.data() + have;
    z.avail_out = static_cast<uInt>(room);
    rc = inflate(&z, Z_NO_FLUSH);
    out.resize(have + room - z.avail_out);
    if (rc == Z_STREAM_END) break;
    if (rc != Z_OK) {
      const std::string msg = z.msg ? z.msg : "corrupt data";
      inflateEnd(&z);
      throw std::runtime_error(std::string(gzip ? "gzip" : "zlib") + ": " + msg);
    }
    if (z.avail_in == 0 && z.avail_out != 0) break;  // input ended before the stream did
    if (out.size() > expected) break;
  }
  inflateEnd(&z);
  if (out.size() > expected) {
    throw std::runtime_error("decompresses to more than the " + std::to_string(expected) +
                             " bytes the layer's size calls for");
  }
  if (rc != Z_STREAM_END) {
    throw std::runtime_error(std::string(gzip ? "gzip" : "zlib") + " stream ends early, after " +
                             std::to_string(out.size()) + " bytes");
  }
  if (out.size() != expected) {
    throw std::runtime_error("decompresses to " + std::to_string(out.size()) +
                             " bytes, but the layer's size calls for " + std::to_string(expected));
  }
  return out;
}

}  // namespace tv::level::detail
