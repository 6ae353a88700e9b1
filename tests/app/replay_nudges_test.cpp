// A recorded game's corner corrections in the debugger: the recording's cornerNudge calls become
// the picture's nudges for the frame on screen (up to the selected call), drawn as a scene's
// are. The same jump recorded without correction draws none: the negative control.
#include <gtest/gtest.h>

#include <set>

#include "imgui.h"
#include "imgui_frame.hpp"
#include "tv/corner.hpp"
#include "tv/record/recorder.hpp"
#include "tv/record/replay.hpp"
#include "tv/ui/camera.hpp"
#include "tv/ui/overlays.hpp"
#include "tv/ui/panels.hpp"
#include "tv/ui/palette.hpp"
#include "tv/ui/replay_source.hpp"

namespace tv::ui {
namespace {

//          +------------------------------+
//          |        ceiling {16, 0, 32, 8}  |
//       +--+-----------------------------+
//       |b |   body {10, 40, 8, 12} jumps to y 0 in frame 1: it meets the ceiling at (10, 8),
//       +--+   2 px under its left end, and is nudged to x 8 (tv::moveCornered)
struct Jump {
  ItemId ceiling, body;
  std::vector<std::uint8_t> bytes;
};

Jump recordJump(double maxNudge) {
  Jump j;
  World w(16);
  Recorder rec;
  w.attach(rec);
  j.ceiling = w.add({16, 0, 32, 8});
  j.body = w.add({10, 40, 8, 12});
  rec.label(j.body, "jumper", "player");
  rec.frame();  // frame 1: the jump
  CornerOptions o;
  o.maxNudge = maxNudge;
  (void)moveCornered(w, j.body, {10, 0}, o);
  rec.frame();  // frame 2: standing still
  (void)w.queryRect({0, 0, 64, 64});
  w.detach();
  rec.close();
  j.bytes = rec.bytes();
  return j;
}

std::set<ImU32> coloursIn(const WorldPicture& pic) {
  Camera cam;
  cam.frame({0, -8, 64, 64}, {0, 0}, {1280, 720});
  return testing::coloursDrawn(cam, pic);
}

using ReplayNudges = testing::ImGuiFrame;

TEST_F(ReplayNudges, ARecordedNudgeIsInTheFramesPictureAndDrawnInItsColour) {
  const Jump j = recordJump(4);
  ReplaySource s(Replay::fromBytes(j.bytes), "jump");
  s.goTo(1);
  const WorldPicture p = s.picture();
  ASSERT_EQ(p.nudges.size(), 1u);
  const sim::CornerNudgeAt& n = p.nudges[0];
  EXPECT_EQ(n.ceiling, j.ceiling);
  EXPECT_EQ(n.from, (Rect{10, 8, 8, 12})) << "where it met the corner";
  EXPECT_EQ(n.to, (Rect{8, 8, 8, 12})) << "where the nudge put it";
  ASSERT_LT(n.body, p.bodies.size());
  EXPECT_EQ(p.bodies[n.body].item, j.body);
  EXPECT_TRUE(coloursIn(p).count(palette::kNudge));
  // Only the frame that made it: the next frame has none.
  s.goTo(2);
  EXPECT_TRUE(s.picture().nudges.empty());
  EXPECT_FALSE(coloursIn(s.picture()).count(palette::kNudge));
}

TEST_F(ReplayNudges, WithACallSelectedOnlyTheNudgesUpToItAreShown) {
  const Jump j = recordJump(4);
  ReplaySource s(Replay::fromBytes(j.bytes), "jump");
  s.goTo(1);
  std::optional<std::uint32_t> nudgeCall;
  for (std::uint32_t k = 0; k < s.calls().size(); ++k)
    if (s.calls()[k].kind == CallKind::cornerNudge) nudgeCall = k;
  ASSERT_TRUE(nudgeCall);
  ASSERT_GT(*nudgeCall, 0u);
  s.selectCall(*nudgeCall - 1);  // the last move of the correction: not yet said to be one
  EXPECT_TRUE(s.picture().nudges.empty());
  s.selectCall(*nudgeCall);
  EXPECT_EQ(s.picture().nudges.size(), 1u);
}

TEST_F(ReplayNudges, NegativeControlTheSameJumpWithoutCorrectionDrawsNoNudge) {
  const Jump j = recordJump(0);
  ReplaySource s(Replay::fromBytes(j.bytes), "jump");
  s.goTo(1);
  EXPECT_TRUE(s.picture().nudges.empty());
  EXPECT_FALSE(coloursIn(s.picture()).count(palette::kNudge));
  EXPECT_FALSE(legendScopeOf(s).has & palette::kWithCornerNudge);
}

TEST_F(ReplayNudges, TheLegendNamesTheNudgeColourOfARecordingThatHasNudges) {
  const Jump j = recordJump(4);
  ReplaySource s(Replay::fromBytes(j.bytes), "jump");
  EXPECT_TRUE(legendScopeOf(s).has & palette::kWithCornerNudge);
}

}  // namespace
}  // namespace tv::ui
