#pragma once
// Decoding a Tiled tile layer's `data`: base64, then zlib or gzip, into little-endian gids.
// Bounded: the output never grows past what the layer declares, and a declaration the input
// cannot possibly hold is refused before anything is allocated. Internal to tv::level.

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace tv::level::detail {

/// Base64 (standard alphabet, '=' padding, no whitespace other than line breaks). Throws
/// std::runtime_error with what is wrong and the character offset.
std::vector<std::uint8_t> decodeBase64(std::string_view text);

/// Inflates zlib (`gzip` false) or gzip data to exactly `expected` bytes. Throws
/// std::runtime_error when the stream is corrupt, ends early or holds more than `expected`.
std::vector<std::uint8_t> inflateExactly(const std::vector<std::uint8_t>& in, std::size_t expected,
                                         bool gzip);

/// The most bytes `compressed` bytes of deflate data can inflate to (deflate's ratio is at most
/// 1032:1), so a layer declaring more is refused before inflating.
inline std::size_t maxInflated(std::size_t compressed) {
  return compressed * 1032 + 1024;
}

}  // namespace tv::level::detail
