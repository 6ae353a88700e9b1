// tv_golden_check: renders one golden case with tv-render and compares it with the golden PNG.
//
//   tv_golden_check TV_RENDER GOLDEN.png OUT_DIR NAME -- [tv-render arguments...]
//   tv_golden_check --compare GOLDEN.png ACTUAL.png [DIFF.png]
//
// "The same picture" is image_compare.hpp's: no pixel off by more than a few levels, and only a
// small share of pixels off at all, so that another Mesa build's rounding passes and a moved line
// does not. TV_GOLDEN_TOLERANCE="C[:F]" overrides the bounds ("0:0" is exact).
// On a mismatch the actual image and a diff image (rounding in red, real differences in yellow,
// over the dimmed golden) are left in OUT_DIR and named in the failure; on success the actual
// image is removed.
#include <spawn.h>
#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "image_compare.hpp"

extern char** environ;

namespace {

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

// Compares two files; returns 0 when they match, 1 when they do not, 2 when one can't be read.
int compareFiles(const std::string& name, const std::string& golden, const std::string& actual,
                 const std::string& diff, const tv::test::Tolerance& tol) {
  const auto want = tv::test::loadPng(golden);
  if (!want) {
    std::fprintf(stderr,
                 "%s: cannot read the golden %s\n  actual: %s\n  (render the goldens with "
                 "app/render/regenerate_goldens.sh or the tv-goldens target)\n",
                 name.c_str(), golden.c_str(), actual.c_str());
    return 2;
  }
  const auto got = tv::test::loadPng(actual);
  if (!got) {
    std::fprintf(stderr, "%s: cannot read %s\n", name.c_str(), actual.c_str());
    return 2;
  }
  if (want->w != got->w || want->h != got->h) {
    std::fprintf(stderr, "%s: size %dx%d, golden %dx%d\n  golden: %s\n  actual: %s\n", name.c_str(),
                 got->w, got->h, want->w, want->h, golden.c_str(), actual.c_str());
    return 1;
  }
  const tv::test::Comparison c = tv::test::compare(*want, *got, tol);
  if (!c.matches()) {
    if (!diff.empty()) (void)tv::test::savePng(diff, tv::test::diffPicture(*want, *got, tol));
    std::fprintf(stderr,
                 "%s: differs from the golden: %s\n"
                 "  golden: %s\n  actual: %s\n%s%s%s"
                 "  if the change is intended: app/render/regenerate_goldens.sh (target "
                 "tv-goldens)\n",
                 name.c_str(), c.describe(tol).c_str(), golden.c_str(), actual.c_str(),
                 diff.empty() ? "" : "  diff:   ", diff.c_str(),
                 diff.empty() ? "" : "  (yellow: beyond the tolerance; red: within it)\n");
    return 1;
  }
  std::printf("%s: matches the golden (%s)\n", name.c_str(), c.describe(tol).c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  tv::test::Tolerance tol;
  if (const char* env = std::getenv("TV_GOLDEN_TOLERANCE"); env && *env) {
    const auto parsed = tv::test::parseTolerance(env);
    if (!parsed) {
      std::fprintf(stderr,
                   "TV_GOLDEN_TOLERANCE must be C or C:F (C in 0..255, F in 0..1), but was '%s'\n",
                   env);
      return 2;
    }
    tol = *parsed;
  }
  if (argc >= 4 && std::string(argv[1]) == "--compare") {
    const std::string diff = argc >= 5 ? argv[4] : "";
    return compareFiles(argv[3], argv[2], argv[3], diff, tol);
  }
  if (argc < 6 || std::string(argv[5]) != "--") {
    std::fprintf(stderr,
                 "usage: tv_golden_check TV_RENDER GOLDEN.png OUT_DIR NAME -- [args...]\n"
                 "       tv_golden_check --compare GOLDEN.png ACTUAL.png [DIFF.png]\n");
    return 2;
  }
  const std::string render = argv[1], golden = argv[2], dir = argv[3], name = argv[4];
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
  const int verdict = compareFiles(name, golden, actual, diff, tol);
  if (verdict == 0) std::filesystem::remove(actual);
  return verdict == 0 ? 0 : 1;
}
