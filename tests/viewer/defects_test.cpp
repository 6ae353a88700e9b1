// Each test is one defect a fresh-eyes review found in the debugger, reproduced the way a new
// user met it, with the control that shows the fix is not a coincidence.
#include <cstdio>
#include <fstream>

#include "driver.hpp"
#include "tv/ui/sim_source.hpp"

namespace tv::viewer {
namespace {

// The status bar dropped "movers differ" at 1280 px when the first failure named two movers,
// and always at 1024. It now has a row of its own: both are drawn, whole, at both widths.
TEST_F(DebuggerDriver, TheStatusRowShowsTheFirstFailureAndWhereTheMoversDiffer) {
  for (const float w : {1280.0f, 1024.0f}) {
    resize(w, w == 1280.0f ? 720.0f : 640.0f);
    // With 32 px pieces substep-discrete tunnels like discrete: the failure names two movers.
    open({"--scene", "bullets-wall", "--compare", "discrete,substep-discrete,continuous",
          "--substep", "32", "--tick", "2", "--body", "2"});
    frames(2);
    const std::string row = drawnText("Timeline");
    EXPECT_NE(row.find("first failure: tick 1, discrete tunnelled, substep-discrete tunnelled"),
              std::string::npos)
        << w << ": " << row;
    EXPECT_NE(row.find("movers differ from tick 1"), std::string::npos) << w << ": " << row;
    EXPECT_EQ(row.find("more)"), std::string::npos) << w << ": nothing left over: " << row;
    std::string where;
    EXPECT_EQ(cutGlyphs(&where), 0) << w << ": " << where;
  }
}

// Dragging a slider to a value re-runs live, then its release applied "again": nothing had
// changed since the drag, so it restarted at tick 0. Typing the same value kept the tick. An
// edit now always lands on the tick on screen; only Restart goes to 0.
TEST_F(DebuggerDriver, ReleasingADraggedSliderKeepsTheTick) {
  open({"--scene", "seam-walk", "--mover", "continuous", "--tick", "40", "--body", "0"});
  ASSERT_TRUE(dbg().tune("speed", 200.0));  // the drag, applied live
  EXPECT_EQ(dbg().currentTick(), 40u);
  ASSERT_TRUE(dbg().tune("speed", 200.0));  // the release: the same value again
  frames(2);
  EXPECT_EQ(dbg().currentTick(), 40u);
  dbg().command(Command::restart);  // the control: Restart does go to tick 0
  EXPECT_EQ(dbg().currentTick(), 0u);
}

// A value that makes the scene end sooner lands on its new end, and says so.
TEST_F(DebuggerDriver, ATuneThatShortensTheSceneLandsOnItsEndAndSaysSo) {
  // corner-graze's shots are done once past their tiles: at 960 px/s at tick 6, at 1920 at 5.
  open({"--scene", "corner-graze", "--mover", "continuous", "--speed", "960", "--tick", "6"});
  ASSERT_EQ(dbg().currentTick(), 6u);
  ASSERT_TRUE(dbg().tune("speed", 1920.0));
  frames(2);
  EXPECT_EQ(dbg().currentTick(), 5u);
  EXPECT_NE(dbg().notice().find("now ends at tick " + std::to_string(dbg().currentTick())),
            std::string::npos)
      << dbg().notice();
}

// I opened the Items tab without focusing its search, so what was typed next went to the
// shortcuts: a space in "bullet 4" started playback. In the what-if layout I did nothing.
TEST_F(DebuggerDriver, IFocusesTheItemsSearchAndWhatIsTypedGoesThere) {
  for (const bool whatIf : {false, true}) {
    std::vector<std::string> args = {sampleRecording(), "--frame", "30"};
    if (whatIf) args.insert(args.end(), {"--what-if", "discrete"});
    open(args);
    ASSERT_TRUE(dbg().paused());
    ImGui::GetIO().AddInputCharacter('i');
    frames(3);
    for (const char c : std::string("bullet 4"))
      ImGui::GetIO().AddInputCharacter(static_cast<unsigned>(static_cast<unsigned char>(c)));
    frames(2);
    EXPECT_TRUE(dbg().paused()) << (whatIf ? "what-if" : "recording") << ": the space played";
    EXPECT_EQ(dbg().view().items.filter, "bullet 4") << (whatIf ? "what-if" : "recording");
  }
}

TEST_F(DebuggerDriver, ASpaceWithNoTextFieldActivePlays) {  // the control: the shortcut works
  open({sampleRecording(), "--frame", "30"});
  ImGui::GetIO().AddInputCharacter(' ');
  frames(1);
  EXPECT_FALSE(dbg().paused());
}

// At 1024x640 each panel's "cand./move" line ran under the legend, and Help covered the
// tuning panel on the first run.
TEST_F(DebuggerDriver, At1024EveryPanelLineIsWholeAndHelpLeavesTheControlsInView) {
  resize(1024, 640);
  open({"--scene", "bullets-wall", "--compare", "discrete,substep-discrete,continuous", "--tick",
        "2", "--body", "2", "--view", "follow"});
  dbg().openHelp();
  frames(3);
  // No glyph of a panel is cut at its bottom edge.
  const ImDrawData* dd = ImGui::GetDrawData();
  int cut = 0;
  for (int l = 0; l < dd->CmdListsCount; ++l) {
    const ImDrawList* dl = dd->CmdLists[l];
    const std::string owner = dl->_OwnerName ? dl->_OwnerName : "";
    if (owner.find("###panel") == std::string::npos) continue;
    for (const ImDrawCmd& cmd : dl->CmdBuffer) {
      for (unsigned i = 0; i < cmd.ElemCount; ++i) {
        const ImDrawVert& v = dl->VtxBuffer[static_cast<int>(cmd.VtxOffset + dl->IdxBuffer[static_cast<int>(cmd.IdxOffset + i)])];
        if (v.pos.y > cmd.ClipRect.w + 0.5f && v.pos.y < cmd.ClipRect.w + 14.0f) ++cut;
      }
    }
  }
  EXPECT_EQ(cut, 0) << "a panel's last lines run past its bottom";
  const std::string panels = drawnText("###panel0");
  EXPECT_NE(panels.find("cand./move"), std::string::npos) << panels;
  // Help and the controls do not overlap.
  const ImRect help = windowRect("Help (F1)");
  const ImRect controls = windowRect("Scene and mover");
  ASSERT_GT(help.GetArea(), 0.0f);
  ASSERT_GT(controls.GetArea(), 0.0f);
  EXPECT_FALSE(help.Overlaps(controls));
}

// Help sat where the column's tabs were when it opened: opening the controls' Overlays (or a
// window resized) moved the tabs down and the controls ran under Help. It follows the tabs now,
// until the person drags it.
TEST_F(DebuggerDriver, HelpFollowsTheColumnsTabsWhenTheLayoutMoves) {
  open({"--scene", "bullets-wall", "--tick", "2", "--body", "2"});
  dbg().openHelp();
  frames(3);
  const ImVec2 first = dbg().view().tabsPos;
  resize(1024, 640);
  frames(3);  // the controls' height settles over a frame or two, as when Help opens
  const ImVec2 tabs = dbg().view().tabsPos;
  ASSERT_NE(tabs.x, first.x) << "the tabs did not move: the test shows nothing";
  const ImRect help = windowRect("Help (F1)");
  EXPECT_NEAR(help.Min.x, tabs.x, 1.0f);  // ImGui puts windows on whole pixels
  EXPECT_NEAR(help.Min.y, tabs.y, 1.0f);
  EXPECT_FALSE(help.Overlaps(windowRect("Scene and mover")));
}

// What-if opened on the mover shown, and "Run beside it" ran discrete beside discrete: the
// Failures tab listed each failure twice (1482) while the status bar said, in green, "no
// failure in 2 ticks". A mover is shown once; movers that fail alike are not "no failure".
TEST_F(DebuggerDriver, AMoverIsNotRunBesideItselfAndSharedFailuresAreNotNoFailure) {
  open({"--scene", "bullets-wall", "--mover", "discrete", "--tick", "2", "--body", "2"});
  dbg().compareWith({MoverSpec{.kind = MoverKind::discrete}});
  EXPECT_FALSE(dbg().session().comparing());
  EXPECT_NE(dbg().message().find("discrete is already shown"), std::string::npos) << dbg().message();
  dbg().compareWith({MoverSpec{.kind = MoverKind::continuous}});  // the control: another mover
  EXPECT_TRUE(dbg().session().comparing()) << dbg().message();
  // Pieces longer than the whole move: substep-discrete teleports as discrete does, and both
  // send the same 741 bullets through. Neither is worse; their failures are listed.
  open({"--scene", "bullets-wall", "--compare", "discrete,substep-discrete", "--substep", "1000",
        "--tick", "2"});
  frames(5);
  ASSERT_TRUE(dbg().checks().done());
  ASSERT_FALSE(dbg().checks().firstFailure()) << "one mover did worse: the test shows nothing";
  ASSERT_FALSE(dbg().checks().failures().entries.empty());
  std::string all;
  for (const std::string& s : dbg().status()) all += s + " | ";
  EXPECT_EQ(all.find("no failure in"), std::string::npos) << all;
  EXPECT_NE(all.find("failures are listed"), std::string::npos) << all;
}

// V in one panel showed nothing but flipped a hidden setting: the next what-if then opened
// overlaid instead of beside. It says what it is for and changes nothing.
TEST_F(DebuggerDriver, OverlaidIsOnlyForComparedMovers) {
  open({"--scene", "bullets-wall", "--mover", "discrete", "--tick", "2"});
  dbg().command(Command::overlay);
  EXPECT_FALSE(dbg().view().overlaid);
  EXPECT_NE(dbg().notice().find("compare first"), std::string::npos) << dbg().notice();
  dbg().compareWith({MoverSpec{.kind = MoverKind::continuous}});
  ASSERT_TRUE(dbg().session().comparing()) << dbg().message();
  dbg().command(Command::overlay);  // the control: compared, V overlays them
  EXPECT_TRUE(dbg().view().overlaid);
  EXPECT_TRUE(dbg().notice().empty()) << "a hint that no longer holds: " << dbg().notice();
}

// The scene picker cut its descriptions, and a recording's call lines were cut at the column's
// edge; both wrap now.
TEST_F(DebuggerDriver, PickerDescriptionsAndCallLinesAreWhole) {
  resize(1024, 640);
  open({"--scene", "bullets-wall", "--mover", "continuous", "--tick", "1"});
  dbg().command(Command::openScene);
  frames(3);
  std::string where;
  EXPECT_EQ(cutGlyphs(&where), 0) << "picker: " << where;
  const std::string picker = drawnText("Open scene");
  EXPECT_NE(picker.find("bump.lua's benchmark"), std::string::npos) << picker;
  open({sampleRecording(), "--frame", "62", "--call", "2"});
  frames(3);
  where.clear();
  EXPECT_EQ(cutGlyphs(&where), 0) << "calls: " << where;
  const std::string calls = drawnText("###Calls");
  EXPECT_NE(calls.find("ended at"), std::string::npos) << calls;
}

// The substep sweep marked "8 (now)" while the substep field read 0: both now say 0 is tile/2.
TEST_F(DebuggerDriver, TheSubstepFieldSaysWhatZeroComesTo) {
  open({"--scene", "bullets-wall", "--mover", "substep-discrete", "--tick", "1", "--sweep"});
  frames(4);
  const std::string controls = drawnText("Scene and mover");
  EXPECT_NE(controls.find("0 = tile/2 = 8 px"), std::string::npos) << controls;
  const std::string sweep = drawnText("Substep sweep");
  EXPECT_NE(sweep.find("8  (now)"), std::string::npos) << sweep;
  EXPECT_NE(sweep.find("the length now: 8 px (the substep parameter is 0: tile/2)"),
            std::string::npos)
      << sweep;
  std::string where;
  EXPECT_EQ(cutGlyphs(&where), 0) << where;
}

// A map with nothing solid showed an empty world with a green verdict, its note on stderr only.
TEST_F(DebuggerDriver, AMapWithNothingSolidSaysSoInTheWindow) {
  const std::string path = ::testing::TempDir() + "tv_nothing_solid.tmj";
  {
    std::ofstream out(path);
    out << R"({"type": "map", "width": 20, "height": 10, "tilewidth": 16, "tileheight": 16,
      "infinite": false, "orientation": "orthogonal", "layers": [
      {"type": "objectgroup", "name": "actors", "objects": [
        {"id": 1, "type": "walker", "x": 40, "y": 40, "width": 12, "height": 12}]}]})";
  }
  open({"--map", path, "--tick", "1"});
  frames(2);
  const std::string hud = drawnText("HUD");
  EXPECT_NE(hud.find("nothing is solid"), std::string::npos) << hud;
  EXPECT_EQ(hud.find("nothing failed"), std::string::npos) << hud;
}

