#pragma once
// An ImGui frame without a window, for tests that read what the debugger's drawing adds to a
// draw list: ImGui builds draw lists with no backend once its font atlas is built.

#include <gtest/gtest.h>

#include <set>

#include "imgui.h"
#include "tv/ui/camera.hpp"
#include "tv/ui/overlays.hpp"

namespace tv::ui::testing {

/// A context with a built font atlas and a frame begun (the current font labels are measured
/// and drawn with), for the length of a test.
class ImGuiFrame : public ::testing::Test {
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
    ImGui::NewFrame();
  }
  void TearDown() override {
    ImGui::EndFrame();
    ImGui::DestroyContext();
  }
};

/// Every vertex colour drawing `pic` through `cam` adds to a fresh draw list.
inline std::set<ImU32> coloursDrawn(const Camera& cam, const WorldPicture& pic,
                                    const Overlays& on = {}) {
  ImDrawList dl(ImGui::GetDrawListSharedData());
  dl._ResetForNewFrame();
  dl.PushClipRectFullScreen();
  dl.PushTextureID(ImGui::GetIO().Fonts->TexID);
  drawWorld(dl, cam, pic, on);
  std::set<ImU32> out;
  for (const ImDrawVert& v : dl.VtxBuffer) out.insert(v.col);
  return out;
}

}  // namespace tv::ui::testing
