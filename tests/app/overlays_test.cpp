// Overlays draw what was recorded and only what is in view, and drawing never touches the
// simulation. No GL here: ImGui builds draw lists without a backend.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

#include "imgui.h"
#include "tv/sim/scene.hpp"
#include "tv/ui/overlays.hpp"
#include "tv/ui/session.hpp"
#include "tv/ui/sim_source.hpp"
#include "tv/ui/view.hpp"

namespace tv::ui {
namespace {

// An ImGui context with a built font atlas, for the length of a test.
class ImGuiFixture : public ::testing::Test {
 protected:
  void SetUp() override {
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    io.DisplaySize = {1280, 720};
    io.DeltaTime = 1.0f / 60.0f;
    unsigned char* pixels = nullptr;
    int w = 0, h = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);
    ImGui::NewFrame();  // sets the current font that labels are measured and drawn with
  }
  void TearDown() override {
    ImGui::EndFrame();
    ImGui::DestroyContext();
  }

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

}  // namespace
}  // namespace tv::ui
