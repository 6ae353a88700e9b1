// The fixed-step accumulator: physics in equal ticks whatever the render rate.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "tv/error.hpp"
#include "tv/timestep.hpp"

namespace tv {
namespace {

TEST(FixedStep, RunsOneTickPerFrameAtTheStepRate) {
  FixedStep clock(1.0 / 60.0);
  int ticks = 0;
  for (int f = 0; f < 600; ++f) ticks += clock.advance(1.0 / 60.0);
  EXPECT_NEAR(ticks, 600, 1);  // rounding may carry the last tick into the next frame
  EXPECT_EQ(clock.ticks(), static_cast<std::uint64_t>(ticks));
  EXPECT_EQ(clock.frames(), 600u);
}

TEST(FixedStep, RunsTheSameTicksPerSecondAtAnyRenderRate) {
  for (const double hz : {30.0, 60.0, 144.0, 240.0, 360.0}) {
    FixedStep clock(1.0 / 60.0);
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<> jitter(0.8, 1.2);
    double elapsed = 0;
    while (elapsed < 10.0) {
      const double dt = jitter(rng) / hz;
      elapsed += dt;
      (void)clock.advance(dt);
    }
    EXPECT_NEAR(static_cast<double>(clock.ticks()), elapsed * 60.0, 1.0) << hz;
    EXPECT_GE(clock.alpha(), 0.0);
    EXPECT_LT(clock.alpha(), 1.0);
  }
}

TEST(FixedStep, CapsALongHitchInsteadOfSpiralling) {
  FixedStep clock(1.0 / 60.0, 0.25);
  EXPECT_EQ(clock.advance(2.0), 15);  // 0.25 s of catch-up, not 120 ticks
  EXPECT_EQ(clock.clampedFrames(), 1u);
}

TEST(FixedStep, AlphaSaysWhereTheFrameFallsBetweenTicks) {
  FixedStep clock(0.5, 1.0);
  EXPECT_EQ(clock.advance(0.75), 1);
  EXPECT_EQ(clock.alpha(), 0.5);
  EXPECT_EQ(interpolate({0, 0}, {10, -4}, clock.alpha()), (Vec2{5, -2}));
  EXPECT_EQ(floorOnDraw({3.99, -0.5}), (Vec2{3, -1}));
}

TEST(FixedStep, BadInputNamesTheValueAndChangesNothing) {
  const auto message = [](auto&& f) {
    try {
      f();
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message([] { FixedStep s(0.0); }).find("step must be finite and > 0, but was 0"),
            std::string::npos);
  EXPECT_NE(message([] { FixedStep s(NAN); }).find("nan"), std::string::npos);
  EXPECT_NE(message([] { FixedStep s(0.1, 0.05); }).find("maxFrameTime"), std::string::npos);
  FixedStep clock(0.1, 1.0);
  (void)clock.advance(0.15);
  EXPECT_NE(message([&] { (void)clock.advance(-1.0); }).find("-1"), std::string::npos);
  EXPECT_NE(message([&] { (void)clock.advance(INFINITY); }).find("inf"), std::string::npos);
  EXPECT_EQ(clock.ticks(), 1u);
  EXPECT_EQ(clock.frames(), 1u);
  EXPECT_NEAR(clock.accumulator(), 0.05, 1e-15);
}

}  // namespace
}  // namespace tv
