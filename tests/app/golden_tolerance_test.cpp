// What the golden comparison tolerates, and what it must still catch (image_compare.hpp).
//
// The positive side is measured for real by the golden tests themselves: every golden rendered
// again under the default rasterizer and under LP_NATIVE_VECTOR_WIDTH=128 and =256 must match
// (tests/app/CMakeLists.txt). Here: rounding noise like another Mesa build's passes, and the
// changes a golden exists to catch fail, each made as small as it can be on a real golden.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <string>

#include "image_compare.hpp"
#include "tv/ui/palette.hpp"

namespace tv::test {
namespace {

const std::string kShots = TV_SCREENSHOTS_DIR;

Image golden(const std::string& name) {
  auto image = loadPng(kShots + "/" + name + ".png");
  if (!image) ADD_FAILURE() << "cannot read " << kShots << "/" << name << ".png";
  return image ? *image : Image{};
}

bool is(const unsigned char* p, ImU32 colour) {
  return p[0] == ((colour >> IM_COL32_R_SHIFT) & 0xFF) &&
         p[1] == ((colour >> IM_COL32_G_SHIFT) & 0xFF) &&
         p[2] == ((colour >> IM_COL32_B_SHIFT) & 0xFF);
}

bool matches(const Image& a, const Image& b) { return compare(a, b, Tolerance{}).matches(); }

TEST(GoldenTolerance, AGoldenMatchesItself) {
  const Image g = golden("rest-floor_continuous_14");
  const Comparison c = compare(g, g, Tolerance{});
  EXPECT_TRUE(c.matches());
  EXPECT_EQ(c.differing, 0u);
}

// Another Mesa build moved up to 6046 of 921600 pixels by at most 2 levels (0.66%): noise of that
// kind, on twice as many pixels, passes.
TEST(GoldenTolerance, RoundingLikeAnotherMesaBuildsPasses) {
  Image g = golden("rest-floor_continuous_14");
  Image noisy = g;
  std::uint64_t state = 1;
  std::size_t touched = 0;
  for (std::size_t i = 0; i < noisy.rgb.size(); i += 3) {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    if ((state >> 33) % 75 != 0) continue;  // ~1.3% of the pixels
    ++touched;
    for (std::size_t c = 0; c < 3; ++c) {
      const int v = noisy.rgb[i + c] + ((state >> (40 + c)) & 1 ? 2 : -2);
      noisy.rgb[i + c] = static_cast<unsigned char>(std::clamp(v, 0, 255));
    }
  }
  ASSERT_GT(touched, g.rgb.size() / 3 / 100);
  EXPECT_TRUE(matches(g, noisy)) << compare(g, noisy, Tolerance{}).describe(Tolerance{});
}

// A vertical grid line (one pixel wide) moved one pixel to the right.
//
//   before:  . . | . .        after:  . . . | .
TEST(GoldenTolerance, AGridLineShiftedByOnePixelFails) {
  const Image g = golden("crowd_continuous_4");
  // The longest vertical run of grid-line pixels with background on both sides.
  int bestX = -1, bestY = 0, bestLength = 0;
  for (int x = 1; x + 1 < g.w; ++x) {
    int run = 0;
    for (int y = 0; y < g.h; ++y) {
      const bool line = is(g.at(x, y), tv::ui::palette::kGridLine) && !is(g.at(x + 1, y), tv::ui::palette::kGridLine);
      run = line ? run + 1 : 0;
      if (run > bestLength) bestLength = run, bestX = x, bestY = y - run + 1;
    }
  }
  ASSERT_GE(bestLength, 20) << "no grid line found in the golden";
  Image moved = g;
  for (int y = bestY; y < bestY + bestLength; ++y) {
    std::copy_n(g.at(bestX, y), 3, moved.at(bestX + 1, y));
    std::copy_n(g.at(bestX - 1, y), 3, moved.at(bestX, y));
  }
  const Comparison c = compare(g, moved, Tolerance{});
  EXPECT_FALSE(c.matches()) << c.describe(Tolerance{});
  EXPECT_GE(c.beyond, static_cast<std::size_t>(bestLength));
}

// The largest body drawn one pixel to the right, its outline with it.
TEST(GoldenTolerance, ABodyDrawnOnePixelOffFails) {
  const Image g = golden("rest-floor_continuous_14");
  int x0 = g.w, y0 = g.h, x1 = -1, y1 = -1;
  for (int y = 0; y < g.h; ++y)
    for (int x = 0; x < g.w * 2 / 3; ++x)  // the world view, not the panels or the legend
      if (is(g.at(x, y), tv::ui::palette::kBody))
        x0 = std::min(x0, x), y0 = std::min(y0, y), x1 = std::max(x1, x), y1 = std::max(y1, y);
  ASSERT_GT(x1 - x0, 8) << "no body in the golden";
  Image moved = g;
  x0 = std::max(0, x0 - 2), x1 = std::min(g.w - 2, x1 + 2);
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) std::copy_n(g.at(x, y), 3, moved.at(x + 1, y));
  const Comparison c = compare(g, moved, Tolerance{});
  EXPECT_FALSE(c.matches()) << c.describe(Tolerance{});
}

// A palette colour changed by the smallest step the tolerance does not absorb: the solids' grey.
TEST(GoldenTolerance, AChangedPaletteColourFails) {
  const Image g = golden("bullets-wall_continuous_2");
  Image changed = g;
  std::size_t recoloured = 0;
  for (std::size_t i = 0; i < changed.rgb.size(); i += 3)
    if (is(&changed.rgb[i], tv::ui::palette::kSolid)) {
      changed.rgb[i] = static_cast<unsigned char>(changed.rgb[i] + Tolerance{}.channel + 1);
      ++recoloured;
    }
  ASSERT_GT(recoloured, 0u) << "the golden shows no solid";
  const Comparison c = compare(g, changed, Tolerance{});
  EXPECT_FALSE(c.matches()) << c.describe(Tolerance{});
  EXPECT_EQ(c.beyond, recoloured);
}

// The world view's labels gone ("start", "goal", "hit 1  ti ..."): every pixel of label text
// painted with the background at the left edge of its row.
TEST(GoldenTolerance, AMissingLabelFails) {
  const Image g = golden("bullets-wall_continuous_2");
  Image blank = g;
  std::size_t erased = 0;
  for (int y = 40; y < g.h; ++y)  // below the title bar
    for (int x = 1; x < g.w * 2 / 3; ++x)
      if (is(g.at(x, y), tv::ui::palette::kLabel)) {
        std::copy_n(g.at(0, y), 3, blank.at(x, y));
        ++erased;
      }
  ASSERT_GT(erased, 0u) << "the golden shows no label";
  EXPECT_FALSE(matches(g, blank));
}

// Every pixel a level or two brighter (a blend or gamma change): each within the per-channel
// tolerance, but far more pixels than rounding moves.
TEST(GoldenTolerance, EveryColourNudgedByTwoLevelsFails) {
  const Image g = golden("rest-floor_continuous_14");
  Image nudged = g;
  for (unsigned char& v : nudged.rgb) v = static_cast<unsigned char>(std::min(255, v + 2));
  const Comparison c = compare(g, nudged, Tolerance{});
  EXPECT_EQ(c.beyond, 0u);
  EXPECT_FALSE(c.matches()) << c.describe(Tolerance{});
}

TEST(GoldenTolerance, ASizeChangeFails) {
  const Image g = golden("crowd_continuous_4");
  Image cropped = g;
  cropped.h -= 1;
  cropped.rgb.resize(static_cast<std::size_t>(cropped.w) * static_cast<std::size_t>(cropped.h) * 3);
  EXPECT_FALSE(matches(g, cropped));
}

TEST(GoldenTolerance, TheOverrideIsParsedOrRefused) {
  ASSERT_TRUE(parseTolerance("0:0"));
  EXPECT_EQ(parseTolerance("0:0")->channel, 0);
  EXPECT_EQ(parseTolerance("3")->channel, 3);
  EXPECT_DOUBLE_EQ(parseTolerance("2:0.5")->fraction, 0.5);
  for (const char* bad : {"", "x", "-1", "256", "2:", "2:1.5", "2:nan", "2:0.1x"})
    EXPECT_FALSE(parseTolerance(bad)) << bad;
}

}  // namespace
}  // namespace tv::test
