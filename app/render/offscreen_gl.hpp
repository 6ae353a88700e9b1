#pragma once
// An OSMesa context drawing into memory: GL without a display, a window or a GPU (llvmpipe).

#include <cstdint>
#include <vector>

#include <GL/osmesa.h>

namespace tv::headless {

class OffscreenGl {
 public:
  /// A GL 3.3 core context (falls back to OSMesa's default) with a w x h RGBA buffer, made
  /// current. Throws std::runtime_error when OSMesa refuses.
  OffscreenGl(int width, int height);
  ~OffscreenGl();
  OffscreenGl(const OffscreenGl&) = delete;
  OffscreenGl& operator=(const OffscreenGl&) = delete;

  [[nodiscard]] int width() const { return width_; }
  [[nodiscard]] int height() const { return height_; }
  /// Waits for GL and returns the picture as RGB rows, top row first (alpha dropped: the PNGs
  /// are opaque).
  [[nodiscard]] std::vector<std::uint8_t> readRgb() const;

 private:
  int width_, height_;
  std::vector<std::uint8_t> buffer_;  // RGBA, bottom row first (OSMesa's default)
  OSMesaContext context_ = nullptr;
};

}  // namespace tv::headless
