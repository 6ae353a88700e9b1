#pragma once
// PNG output through stb_image_write (the implementation lives in Debian's libstb).

#include <cstdint>
#include <string>
#include <vector>

namespace tv::headless {

/// Writes 8-bit RGB rows (top first); throws std::runtime_error naming the file on failure.
void writePng(const std::string& path, int width, int height, const std::vector<std::uint8_t>& rgb);

}  // namespace tv::headless
