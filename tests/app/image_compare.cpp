#include "image_compare.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>

#include "stb_image.h"
#include "stb_image_write.h"

namespace tv::test {

std::optional<Image> loadPng(const std::string& path) {
  Image out;
  int channels = 0;
  unsigned char* data = stbi_load(path.c_str(), &out.w, &out.h, &channels, 3);
  if (!data) return std::nullopt;
  out.rgb.assign(data, data + static_cast<std::size_t>(out.w) * static_cast<std::size_t>(out.h) * 3);
  stbi_image_free(data);
  return out;
}

bool savePng(const std::string& path, const Image& image) {
  return stbi_write_png(path.c_str(), image.w, image.h, 3, image.rgb.data(), image.w * 3) != 0;
}

std::optional<Tolerance> parseTolerance(const std::string& text) {
  Tolerance t;
  const char* s = text.c_str();
  char* end = nullptr;
  const long c = std::strtol(s, &end, 10);
  if (end == s || c < 0 || c > 255) return std::nullopt;
  t.channel = static_cast<int>(c);
  if (*end == ':') {
    const char* f = end + 1;
    t.fraction = std::strtod(f, &end);
    if (end == f || !(t.fraction >= 0.0 && t.fraction <= 1.0)) return std::nullopt;
  }
  if (*end != '\0') return std::nullopt;
  return t;
}

namespace {
int pixelDifference(const unsigned char* a, const unsigned char* b) {
  int d = 0;
  for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(int{a[c]} - int{b[c]}));
  return d;
}
}  // namespace

Comparison compare(const Image& golden, const Image& actual, const Tolerance& tolerance) {
  Comparison r;
  if (golden.w != actual.w || golden.h != actual.h) {
    r.sameSize = false;
    return r;
  }
  r.pixels = static_cast<std::size_t>(golden.w) * static_cast<std::size_t>(golden.h);
  for (std::size_t p = 0; p < r.pixels; ++p) {
    const int d = pixelDifference(&golden.rgb[p * 3], &actual.rgb[p * 3]);
    r.worst = std::max(r.worst, d);
    if (d > 0) ++r.differing;
    if (d > tolerance.channel) ++r.beyond;
  }
  r.allowed = static_cast<std::size_t>(tolerance.fraction * static_cast<double>(r.pixels));
  return r;
}

std::string Comparison::describe(const Tolerance& tolerance) const {
  if (!sameSize) return "the sizes differ";
  char line[256];
  std::snprintf(line, sizeof line,
                "%zu of %zu pixels differ, by at most %d; %zu by more than %d levels (none "
                "allowed); %zu may differ at all",
                differing, pixels, worst, beyond, tolerance.channel, allowed);
  return line;
}

Image diffPicture(const Image& golden, const Image& actual, const Tolerance& tolerance) {
  Image out = golden;
  const std::size_t pixels = static_cast<std::size_t>(golden.w) * static_cast<std::size_t>(golden.h);
  if (actual.w != golden.w || actual.h != golden.h) return out;
  for (std::size_t p = 0; p < pixels; ++p) {
    unsigned char* o = &out.rgb[p * 3];
    const int d = pixelDifference(&golden.rgb[p * 3], &actual.rgb[p * 3]);
    for (int c = 0; c < 3; ++c) o[c] = static_cast<unsigned char>(o[c] / 4);
    if (d > tolerance.channel) {
      o[0] = 255, o[1] = 230, o[2] = 0;
    } else if (d > 0) {
      o[0] = static_cast<unsigned char>(std::min(255, 128 + 40 * d)), o[1] = 0, o[2] = 0;
    }
  }
  return out;
}

}  // namespace tv::test
