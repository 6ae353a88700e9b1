#pragma once
// The debugger as a new user meets it, driven frame by frame through ImGui without a window:
// the mouse and keys are set on ImGuiIO, frames are built (never rendered) and the debugger's
// state, windows and draw lists are read back — including the text it drew, glyph by glyph.

#include <gtest/gtest.h>

#include <GLFW/glfw3.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include <unistd.h>

#include "debugger.hpp"
#include "imgui.h"
#include "imgui_internal.h"
#include "options.hpp"
#include "tv/app/platformer_game.hpp"
#include "tv/record/recorder.hpp"
#include "tv/ui/palette.hpp"
#include "app/drawn_text.hpp"

namespace tv::viewer {

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
    // A text field left active by the debugger before keeps no keys from this one.
    ImGui::ClearActiveID();
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
  void close() { debugger_.reset(); }

 private:
  std::unique_ptr<Debugger> debugger_;
};

// -- reading the picture back ------------------------------------------------------------------

// -- 5. no text outside its panel ------------------------------------------------------------
// A glyph that straddles the left or right side of its draw command's clip rect is text cut
// off at a panel's edge ("erlapping touch"). Every glyph of every window must lie inside its
// clip rect across; the top and bottom are where a window scrolls, which is not a defect.
inline int cutGlyphs(std::string* where) {
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

/// Glyphs of a window's text (by a part of its name) drawn over another of its glyphs: one
/// line of text written over another. Each overlap is counted once; `where` says where.
inline int overlappingGlyphs(const std::string& window, std::string* where) {
  const ImDrawData* dd = ImGui::GetDrawData();
  const ImVector<ImFontGlyph>& glyphs = ImGui::GetIO().Fonts->Fonts[0]->Glyphs;
  struct Box {
    float x0, y0, x1, y1;
  };
  std::vector<Box> boxes;
  for (int l = 0; l < dd->CmdListsCount; ++l) {
    const ImDrawList* dl = dd->CmdLists[l];
    const std::string owner = dl->_OwnerName ? dl->_OwnerName : "";
    if (owner.find(window) == std::string::npos) continue;
    for (const ImDrawCmd& cmd : dl->CmdBuffer) {
      if (cmd.UserCallback) continue;
      const ImVec4 clip = cmd.ClipRect;
      for (unsigned i = 0; i + 3 <= cmd.ElemCount; i += 3) {
        const ImDrawIdx* idx = dl->IdxBuffer.Data + cmd.IdxOffset + i;
        const ImDrawVert& a = dl->VtxBuffer[static_cast<int>(cmd.VtxOffset + idx[0])];
        const ImDrawVert& c = dl->VtxBuffer[static_cast<int>(cmd.VtxOffset + idx[2])];
        for (const ImFontGlyph& g : glyphs) {
          if (g.U0 != a.uv.x || g.V0 != a.uv.y || g.U1 != c.uv.x || g.V1 != c.uv.y) continue;
          if (!(g.X1 > g.X0)) break;
          const Box b{std::min(a.pos.x, c.pos.x), std::min(a.pos.y, c.pos.y),
                      std::max(a.pos.x, c.pos.x), std::max(a.pos.y, c.pos.y)};
          // Only what shows: a glyph scrolled out of its clip rect is not read.
          if (b.x1 <= clip.x || b.x0 >= clip.z || b.y1 <= clip.y || b.y0 >= clip.w) break;
          // The second triangle of a glyph's quad repeats its corners.
          if (!boxes.empty() && boxes.back().x0 == b.x0 && boxes.back().y0 == b.y0) break;
          boxes.push_back(b);
          break;
        }
      }
    }
  }
  int n = 0;
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    for (std::size_t j = i + 1; j < boxes.size(); ++j) {
      const Box& p = boxes[i];
      const Box& q = boxes[j];
      // More than a pixel each way: glyphs of one word touch, they do not cover each other.
      if (std::min(p.x1, q.x1) - std::max(p.x0, q.x0) > 1.0f &&
          std::min(p.y1, q.y1) - std::max(p.y0, q.y0) > 1.0f) {
        ++n;
        char text[96];
        std::snprintf(text, sizeof text, "(%.0f, %.0f) over (%.0f, %.0f); ",
                      static_cast<double>(p.x0), static_cast<double>(p.y0),
                      static_cast<double>(q.x0), static_cast<double>(q.y0));
        if (where->size() < 400) where->append(text);
      }
    }
  }
  return n;
}

// drawnText(window): the text a window drew, rebuilt from its glyphs (app/drawn_text.hpp).
using tvtest::drawnText;

/// The sample platformer's first 240 frames, recorded once per test process into a scratch file
/// of its own (ctest runs each test in a process, side by side: a shared file would be read by
/// one while another rewrites it).
inline const std::string& sampleRecording() {
  static const std::string path = [] {
    const std::string p =
        ::testing::TempDir() + "tv_viewer_sample_" + std::to_string(::getpid()) + ".tvrec";
    Recorder rec(p);
    (void)example::play(240, false, &rec);
    return p;
  }();
  // Removed when the process ends.
  static const struct Remove {
    ~Remove() { std::remove(path.c_str()); }
  } remove;
  return path;
}

/// The screen rect of the window named `name` (ImGui's full name, "###id" included), or an empty
/// rect when it was not drawn.
inline ImRect windowRect(const char* name) {
  const ImGuiWindow* w = ImGui::FindWindowByName(name);
  if (!w || !w->WasActive) return ImRect();
  return w->Rect();
}

}  // namespace tv::viewer
