#pragma once
// Comparing a rendered picture with its golden: what "the same picture" means across rasterizers.
//
// The goldens are rendered by Mesa's llvmpipe, whose rounding moves with the Mesa build (Debian 12's
// 22.3.6-1+deb12u1 against +deb12u2: up to 6046 of 921600 pixels differ, by at most 2 levels) and
// could move with the CPU's vector width. A picture therefore matches its golden when
//   - no pixel differs by more than `channel` levels in any channel (a moved line, a body drawn a
//     pixel off, a missing label or a changed palette colour all change some pixel by far more), and
//   - at most `fraction` of the pixels differ at all (a change that shifts every colour by a level
//     or two — a blend or gamma change — is a real change, not rounding).
// The defaults were chosen by measurement (tests/app/README.md says how): twice the largest
// difference seen between rasterizers, and three times the largest share of pixels that differed.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace tv::test {

struct Image {
  int w = 0, h = 0;
  std::vector<unsigned char> rgb;  ///< w*h*3 bytes, row by row from the top

  [[nodiscard]] unsigned char* at(int x, int y) {
    return rgb.data() + (static_cast<std::size_t>(y) * static_cast<std::size_t>(w) +
                         static_cast<std::size_t>(x)) * 3;
  }
  [[nodiscard]] const unsigned char* at(int x, int y) const {
    return const_cast<Image*>(this)->at(x, y);
  }
};

/// Reads a PNG as RGB; nothing when it cannot be read.
[[nodiscard]] std::optional<Image> loadPng(const std::string& path);
/// Writes an RGB PNG; false when it cannot be written.
bool savePng(const std::string& path, const Image& image);

struct Tolerance {
  int channel = 4;          ///< largest per-channel difference a pixel may have, 0..255
  double fraction = 0.02;   ///< largest share of pixels that may differ at all, 0..1
};

/// Parses "C" or "C:F" (TV_GOLDEN_TOLERANCE); nothing when malformed.
[[nodiscard]] std::optional<Tolerance> parseTolerance(const std::string& text);

struct Comparison {
  bool sameSize = true;
  std::size_t pixels = 0;     ///< pixels compared
  std::size_t differing = 0;  ///< pixels with any channel different
  std::size_t beyond = 0;     ///< pixels with a channel different by more than the tolerance
  int worst = 0;              ///< the largest channel difference
  std::size_t allowed = 0;    ///< how many pixels may differ at all
  [[nodiscard]] bool matches() const { return sameSize && beyond == 0 && differing <= allowed; }
  /// One line for a failure or a success ("913 of 921600 pixels differ, by at most 1; ...").
  [[nodiscard]] std::string describe(const Tolerance& tolerance) const;
};

[[nodiscard]] Comparison compare(const Image& golden, const Image& actual, const Tolerance& tolerance);

/// The golden dimmed to a quarter with every differing pixel in red (brighter = larger) and every
/// pixel beyond the tolerance in yellow, so a moved line stands out from rounding noise.
[[nodiscard]] Image diffPicture(const Image& golden, const Image& actual, const Tolerance& tolerance);

}  // namespace tv::test
