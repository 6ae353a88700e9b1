// Overlays draw what was recorded and only what is in view, and drawing never touches the
// simulation. No GL here: ImGui builds draw lists without a backend.
#include <gtest/gtest.h>

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

}  // namespace
}  // namespace tv::ui
