// The debugger as a new user meets it, driven frame by frame through ImGui without a window:
// the mouse and keys are set on ImGuiIO, frames are built (never rendered) and the debugger's
// state and draw lists are read back. Each test is one defect a new user hit.
#include <gtest/gtest.h>

#include <GLFW/glfw3.h>

#include <cfloat>
#include <chrono>
#include <memory>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "debugger.hpp"
#include "imgui.h"
#include "options.hpp"
#include "tv/ui/palette.hpp"

namespace tv::viewer {
namespace {

class DebuggerDriver : public ::testing::Test {
 protected:
  void SetUp() override {
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    io.DeltaTime = 1.0f / 60.0f;
    ui::applyStyle(ImGui::GetStyle());  // the debugger's compact look, as the window has it
    unsigned char* pixels = nullptr;
    int w = 0, h = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);
    resize(1280, 720);
  }
  void TearDown() override {
    debugger_.reset();
    ImGui::DestroyContext();
  }

  static void resize(float w, float h) { ImGui::GetIO().DisplaySize = {w, h}; }

  void open(const std::vector<std::string>& given) {
    std::vector<std::string> args = {"tv-debugger"};
    args.insert(args.end(), given.begin(), given.end());
    args.push_back("--no-settings");
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    const ViewerOptions o = parseViewerOptions(static_cast<int>(argv.size()), argv.data());
    debugger_ = std::make_unique<Debugger>(o, nullptr);
    debugger_->setPinned(true);  // the look-ahead runs to its end: marks do not depend on speed
    frames(3);
  }

  // One frame with the mouse at `mouse` (off screen by default) and `right` held.
  void frame(ImVec2 mouse = {-FLT_MAX, -FLT_MAX}, bool right = false,
             std::vector<KeyPress> keys = {}) {
    ImGuiIO& io = ImGui::GetIO();
    io.MousePos = mouse;
    io.MouseDown[1] = right;
    ImGui::NewFrame();
    debugger_->frame(1.0 / 60.0, keys);
    ImGui::Render();
  }
  void frames(int n) {
    for (int i = 0; i < n; ++i) frame();
  }

  Debugger& dbg() { return *debugger_; }

 private:
  std::unique_ptr<Debugger> debugger_;
};

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
  ASSERT_TRUE(dbg().divergence().done());
  ASSERT_TRUE(dbg().divergence().firstFailure().has_value());
  EXPECT_EQ(*dbg().divergence().firstFailure(), 1u);
  const std::string& what = dbg().divergence().failureText();
  EXPECT_NE(what.find("discrete tunnelled"), std::string::npos) << what;
  EXPECT_NE(what.find("substep-discrete tunnelled"), std::string::npos) << what;
  EXPECT_EQ(what.find("continuous"), std::string::npos) << what;
}

TEST_F(DebuggerDriver, MoversThatAllHoldReportNoFailure) {  // the negative control
  open({"--scene", "bullets-wall", "--compare", "sweep,continuous"});
  ASSERT_TRUE(dbg().divergence().done());
  EXPECT_FALSE(dbg().divergence().firstFailure().has_value()) << dbg().divergence().failureText();
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

// -- 5. no text outside its panel ------------------------------------------------------------
// A glyph that straddles the left or right side of its draw command's clip rect is text cut
// off at a panel's edge ("erlapping touch"). Every glyph of every window must lie inside its
// clip rect across; the top and bottom are where a window scrolls, which is not a defect.
int cutGlyphs(std::string* where) {
  const ImDrawData* dd = ImGui::GetDrawData();
  // A glyph is a quad drawn as two triangles; its first triangle runs from the vertex with the
  // glyph's (U0, V0) to the one with its (U1, V1). Lines and shapes use other UVs. Triangles are
  // walked one by one: other primitives in the same command need not come in sixes.
  const ImVector<ImFontGlyph>& glyphs = ImGui::GetIO().Fonts->Fonts[0]->Glyphs;
  const auto isGlyph = [&](ImVec2 uv0, ImVec2 uv2) {
    for (const ImFontGlyph& g : glyphs) {
      if (g.U0 == uv0.x && g.V0 == uv0.y && g.U1 == uv2.x && g.V1 == uv2.y && g.X1 > g.X0)
        return true;
    }
    return false;
  };
  int cut = 0;
  for (int l = 0; l < dd->CmdListsCount; ++l) {
    const ImDrawList* dl = dd->CmdLists[l];
    for (const ImDrawCmd& cmd : dl->CmdBuffer) {
      if (cmd.UserCallback) continue;
      const ImVec4 clip = cmd.ClipRect;
      for (unsigned i = 0; i + 3 <= cmd.ElemCount; i += 3) {
        const ImDrawIdx* idx = dl->IdxBuffer.Data + cmd.IdxOffset + i;
        const ImDrawVert& a = dl->VtxBuffer[static_cast<int>(cmd.VtxOffset + idx[0])];
        const ImDrawVert& c = dl->VtxBuffer[static_cast<int>(cmd.VtxOffset + idx[2])];
        if (!isGlyph(a.uv, c.uv)) continue;
        const float x0 = std::min(a.pos.x, c.pos.x), x1 = std::max(a.pos.x, c.pos.x);
        const float y0 = std::min(a.pos.y, c.pos.y), y1 = std::max(a.pos.y, c.pos.y);
        const bool inside = x0 >= clip.x - 0.5f && x1 <= clip.z + 0.5f;
        const bool visible = x1 > clip.x && x0 < clip.z && y1 > clip.y && y0 < clip.w;
        if (visible && !inside) {
          ++cut;
          char text[160];
          std::snprintf(text, sizeof text, "%s at (%.0f, %.0f); ",
                        dl->_OwnerName ? dl->_OwnerName : "?", static_cast<double>(x0),
                        static_cast<double>(y0));
          if (where->size() < 600) where->append(text);
        }
      }
    }
  }
  return cut;
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
