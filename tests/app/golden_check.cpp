// tv_golden_check: renders one golden case with tv-render and compares it with the golden PNG.
//
//   tv_golden_check TV_RENDER GOLDEN.png OUT_DIR NAME -- [tv-render arguments...]
//
// Exact by default: the goldens are pinned to Debian 12's Mesa (llvmpipe), where the output is
// byte-identical across runs. Another Mesa build rasterises a few edge pixels differently, so
// TV_GOLDEN_TOLERANCE="C[:F]" accepts pixels whose channels differ by at most C (0..255), and
// then up to a fraction F (0..1) of pixels differing by more (e.g. "2:0.001").
// On a mismatch the actual image and a diff image (differences in red over the dimmed golden)
// are left in OUT_DIR and named in the failure; on success the actual image is removed.
#include <spawn.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "stb_image.h"
#include "stb_image_write.h"

extern char** environ;

namespace {

struct Image {
  int w = 0, h = 0;
  std::vector<unsigned char> rgb;
};

bool load(const std::string& path, Image& out) {
  int channels = 0;
  unsigned char* data = stbi_load(path.c_str(), &out.w, &out.h, &channels, 3);
  if (!data) return false;
  out.rgb.assign(data,
                 data + static_cast<std::size_t>(out.w) * static_cast<std::size_t>(out.h) * 3);
  stbi_image_free(data);
  return true;
}

struct Tolerance {
  int channel = 0;
  double fraction = 0.0;
};

bool parseTolerance(const char* text, Tolerance& t) {
  if (!text || !*text) return true;
  char* end = nullptr;
  const long c = std::strtol(text, &end, 10);
  if (end == text || c < 0 || c > 255) return false;
  t.channel = static_cast<int>(c);
  if (*end == ':') {
    const char* f = end + 1;
    t.fraction = std::strtod(f, &end);
    if (end == f || t.fraction < 0.0 || t.fraction > 1.0) return false;
  }
  return *end == '\0';
}

int run(const std::vector<std::string>& argv) {
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  pid_t pid = 0;
  if (posix_spawn(&pid, args[0], nullptr, nullptr, args.data(), environ) != 0) return -1;
  int status = 0;
  if (waitpid(pid, &status, 0) < 0) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 6 || std::string(argv[5]) != "--") {
    std::fprintf(stderr, "usage: tv_golden_check TV_RENDER GOLDEN.png OUT_DIR NAME -- [args...]\n");
    return 2;
  }
  const std::string render = argv[1], golden = argv[2], dir = argv[3], name = argv[4];
  Tolerance tol;
  if (!parseTolerance(std::getenv("TV_GOLDEN_TOLERANCE"), tol)) {
    std::fprintf(stderr,
                 "TV_GOLDEN_TOLERANCE must be C or C:F (C in 0..255, F in 0..1), but was '%s'\n",
                 std::getenv("TV_GOLDEN_TOLERANCE"));
    return 2;
  }
  std::filesystem::create_directories(dir);
  const std::string actual = dir + "/" + name + ".png";
  const std::string diff = dir + "/" + name + ".diff.png";
  std::filesystem::remove(actual);
  std::filesystem::remove(diff);

  std::vector<std::string> cmd = {render};
  for (int i = 6; i < argc; ++i) cmd.emplace_back(argv[i]);
  cmd.insert(cmd.end(), {"--out", actual});
  const int rc = run(cmd);
  if (rc != 0) {
    std::fprintf(stderr, "%s: tv-render exited with %d\n", name.c_str(), rc);
    return 1;
  }

  Image want, got;
  if (!load(golden, want)) {
    std::fprintf(stderr,
                 "%s: cannot read the golden %s\n  actual: %s\n  (render the goldens with "
                 "app/headless/regenerate_goldens.sh or the tv-goldens target)\n",
                 name.c_str(), golden.c_str(), actual.c_str());
    return 1;
  }
  if (!load(actual, got)) {
    std::fprintf(stderr, "%s: cannot read what tv-render wrote: %s\n", name.c_str(),
                 actual.c_str());
    return 1;
  }
  if (want.w != got.w || want.h != got.h) {
    std::fprintf(stderr, "%s: size %dx%d, golden %dx%d\n  golden: %s\n  actual: %s\n", name.c_str(),
                 got.w, got.h, want.w, want.h, golden.c_str(), actual.c_str());
    return 1;
  }

  const std::size_t pixels = static_cast<std::size_t>(want.w) * static_cast<std::size_t>(want.h);
  std::size_t differing = 0, beyond = 0;
  int worst = 0;
  std::vector<unsigned char> picture(pixels * 3);
  for (std::size_t p = 0; p < pixels; ++p) {
    int d = 0;
    for (std::size_t c = 0; c < 3; ++c) {
      d = std::max(d, std::abs(int{want.rgb[p * 3 + c]} - int{got.rgb[p * 3 + c]}));
    }
    worst = std::max(worst, d);
    if (d > 0) ++differing;
    if (d > tol.channel) ++beyond;
    // The diff image: the golden dimmed to a quarter, differences in red (brighter = larger).
    for (std::size_t c = 0; c < 3; ++c)
      picture[p * 3 + c] = static_cast<unsigned char>(want.rgb[p * 3 + c] / 4);
    if (d > 0) {
      picture[p * 3] = static_cast<unsigned char>(std::min(255, 128 + d));
      picture[p * 3 + 1] = 0;
      picture[p * 3 + 2] = 0;
    }
  }
  const auto allowed = static_cast<std::size_t>(tol.fraction * static_cast<double>(pixels));
  if (beyond > allowed) {
    stbi_write_png(diff.c_str(), want.w, want.h, 3, picture.data(), want.w * 3);
    std::fprintf(
        stderr,
        "%s: %zu of %zu pixels differ (largest channel difference %d); %zu beyond the "
        "tolerance %d, %zu allowed (TV_GOLDEN_TOLERANCE)\n"
        "  golden: %s\n  actual: %s\n  diff:   %s\n"
        "  if the change is intended: app/headless/regenerate_goldens.sh (target tv-goldens)\n",
        name.c_str(), differing, pixels, worst, beyond, tol.channel, allowed, golden.c_str(),
        actual.c_str(), diff.c_str());
    return 1;
  }
  std::printf("%s: matches the golden (%zu pixels differ by at most %d)\n", name.c_str(), differing,
              worst);
  std::filesystem::remove(actual);
  return 0;
}
