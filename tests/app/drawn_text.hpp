#pragma once
// Reading back what ImGui drew, as a person would read it: the text of a window, rebuilt from
// the glyphs of its draw list. The debugger's tests (tests/viewer) and the still's (tests/app)
// say "the status row shows ..." or "the picture is labelled ..." with it.

#include <cmath>
#include <string>

#include "imgui.h"

namespace tvtest {

/// The text a window drew (its draw list, by a part of the window's name; empty: every
/// window), rebuilt from the glyphs: a new line where the baseline moves, spaces where the pen
/// jumped. Lets a test say "the status row shows ..." of what a person would read.
inline std::string drawnText(const std::string& window = "") {
  const ImDrawData* dd = ImGui::GetDrawData();
  const ImFont* font = ImGui::GetIO().Fonts->Fonts[0];
  const float advance = font->GetCharAdvance(' ');
  std::string out;
  for (int l = 0; l < dd->CmdListsCount; ++l) {
    const ImDrawList* dl = dd->CmdLists[l];
    const std::string owner = dl->_OwnerName ? dl->_OwnerName : "";
    if (!window.empty() && owner.find(window) == std::string::npos) continue;
    float lastX = -1e9f, lastY = -1e9f;
    for (const ImDrawCmd& cmd : dl->CmdBuffer) {
      if (cmd.UserCallback) continue;
      for (unsigned i = 0; i + 3 <= cmd.ElemCount; i += 3) {
        const ImDrawIdx* idx = dl->IdxBuffer.Data + cmd.IdxOffset + i;
        const ImDrawVert& a = dl->VtxBuffer[static_cast<int>(cmd.VtxOffset + idx[0])];
        const ImDrawVert& c = dl->VtxBuffer[static_cast<int>(cmd.VtxOffset + idx[2])];
        for (const ImFontGlyph& g : font->Glyphs) {
          if (g.U0 != a.uv.x || g.V0 != a.uv.y || g.U1 != c.uv.x || g.V1 != c.uv.y) continue;
          if (!(g.X1 > g.X0)) break;
          const float x = a.pos.x - g.X0, y = a.pos.y - g.Y0;
          // Glyphs come in pairs of triangles: the second shares the first's corners.
          if (x == lastX && y == lastY) break;
          if (std::abs(y - lastY) > 2.0f || x < lastX) {
            out += '\n';
          } else {
            const int gap = static_cast<int>(std::lround((x - lastX) / advance)) - 1;
            for (int s = 0; s < gap && s < 8; ++s) out += ' ';
          }
          out += static_cast<char>(g.Codepoint);
          lastX = x;
          lastY = y;
          break;
        }
      }
    }
    out += '\n';
  }
  return out;
}

}  // namespace tvtest
