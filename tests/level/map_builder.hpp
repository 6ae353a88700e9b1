#pragma once
// Tiled maps written in the tests: a few lines of JSON, with tile data encoded on the spot
// (CSV, or base64 of little-endian gids, raw or zlib or gzip), so every map is readable here.

#include <zlib.h>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace tv::level::test {

inline std::string base64(const std::vector<std::uint8_t>& bytes) {
  static constexpr char kAlphabet[] =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  std::size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const std::uint32_t v =
        std::uint32_t{bytes[i]} << 16 | std::uint32_t{bytes[i + 1]} << 8 | bytes[i + 2];
    for (int k = 18; k >= 0; k -= 6) out += kAlphabet[(v >> k) & 63];
  }
  if (i + 1 == bytes.size()) {
    const std::uint32_t v = std::uint32_t{bytes[i]} << 16;
    out += kAlphabet[(v >> 18) & 63];
    out += kAlphabet[(v >> 12) & 63];
    out += "==";
  } else if (i + 2 == bytes.size()) {
    const std::uint32_t v = std::uint32_t{bytes[i]} << 16 | std::uint32_t{bytes[i + 1]} << 8;
    out += kAlphabet[(v >> 18) & 63];
    out += kAlphabet[(v >> 12) & 63];
    out += kAlphabet[(v >> 6) & 63];
    out += '=';
  }
  return out;
}

inline std::vector<std::uint8_t> littleEndian(const std::vector<std::uint32_t>& gids) {
  std::vector<std::uint8_t> b;
  for (const std::uint32_t g : gids) {
    for (int k = 0; k < 4; ++k) b.push_back(static_cast<std::uint8_t>(g >> (8 * k)));
  }
  return b;
}

/// zlib (gzip = false) or gzip stream of `in`.
inline std::vector<std::uint8_t> deflated(const std::vector<std::uint8_t>& in, bool gzip) {
  z_stream z{};
  if (deflateInit2(&z, 9, Z_DEFLATED, gzip ? 15 + 16 : 15, 8, Z_DEFAULT_STRATEGY) != Z_OK)
    throw std::runtime_error("deflateInit2");
  std::vector<std::uint8_t> out(deflateBound(&z, static_cast<uLong>(in.size())) + 64);
  z.next_in = const_cast<Bytef*>(in.data());
  z.avail_in = static_cast<uInt>(in.size());
  z.next_out = out.data();
  z.avail_out = static_cast<uInt>(out.size());
  if (deflate(&z, Z_FINISH) != Z_STREAM_END) throw std::runtime_error("deflate");
  out.resize(z.total_out);
  deflateEnd(&z);
  return out;
}

/// The `data` member of a tile layer: `"data": [..]` for csv, else a base64 string plus the
/// layer's "encoding" and "compression" members.
inline std::string tileData(const std::vector<std::uint32_t>& gids, const std::string& format) {
  if (format == "csv") {
    std::string s = "\"data\": [";
    for (std::size_t i = 0; i < gids.size(); ++i) s += (i ? "," : "") + std::to_string(gids[i]);
    return s + "]";
  }
  std::vector<std::uint8_t> bytes = littleEndian(gids);
  std::string compression;
  if (format == "zlib" || format == "gzip") {
    bytes = deflated(bytes, format == "gzip");
    compression = format;
  }
  return "\"encoding\": \"base64\", \"compression\": \"" + compression + "\", \"data\": \"" +
         base64(bytes) + "\"";
}

/// One tileset of 16 tiles at gid 1; tile ids in `collidableTiles` have collidable = true.
inline std::string tileset(const std::string& collidableTiles = "") {
  std::string tiles;
  std::size_t at = 0;
  while (at < collidableTiles.size()) {
    std::size_t comma = collidableTiles.find(',', at);
    if (comma == std::string::npos) comma = collidableTiles.size();
    tiles += std::string(tiles.empty() ? "" : ",") +
             "{\"id\": " + collidableTiles.substr(at, comma - at) +
             R"(, "properties": [{"name": "collidable", "type": "bool", "value": true}]})";
    at = comma + 1;
  }
  return R"({"firstgid": 1, "name": "tiles", "tilecount": 16, "columns": 4, "tilewidth": 16,
             "tileheight": 16, "tiles": [)" +
         tiles + "]}";
}

/// A finite orthogonal map of 16 px tiles.
inline std::string map(int width, int height, const std::string& layers,
                       const std::string& tilesets = tileset(), const std::string& extra = "") {
  return R"({"type": "map", "orientation": "orthogonal", "renderorder": "right-down",
             "tilewidth": 16, "tileheight": 16, "infinite": false, "width": )" +
         std::to_string(width) + ", \"height\": " + std::to_string(height) + extra +
         ", \"tilesets\": [" + tilesets + "], \"layers\": [" + layers + "]}";
}

inline std::string collidable(bool v = true) {
  return std::string(R"("properties": [{"name": "collidable", "type": "bool", "value": )") +
         (v ? "true" : "false") + "}]";
}

inline std::string tileLayer(const std::string& name, int w, int h, const std::string& data,
                             const std::string& more = "") {
  return R"({"type": "tilelayer", "name": ")" + name + "\", \"width\": " + std::to_string(w) +
         ", \"height\": " + std::to_string(h) + ", " + data + (more.empty() ? "" : ", " + more) +
         "}";
}

}  // namespace tv::level::test
