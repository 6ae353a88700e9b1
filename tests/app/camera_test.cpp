// The camera: world rect -> screen rect, zoom and culling, exact far from the origin.
#include <gtest/gtest.h>

#include "tv/ui/camera.hpp"

namespace tv::ui {
namespace {

TEST(Camera, FramesAWorldRectCentredAndWhole) {
  Camera cam;
  // 200 x 100 world units into 800 x 600 px: the width limits the scale to 4 px per unit, and
  // the view grows vertically to 150 units so nothing is stretched.
  cam.frame({0, 0, 200, 100}, {0, 0}, {800, 600});
  EXPECT_DOUBLE_EQ(cam.scale(), 4.0);
  EXPECT_DOUBLE_EQ(cam.view().w, 200.0);
  EXPECT_DOUBLE_EQ(cam.view().h, 150.0);
  EXPECT_FLOAT_EQ(cam.toScreen({100, 50}).x, 400.0f);
  EXPECT_FLOAT_EQ(cam.toScreen({100, 50}).y, 300.0f);
}

TEST(Camera, FramesInsideASafeAreaButFillsTheScreen) {
  Camera cam;
  // A 40 px HUD on top and a 60 px legend below: the world goes between them.
  cam.frame({0, 0, 100, 100}, {0, 0}, {500, 600}, {0, 40}, {500, 500});
  EXPECT_DOUBLE_EQ(cam.scale(), 5.0);
  EXPECT_FLOAT_EQ(cam.toScreen({50, 50}).y, 290.0f);  // centre of the safe area
  EXPECT_FLOAT_EQ(cam.toScreen({0, 0}).y, 40.0f);
  EXPECT_DOUBLE_EQ(cam.view().h, 120.0);  // the view still covers all 600 px
}

TEST(Camera, ScreenAndWorldRoundTrip) {
  Camera cam;
  cam.frame({-30, 10, 64, 48}, {100, 20}, {640, 480});
  const Vec2 p{-12.5, 33.25};
  const Vec2 back = cam.toWorld(cam.toScreen(p));
  EXPECT_NEAR(back.x, p.x, 1e-4);
  EXPECT_NEAR(back.y, p.y, 1e-4);
}

TEST(Camera, StaysExactAtABillion) {
  // Floats hold 1e9 only to 64 units; the camera subtracts the view's corner in double first,
  // so a quarter unit still lands on the right pixel.
  Camera cam;
  cam.frame({1e9, 1e9, 16, 16}, {0, 0}, {160, 160});
  EXPECT_FLOAT_EQ(cam.toScreen({1e9 + 0.25, 1e9 + 8}).x, 2.5f);
  EXPECT_FLOAT_EQ(cam.toScreen({1e9 + 0.25, 1e9 + 8}).y, 80.0f);
}

TEST(Camera, ZoomKeepsThePointUnderTheAnchor) {
  Camera cam;
  cam.frame({0, 0, 100, 100}, {0, 0}, {400, 400});
  const ImVec2 anchor{120, 300};
  const Vec2 before = cam.toWorld(anchor);
  cam.zoom(2.5, anchor);
  const Vec2 after = cam.toWorld(anchor);
  EXPECT_NEAR(after.x, before.x, 1e-9);
  EXPECT_NEAR(after.y, before.y, 1e-9);
  EXPECT_DOUBLE_EQ(cam.scale(), 10.0);
}

TEST(Camera, SeesOnlyWhatIsInView) {
  Camera cam;
  cam.frame({0, 0, 100, 100}, {0, 0}, {100, 100});
  EXPECT_TRUE(cam.sees(Rect{50, 50, 1, 1}));
  EXPECT_TRUE(cam.sees(Rect{100, 0, 5, 5}));  // touching the edge counts
  EXPECT_FALSE(cam.sees(Rect{100.5, 0, 5, 5}));
  EXPECT_FALSE(cam.sees(Rect{-10, -10, 5, 5}));
}

}  // namespace
}  // namespace tv::ui
