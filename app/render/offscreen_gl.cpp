#include "offscreen_gl.hpp"

#include <GL/gl.h>

#include <cstring>
#include <stdexcept>
#include <string>

namespace tv::headless {

OffscreenGl::OffscreenGl(int width, int height)
    : width_(width),
      height_(height),
      buffer_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4) {
  // Core 3.3 is what the OpenGL3 backend's shaders are written for; OSMesa's llvmpipe gives 4.5.
  const int attribs[] = {OSMESA_FORMAT,
                         OSMESA_RGBA,
                         OSMESA_DEPTH_BITS,
                         0,
                         OSMESA_STENCIL_BITS,
                         0,
                         OSMESA_PROFILE,
                         OSMESA_CORE_PROFILE,
                         OSMESA_CONTEXT_MAJOR_VERSION,
                         3,
                         OSMESA_CONTEXT_MINOR_VERSION,
                         3,
                         0};
  context_ = OSMesaCreateContextAttribs(attribs, nullptr);
  if (!context_) context_ = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, nullptr);
  if (!context_) throw std::runtime_error("OSMesa could not create a GL context");
  if (!OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, width, height)) {
    OSMesaDestroyContext(context_);
    throw std::runtime_error("OSMesa could not make a " + std::to_string(width) + "x" +
                             std::to_string(height) + " buffer current");
  }
}

OffscreenGl::~OffscreenGl() {
  OSMesaDestroyContext(context_);
}

std::vector<std::uint8_t> OffscreenGl::readRgb() const {
  glFinish();
  const auto w = static_cast<std::size_t>(width_), h = static_cast<std::size_t>(height_);
  std::vector<std::uint8_t> rgb(w * h * 3);
  for (std::size_t y = 0; y < h; ++y) {
    const std::uint8_t* src = buffer_.data() + (h - 1 - y) * w * 4;
    std::uint8_t* dst = rgb.data() + y * w * 3;
    for (std::size_t x = 0; x < w; ++x) std::memcpy(dst + x * 3, src + x * 4, 3);
  }
  return rgb;
}

}  // namespace tv::headless
