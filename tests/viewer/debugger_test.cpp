// The debugger as a new user meets it (see driver.hpp). Each test is one defect a new user hit.
#include <chrono>

#include "driver.hpp"

namespace tv::viewer {
namespace {

// -- 1. compare: pan keeps the zoom -----------------------------------------------------------
//
//   +---------+---------+---------+--------+
//   | panel 0 | panel 1 | panel 2 | column |     right-drag inside panel 0, 5 px a frame:
//   |   <--   |         |         |        |     every panel moves, none zooms out
//   +---------+---------+---------+--------+
TEST_F(DebuggerDriver, PanningACompareKeepsTheZoomOfEveryPanel) {
  // As a new user gets there: one mover first (its HUD covers the top of the view), then C.
  open({"--scene", "bullets-wall", "--mover", "continuous", "--tick", "2", "--body", "2"});
  dbg().command(Command::compare);
  frames(2);
  dbg().command(Command::frameAll);
  frames(2);
  ASSERT_EQ(dbg().panels().size(), 3u);
  const double scale = dbg().panels()[0].camera.scale();
  const Rect before = dbg().panels()[0].camera.view();
  ImVec2 mouse{200, 300};
  frame(mouse, true);
  for (int i = 0; i < 20; ++i) {
    mouse.x -= 5.0f;
    frame(mouse, true);
  }
  frame(mouse, false);
  frames(2);
  for (const ui::DebuggerState& p : dbg().panels()) {
    EXPECT_NEAR(p.camera.scale(), scale, scale * 1e-9);
    EXPECT_NEAR(p.camera.view().w, before.w, before.w * 1e-9);
  }
  // The drag moved the world: 100 px to the left is up to 100 / scale units to the right (the
  // first few px are ImGui's drag threshold).
  EXPECT_GT(dbg().panels()[0].camera.view().x - before.x, 80.0 / scale);
  EXPECT_LE(dbg().panels()[0].camera.view().x - before.x, 100.0 / scale + 1e-9);
  EXPECT_NEAR(dbg().panels()[2].camera.view().x, dbg().panels()[0].camera.view().x, 1e-6);
}

// -- 2. a huge speed is refused, not a frozen window --------------------------------------------
TEST_F(DebuggerDriver, AHugeSpeedIsRefusedNamingTheLimitAndChangesNothing) {
  open({"--scene", "bullets-wall", "--compare", "discrete,substep-discrete,continuous", "--tick",
        "2"});
  const auto t0 = std::chrono::steady_clock::now();
  EXPECT_THROW(open({"--scene", "bullets-wall", "--compare", "discrete,substep-discrete",
                     "--speed", "1e9"}),
               ui::UsageError);
  // What a slider or a typed value does: the draft is applied by a restart.
  open({"--scene", "bullets-wall", "--compare", "discrete,substep-discrete,continuous", "--tick",
        "2"});
  EXPECT_FALSE(dbg().tune("speed", 1e9));
  frames(2);
  EXPECT_NE(dbg().message().find("the limit is 1 s per tick"), std::string::npos)
      << dbg().message();
  EXPECT_EQ(dbg().currentTick(), 2u);
  // Nothing changed: the panel shows the speed that runs, the reason beside it.
  EXPECT_EQ(dbg().panels()[0].draft.get("speed"), 1920.0);
  EXPECT_NE(dbg().panels()[0].error.find("the limit is"), std::string::npos);
  const std::chrono::duration<double> spent = std::chrono::steady_clock::now() - t0;
  // Not a timing assertion on speed: a hang would be minutes (it was 80 s and 4 GB).
  EXPECT_LT(spent.count(), 60.0);
}

// -- 3. the timeline checks every compared mover -----------------------------------------------
TEST_F(DebuggerDriver, TheTimelineReportsTheFirstFailureOfAnyComparedMover) {
  // With 32 px pieces substep-discrete tunnels like discrete; continuous does not.
  open({"--scene", "bullets-wall", "--compare", "discrete,substep-discrete,continuous",
        "--substep", "32"});
  ASSERT_TRUE(dbg().checks().done());
  ASSERT_TRUE(dbg().checks().firstFailure().has_value());
  EXPECT_EQ(*dbg().checks().firstFailure(), 1u);
  const std::string& what = dbg().checks().failureText();
  EXPECT_NE(what.find("discrete tunnelled"), std::string::npos) << what;
  EXPECT_NE(what.find("substep-discrete tunnelled"), std::string::npos) << what;
  EXPECT_EQ(what.find("continuous"), std::string::npos) << what;
}

TEST_F(DebuggerDriver, MoversThatAllHoldReportNoFailure) {  // the negative control
  open({"--scene", "bullets-wall", "--compare", "sweep,continuous"});
  ASSERT_TRUE(dbg().checks().done());
  EXPECT_FALSE(dbg().checks().firstFailure().has_value()) << dbg().checks().failureText();
}

// -- 4. a sweep row keeps the comparison; duplicates are refused --------------------------------
TEST_F(DebuggerDriver, PickingASubstepLengthKeepsTheFirstComparedMover) {
  open({"--scene", "bullets-wall", "--compare", "discrete,substep-discrete,continuous", "--tick",
        "2"});
  dbg().useSubstepLength(4.0);
  frames(2);
  ASSERT_EQ(dbg().movers().size(), 3u);
  EXPECT_EQ(dbg().movers()[0].name(), "discrete");
  EXPECT_EQ(dbg().movers()[1].name(), "substep-discrete");
  EXPECT_EQ(dbg().currentTick(), 2u);

  // No substep mover compared: the swept one joins as a new panel.
  open({"--scene", "bullets-wall", "--compare", "discrete,continuous", "--tick", "2"});
  dbg().useSubstepLength(4.0);
  ASSERT_EQ(dbg().movers().size(), 3u);
  EXPECT_EQ(dbg().movers()[0].name(), "discrete");
  EXPECT_EQ(dbg().movers()[1].name(), "continuous");
  EXPECT_EQ(dbg().movers()[2].name(), "substep-discrete");
}

TEST_F(DebuggerDriver, AMoverNamedTwiceIsRefused) {
  EXPECT_THROW(open({"--compare", "substep-discrete,substep-discrete,continuous"}),
               ui::UsageError);
}

struct Layout {
  float w, h;
  std::vector<std::string> args;
};

TEST_F(DebuggerDriver, NoTextIsCutAtAPanelsEdge) {
  const std::vector<Layout> cases = {
      {1280, 720, {"--scene", "bullets-wall", "--compare", "discrete,substep-discrete,continuous",
                   "--tick", "2", "--body", "2", "--view", "follow"}},
      {1024, 640, {"--scene", "bullets-wall", "--compare", "discrete,substep-discrete,continuous",
                   "--tick", "2", "--body", "2", "--view", "follow"}},
      {1024, 640, {"--scene", "seam-walk", "--compare", "discrete,continuous", "--tick", "18",
                   "--body", "0", "--view", "follow", "--speed", "250"}},
      {1280, 720, {"--scene", "seam-walk", "--tick", "9", "--body", "0", "--view", "follow"}},
      {1024, 640, {"--scene", "bounce-gap", "--mover", "discrete", "--tick", "1", "--body", "0",
                   "--view", "follow"}},
      {1280, 720, {sampleRecording(), "--view", "follow", "--what-if", "discrete",
                   "--first-failure"}},
      {1024, 640, {sampleRecording(), "--frame", "62", "--call", "2", "--what-if", "discrete"}},
      {1024, 640, {sampleRecording(), "--what-if", "discrete", "--tab", "failures"}},
      {1024, 640, {"--scene", "bullets-wall", "--tab", "failures"}},
      // Three panels: "pushed back out of floor tile 2" is wider than each.
      {1024, 640, {"--scene", "seam-walk", "--compare", "discrete,substep-discrete,continuous"}},
      // Moving solids and one-way sides: the legend's five more entries, the longer verdict.
      {1280, 720, {"--scene", "lift-crush", "--mover", "continuous", "--tick", "3", "--body",
                   "3", "--view", "-8,-40,456,400"}},
      {1024, 640, {"--scene", "lift-crush", "--mover", "continuous", "--tick", "3", "--body",
                   "3", "--view", "-8,-40,456,400", "--carry", "0"}},
      {1024, 640, {"--scene", "one-way-rise", "--compare", "discrete,continuous", "--tick", "3",
                   "--body", "2"}},
      {1024, 640, {"--scene", "corner-nudge", "--mover", "continuous", "--tick", "4", "--body",
                   "4", "--view", "100,30,290,100"}},
  };
  for (const Layout& c : cases) {
    resize(c.w, c.h);
    open(c.args);
    frames(3);
    std::string where;
    EXPECT_EQ(cutGlyphs(&where), 0) << c.w << "x" << c.h << " " << c.args[1] << ": " << where;
  }
  // A refusal explains itself in the panel and the bar, whole.
  resize(1024, 640);
  open(cases[1].args);
  EXPECT_FALSE(dbg().tune("speed", 1e9));
  frames(3);
  std::string where;
  EXPECT_EQ(cutGlyphs(&where), 0) << "refused speed: " << where;
}

// -- 8. small frictions ------------------------------------------------------------------------
TEST_F(DebuggerDriver, EscClosesTheTopmostWindowHelpIncluded) {
  open({"--scene", "bullets-wall", "--sweep"});
  dbg().openHelp();
  frame();
  ASSERT_TRUE(dbg().helpOpen());
  frame({-FLT_MAX, -FLT_MAX}, false, {KeyPress{GLFW_KEY_ESCAPE, 0}});
  EXPECT_FALSE(dbg().helpOpen());
}

TEST_F(DebuggerDriver, PlayOnAnEndedScenePlaysItAgainAndSaysSo) {
  open({"--scene", "bullets-wall", "--mover", "continuous", "--tick", "1"});
  dbg().command(Command::pause);  // play
  for (int i = 0; i < 2000 && !dbg().paused(); ++i) frame();
  ASSERT_TRUE(dbg().paused());
  const std::uint64_t end = dbg().currentTick();
  EXPECT_NE(dbg().notice().find("ended at tick " + std::to_string(end)), std::string::npos);
  dbg().command(Command::pause);
  EXPECT_FALSE(dbg().paused());
  EXPECT_EQ(dbg().currentTick(), 0u);
  EXPECT_NE(dbg().notice().find("playing again"), std::string::npos) << dbg().notice();
}

TEST_F(DebuggerDriver, SteppingBackFromTheEndNoLongerSaysTheSceneEnded) {
  open({"--scene", "bullets-wall", "--mover", "continuous", "--tick", "1"});
  dbg().command(Command::pause);  // play to the end, where it stops and says so
  for (int i = 0; i < 2000 && !dbg().paused(); ++i) frame();
  ASSERT_NE(dbg().notice().find("ended at tick"), std::string::npos) << dbg().notice();
  dbg().command(Command::pause);  // plays again from 0, and says so
  EXPECT_NE(dbg().notice().find("playing again"), std::string::npos) << dbg().notice();
  for (int i = 0; i < 2000 && !dbg().paused(); ++i) frame();
  ASSERT_NE(dbg().notice().find("ended at tick"), std::string::npos) << dbg().notice();
  dbg().command(Command::stepBack);  // before the end: it has not ended there
  frames(2);
  EXPECT_EQ(dbg().notice().find("ended"), std::string::npos) << dbg().notice();
}

TEST_F(DebuggerDriver, TunedParametersAreSavedWithTheSettings) {
  open({"--scene", "bullets-wall", "--mover", "substep-discrete", "--tick", "1"});
  ASSERT_TRUE(dbg().tune("substep", 4.0));
  Settings saved;
  dbg().store(saved);
  std::vector<std::string> args = {"tv-debugger"};
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  const Debugger again(parseViewerOptions(1, argv.data()), &saved);
  EXPECT_EQ(again.panels()[0].draft.get("substep"), 4.0);
  EXPECT_EQ(again.movers()[0].name(), "substep-discrete");
}

}  // namespace
}  // namespace tv::viewer