// A recording draws an item that never moves but has a category (a standing enemy) in that
// category's colour, and its legend says so; a scene has no such item, so its legend leaves the
// entry out (and its pictures keep their room). The longer label is whole in one panel and in
// a what-if view, at 1280 and at 1024 px.
TEST_F(DebuggerDriver, OnlyARecordingsLegendNamesTheCategoryColourAndItsLabelIsWhole) {
  open({"--scene", "bullets-wall", "--tick", "1"});
  frames(2);
  EXPECT_EQ(drawnText("Legend").find("never moves"), std::string::npos) << drawnText("Legend");
  EXPECT_NE(drawnText("Legend").find("body, stopped"), std::string::npos);
  for (const float w : {1280.0f, 1024.0f}) {
    resize(w, w == 1280.0f ? 720.0f : 640.0f);
    for (const bool whatIf : {false, true}) {
      std::vector<std::string> args = {sampleRecording(), "--frame", "62", "--call", "2"};
      if (whatIf) args.insert(args.end(), {"--what-if", "discrete"});
      open(args);
      frames(2);
      const std::string legend = drawnText("Legend");
      EXPECT_NE(legend.find("never moves, by category"), std::string::npos)
          << w << (whatIf ? " what-if: " : ": ") << legend;
      std::string where;
      EXPECT_EQ(cutGlyphs(&where), 0) << w << (whatIf ? " what-if: " : ": ") << where;
    }
  }
}

// Three panels at 1024 px are narrower than "pushed back out of floor tile 2": the words over
// the move kept their start in the panel and lost the tile's number past its edge. Too wide
// even as a first clause, they go on two lines, whole.
TEST_F(DebuggerDriver, WhatHappenedIsWholeInANarrowPanel) {
  resize(1024, 640);
  open({"--scene", "seam-walk", "--compare", "discrete,substep-discrete,continuous"});
  frames(2);
  const std::string panel = drawnText("###panel0");
  EXPECT_NE(panel.find("pushed back out of floor"), std::string::npos) << panel;
  EXPECT_NE(panel.find("tile 2"), std::string::npos) << panel;
}

}  // namespace
}  // namespace tv::viewer
