// Overlays draw what was recorded and only what is in view, and drawing never touches the
// simulation. No GL here: ImGui builds draw lists without a backend.
#include <gtest/gtest.h>

#include "imgui.h"
#include "tv/sim/scene.hpp"
#include "tv/ui/layout.hpp"
#include "tv/ui/overlays.hpp"
#include "tv/ui/session.hpp"

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

Session crowd() {
  const sim::SceneDef& s = sim::findScene("crowd");
  Session session(s, s.defaults(), parseMover("continuous"), 0);
  session.advanceTo(4, 0.0);
  return session;
}

TEST_F(ImGuiFixture, DrawsOnlyWhatIsInView) {
  Session s = crowd();
  const WorldPicture pic = s.picture();
  Camera all, empty;
  all.frame(s.sim().camera(), {0, 0}, {800, 600});
  empty.frame({-5000, -5000, 100, 100}, {0, 0}, {800, 600});  // nothing out there
  Overlays on;
  on.grid = on.pixelGrid = false;  // lines that cover any view, empty or not
  const int full = verticesFor(all, pic, on);
  const int none = verticesFor(empty, pic, on);
  EXPECT_GT(full, 5000);
  // Only the background of an empty view remains.
  EXPECT_LE(none, 4);
}

TEST_F(ImGuiFixture, EachOverlayIsAToggle) {
  Session s = crowd();
  const WorldPicture pic = s.picture();
  Camera cam;
  cam.frame(s.followView(64), {0, 0}, {800, 600});
  Overlays on;
  const int everything = verticesFor(cam, pic, on);
  for (const OverlayToggle& t : overlayToggles()) {
    Overlays off = on;
    off.*t.flag = false;
    EXPECT_LE(verticesFor(cam, pic, off), everything) << t.name;
  }
  Overlays nothing;
  for (const OverlayToggle& t : overlayToggles()) nothing.*t.flag = false;
  EXPECT_LT(verticesFor(cam, pic, nothing), everything / 4);
}

TEST_F(ImGuiFixture, DrawingTheDebuggerLeavesTheSimulationAlone) {
  Session s = crowd();
  const std::uint64_t before = s.sim().stateHash();
  DebuggerState st;
  syncDraft(st, s);
  st.frameView = s.sim().camera();
  int vertices = 0;
  for (int f = 0; f < 3; ++f) {
    if (f > 0) ImGui::NewFrame();  // the fixture began the first
    (void)debuggerLayout(s, st, ImGui::GetIO().DisplaySize);
    ImGui::Render();
    vertices = ImGui::GetDrawData()->TotalVtxCount;
  }
  ImGui::NewFrame();  // for the fixture's EndFrame
  EXPECT_EQ(s.sim().stateHash(), before);
  EXPECT_EQ(s.sim().ticks(), 4u);
  EXPECT_GT(vertices, 1000);
}

}  // namespace
}  // namespace tv::ui
