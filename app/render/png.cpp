#include "png.hpp"

#include <stdexcept>

#include "stb_image_write.h"

namespace tv::headless {

void writePng(const std::string& path, int width, int height,
              const std::vector<std::uint8_t>& rgb) {
  if (!stbi_write_png(path.c_str(), width, height, 3, rgb.data(), width * 3)) {
    throw std::runtime_error("could not write '" + path + "'");
  }
}

}  // namespace tv::headless
