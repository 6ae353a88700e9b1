// Overlays draw what was recorded and only what is in view, and drawing never touches the
// simulation. No GL here: ImGui builds draw lists without a backend.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <string_view>
#include <string>

#include "imgui.h"
#include "imgui_frame.hpp"
#include "tv/sim/scene.hpp"
#include "tv/ui/overlays.hpp"
#include "tv/ui/palette.hpp"
#include "tv/ui/panels.hpp"
#include "tv/ui/session.hpp"
#include "tv/ui/sim_source.hpp"
#include "tv/ui/view.hpp"

namespace tv::ui {
namespace {

// An ImGui frame, and what drawing a picture adds to a draw list.
class ImGuiFixture : public testing::ImGuiFrame {
 protected:

  // Vertices that drawing the picture adds to a fresh draw list.
  static int verticesFor(const Camera& cam, const WorldPicture& pic, const Overlays& on) {
    ImDrawList dl(ImGui::GetDrawListSharedData());
    dl._ResetForNewFrame();
    dl.PushClipRectFullScreen();
    dl.PushTextureID(ImGui::GetIO().Fonts->TexID);
    drawWorld(dl, cam, pic, on);
    return dl.VtxBuffer.Size;
  }
};

// Every vertex colour a picture's drawing uses.
std::set<ImU32> coloursIn(const Camera& cam, const WorldPicture& pic) {
  return testing::coloursDrawn(cam, pic);
}

std::unique_ptr<SimSource> sceneAt(std::string_view name, std::uint64_t tick) {
  const sim::SceneDef& s = sim::findScene(name);
  auto source = std::make_unique<SimSource>(s, s.defaults(), MoverSpec{});
  source->advanceTo(tick, 0.0);
  return source;
}

std::unique_ptr<SimSource> crowd() {
  const sim::SceneDef& s = sim::findScene("crowd");
  auto source = std::make_unique<SimSource>(s, s.defaults(), MoverSpec{});
  source->traceBody(0);
  source->advanceTo(4, 0.0);
  return source;
}

TEST_F(ImGuiFixture, DrawingTheDebuggerLeavesTheSimulationAlone) {
  Session s(crowd());
  const sim::Simulation& sim = s.primary().sim()->simulation();
  const std::uint64_t before = sim.stateHash();
  ViewState view;
  syncPanels(view, s);
  syncDraft(view.panels[0], *s.primary().sim());
  view.panels[0].frameView = sim.camera();
  int vertices = 0;
  for (int f = 0; f < 3; ++f) {
    if (f > 0) ImGui::NewFrame();  // the fixture began the first
    (void)sessionView(s, view, {0, 0}, ImGui::GetIO().DisplaySize);
    ImGui::Render();
    vertices = ImGui::GetDrawData()->TotalVtxCount;
  }
  ImGui::NewFrame();  // for the fixture's EndFrame
  EXPECT_EQ(sim.stateHash(), before);
  EXPECT_EQ(sim.ticks(), 4u);
  EXPECT_GT(vertices, 1000);
}

// The text drawMove writes, one string per baseline (glyphs in x order), keyed by its y, with
// the x range each line covers.
struct Line {
  std::string text;
  float y = 0.0f, x0 = 1e9f, x1 = -1e9f;
};
std::map<float, Line> labelsOf(const ImDrawList& dl) {
  const ImFont* font = ImGui::GetIO().Fonts->Fonts[0];
  std::map<float, std::vector<std::pair<float, char>>> glyphs;
  for (int i = 0; i + 3 <= dl.IdxBuffer.Size; i += 3) {
    const ImDrawVert& a = dl.VtxBuffer[dl.IdxBuffer[i]];
    const ImDrawVert& c = dl.VtxBuffer[dl.IdxBuffer[i + 2]];
    for (const ImFontGlyph& g : font->Glyphs) {
      if (g.U0 != a.uv.x || g.V0 != a.uv.y || g.U1 != c.uv.x || g.V1 != c.uv.y || !(g.X1 > g.X0))
        continue;
      // A label's text is drawn twice, its shadow a pixel down and right: one line, each
      // glyph once.
      float y = a.pos.y - g.Y0;
      for (const auto& [known, row] : glyphs) {
        if (std::abs(known - y) <= 1.5f) y = known;
      }
      auto& row = glyphs[y];
      const float x = a.pos.x - g.X0;
      if (std::none_of(row.begin(), row.end(),
                       [&](const auto& p) { return std::abs(p.first - x) <= 1.5f; }))
        row.emplace_back(x, static_cast<char>(g.Codepoint));
      break;
    }
  }
  std::map<float, Line> out;
  for (auto& [y, row] : glyphs) {
    std::sort(row.begin(), row.end());
    Line& l = out[y];
    l.y = y;
    for (const auto& [x, ch] : row) {
      if (!l.text.empty() && x - l.x1 > 3.0f) l.text += ' ';  // a space draws no glyph
      l.text += ch;
      l.x0 = std::min(l.x0, x);
      l.x1 = std::max(l.x1, x + 7.0f);
    }
  }
  return out;
}

// A move's start and goal markers each keep their own label. Two that would overlap are
// stacked; a single "start, goal" label is only for a move that asked to go nowhere.
//
//   goal          <- a line higher
//   start goal
//   [s]--[g]         markers 23 px apart: "start" and "goal" side by side would overlap
TEST_F(ImGuiFixture, NearbyStartAndGoalMarkersEachKeepALabel) {
  World world(16);
  Camera cam;
  cam.frame({0, 0, 200, 100}, {0, 0}, {200, 100});  // one world unit per pixel
  const auto labelsFor = [&](double goalX, double goalY = 50) {
    MoveTrace m;
    m.start = {50, 50, 8, 8};
    m.goal = m.final = {goalX, goalY};
    m.legs.push_back({m.start, m.goal});
    ImDrawList dl(ImGui::GetDrawListSharedData());
    dl._ResetForNewFrame();
    dl.PushClipRectFullScreen();
    dl.PushTextureID(ImGui::GetIO().Fonts->TexID);
    drawMove(dl, cam, world, m, Overlays{});
    return labelsOf(dl);
  };
  const double scale = cam.scale();
  ASSERT_NEAR(scale, 1.0, 1e-9);
  // Beside it, and beside it a little lower (a walker stepping down): "start" and "goal" each
  // on a line of its own.
  for (const double dy : {0.0, 10.0}) {
    std::vector<Line> start, goal;
    for (const auto& [y, l] : labelsFor(50 + 23, 50 + dy)) {
      EXPECT_EQ(l.text.find("start, goal"), std::string::npos) << l.text;
      if (l.text.find("start") != std::string::npos) start.push_back(l);
      if (l.text.find("goal") != std::string::npos) goal.push_back(l);
    }
    ASSERT_EQ(start.size(), 1u) << dy;
    ASSERT_EQ(goal.size(), 1u) << dy;
    EXPECT_EQ(start[0].text, "start") << dy;
    EXPECT_EQ(goal[0].text, "goal") << dy;
    // Neither is written over the other: a line apart, or side by side.
    const bool linesApart = std::abs(start[0].y - goal[0].y) >= ImGui::GetTextLineHeight();
    const bool sideBySide = start[0].x1 <= goal[0].x0 || goal[0].x1 <= start[0].x0;
    EXPECT_TRUE(linesApart || sideBySide) << dy << ": start at y " << start[0].y << ", goal at y "
                                          << goal[0].y;
  }
  // The control: a move that asked to stay where it was has one marker and one label for it.
  bool merged = false;
  for (const auto& [y, l] : labelsFor(50)) merged |= l.text.find("start, goal") != std::string::npos;
  EXPECT_TRUE(merged);
}

// Lifts, crushers and doors (lift-crush, tick 3): the moving solids in their own fill, and the
// bodies they carried, pushed and squished that tick in theirs. A scene without moving solids
// (bullets-wall) draws none of those colours: the negative control.
TEST_F(ImGuiFixture, WhatMovingSolidsDidIsDrawnInItsOwnColours) {
  const auto lifts = sceneAt("lift-crush", 3);
  const sim::Simulation& sim = lifts->simulation();
  ASSERT_FALSE(sim.solidContacts().empty());
  Camera cam;
  cam.frame(sim.camera(), {0, 0}, {1280, 720});
  const std::set<ImU32> drawn = coloursIn(cam, lifts->picture());
  for (const ImU32 c : {palette::kMovingSolid, palette::kCarried, palette::kPushed,
                        palette::kSquished}) {
    EXPECT_TRUE(drawn.count(c)) << std::hex << c;
  }
  EXPECT_FALSE(drawn.count(palette::kOneWay));  // lift-crush has no one-way side

  const auto oneWay = sceneAt("one-way-rise", 3);
  cam.frame(oneWay->simulation().camera(), {0, 0}, {1280, 720});
  EXPECT_TRUE(coloursIn(cam, oneWay->picture()).count(palette::kOneWay));

  // A corner correction (corner-nudge, tick 4: jumps meeting the ceilings), in its own colour;
  // none without correction.
  const auto nudged = sceneAt("corner-nudge", 4);
  ASSERT_FALSE(nudged->simulation().cornerNudges().empty());
  cam.frame(nudged->simulation().camera(), {0, 0}, {1280, 720});
  EXPECT_TRUE(coloursIn(cam, nudged->picture()).count(palette::kNudge));
  {
    const sim::SceneDef& def = sim::findScene("corner-nudge");
    sim::Params p = def.defaults();
    p.set("correct", 0);
    SimSource off(def, p, MoverSpec{});
    off.advanceTo(4, 0.0);
    EXPECT_FALSE(coloursIn(cam, off.picture()).count(palette::kNudge));
  }

  const auto bullets = sceneAt("bullets-wall", 2);
  cam.frame(bullets->simulation().camera(), {0, 0}, {1280, 720});
  const std::set<ImU32> plain = coloursIn(cam, bullets->picture());
  for (const ImU32 c : {palette::kMovingSolid, palette::kOneWay, palette::kCarried,
                        palette::kPushed, palette::kSquished, palette::kNudge}) {
    EXPECT_FALSE(plain.count(c)) << std::hex << c;
  }
}

// The legend lists the colours of moving solids and one-way sides only in a view that can draw
// them (each entry takes height from the world view); elsewhere it is the legend every other
// golden was drawn with.
TEST_F(ImGuiFixture, TheLegendNamesPlatformColoursOnlyWhereTheSceneHasThem) {
  const auto shown = [](const Source& src) {
    std::vector<std::string> labels;
    const palette::LegendScope scope = legendScopeOf(src);
    for (const palette::LegendEntry& e : palette::legend())
      if (scope.shows(e)) labels.emplace_back(e.label);
    return labels;
  };
  const auto has = [](const std::vector<std::string>& l, std::string_view label) {
    return std::find(l.begin(), l.end(), label) != l.end();
  };
  const auto plain = shown(*sceneAt("bullets-wall", 0));
  const auto lifts = shown(*sceneAt("lift-crush", 0));
  const auto oneWay = shown(*sceneAt("one-way-rise", 0));
  for (const char* label :
       {"moving solid", "one-way side", "carried by a solid", "pushed by a solid", "squished"}) {
    EXPECT_FALSE(has(plain, label)) << label;
    EXPECT_TRUE(has(oneWay, label)) << label;
    EXPECT_EQ(has(lifts, label), std::string_view(label) != "one-way side") << label;
  }
  EXPECT_FALSE(has(plain, "corner nudge"));
  EXPECT_FALSE(has(lifts, "corner nudge"));
  EXPECT_TRUE(has(shown(*sceneAt("corner-nudge", 0)), "corner nudge"));
  // The platform entries (and the contact events', its bodies read their contacts) come after
  // the others: without them, the same list in the same order.
  ASSERT_EQ(lifts.size(), plain.size() + 4 + 3);
  EXPECT_TRUE(std::equal(plain.begin(), plain.end(), lifts.begin()));
}

}  // namespace
}  // namespace tv::ui
