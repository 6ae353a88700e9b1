#include "draw_util.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>

namespace tv::ui::detail {

void label(ImDrawList& dl, ImVec2 at, ImU32 colour, std::string_view text, bool anchored) {
  const char* b = text.data();
  const char* e = b + text.size();
  const ImFont* font = ImGui::GetFont();
  const float size = ImGui::GetFontSize();
  if (!font) return;
  const ImVec2 extent = font->CalcTextSizeA(size, FLT_MAX, 0.0f, b, e);
  // A label whose anchor is in view is moved inside the view whole, never cut at the panel's
  // edge ("erlapping touch"); one whose anchor is out of view names nothing visible: skipped.
  const ImVec2 lo = dl.GetClipRectMin(), hi = dl.GetClipRectMax();
  if (at.x < lo.x - extent.x || at.x > hi.x || at.y < lo.y - extent.y || at.y > hi.y) return;
  if (anchored) {
    // Tied to a place (a cell's count): shown only where it fits whole, without a plate.
    if (at.x < lo.x || at.y < lo.y || at.x + extent.x > hi.x || at.y + extent.y > hi.y) return;
    dl.AddText({at.x + 1, at.y + 1}, IM_COL32(0, 0, 0, 200), b, e);
    dl.AddText(at, colour, b, e);
    return;
  }
  at.x = std::max(lo.x + 2.0f, std::min(at.x, hi.x - extent.x - 3.0f));
  at.y = std::max(lo.y + 1.0f, std::min(at.y, hi.y - extent.y - 2.0f));
  at = {std::round(at.x), std::round(at.y)};
  // A dark plate under the text: cell counts and lines beneath never mix into the letters.
  dl.AddRectFilled({at.x - 1, at.y}, {at.x + extent.x + 2, at.y + extent.y + 1},
                   IM_COL32(0, 0, 0, 150));
  dl.AddText({at.x + 1, at.y + 1}, IM_COL32(0, 0, 0, 200), b, e);
  dl.AddText(at, colour, b, e);
}

void labelWrapped(ImDrawList& dl, ImVec2 at, ImU32 colour, std::string_view text, float width) {
  const char* b = text.data();
  const char* e = b + text.size();
  const ImFont* font = ImGui::GetFont();
  const float size = ImGui::GetFontSize();
  if (!font) return;
  const ImVec2 extent = font->CalcTextSizeA(size, FLT_MAX, width, b, e);
  const ImVec2 lo = dl.GetClipRectMin(), hi = dl.GetClipRectMax();
  at.y -= extent.y - size;  // grows upwards: the last line stays where a one-line label is
  if (at.x < lo.x - extent.x || at.x > hi.x || at.y < lo.y - extent.y || at.y > hi.y) return;
  at.x = std::max(lo.x + 2.0f, std::min(at.x, hi.x - extent.x - 3.0f));
  at.y = std::max(lo.y + 1.0f, std::min(at.y, hi.y - extent.y - 2.0f));
  at = {std::round(at.x), std::round(at.y)};
  dl.AddRectFilled({at.x - 1, at.y}, {at.x + extent.x + 2, at.y + extent.y + 1},
                   IM_COL32(0, 0, 0, 150));
  dl.AddText(font, size, {at.x + 1, at.y + 1}, IM_COL32(0, 0, 0, 200), b, e, width);
  dl.AddText(font, size, at, colour, b, e, width);
}

namespace {
// Screen corners of a rect, widened to one pixel so sub-pixel items stay visible.
void corners(const Camera& cam, const Rect& r, ImVec2& a, ImVec2& b) {
  a = cam.toScreenMin(r);
  b = cam.toScreenMax(r);
  if (b.x - a.x < 1.0f) b.x = a.x + 1.0f;
  if (b.y - a.y < 1.0f) b.y = a.y + 1.0f;
}
}  // namespace

void outline(ImDrawList& dl, const Camera& cam, const Rect& r, ImU32 colour, float thickness) {
  ImVec2 a, b;
  corners(cam, r, a, b);
  // AddRect strokes centred on the edge; inset by half a pixel so edges land on pixel centres.
  dl.AddRect({a.x + 0.5f, a.y + 0.5f}, {b.x - 0.5f, b.y - 0.5f}, colour, 0.0f, 0, thickness);
}

void fill(ImDrawList& dl, const Camera& cam, const Rect& r, ImU32 colour) {
  ImVec2 a, b;
  corners(cam, r, a, b);
  dl.AddRectFilled(a, b, colour);
}

void dashedLine(ImDrawList& dl, ImVec2 a, ImVec2 b, ImU32 colour, float dash, float thickness) {
  const float dx = b.x - a.x, dy = b.y - a.y;
  const float len = std::sqrt(dx * dx + dy * dy);
  if (len <= 0.0f) return;
  const float ux = dx / len, uy = dy / len;
  for (float s = 0.0f; s < len; s += 2.0f * dash) {
    const float t = std::min(s + dash, len);
    dl.AddLine({a.x + ux * s, a.y + uy * s}, {a.x + ux * t, a.y + uy * t}, colour, thickness);
  }
}

void dashedOutline(ImDrawList& dl, const Camera& cam, const Rect& r, ImU32 colour, float dash) {
  ImVec2 a, b;
  corners(cam, r, a, b);
  a = {a.x + 0.5f, a.y + 0.5f};
  b = {b.x - 0.5f, b.y - 0.5f};
  dashedLine(dl, a, {b.x, a.y}, colour, dash);
  dashedLine(dl, {b.x, a.y}, b, colour, dash);
  dashedLine(dl, b, {a.x, b.y}, colour, dash);
  dashedLine(dl, {a.x, b.y}, a, colour, dash);
}

void arrow(ImDrawList& dl, ImVec2 from, ImVec2 to, ImU32 colour, float thickness) {
  const float dx = to.x - from.x, dy = to.y - from.y;
  const float len = std::sqrt(dx * dx + dy * dy);
  if (len <= 0.0f) return;
  const float ux = dx / len, uy = dy / len;
  const float head = std::min(7.0f, len * 0.5f);
  const ImVec2 base{to.x - ux * head, to.y - uy * head};
  dl.AddLine(from, base, colour, thickness);
  dl.AddTriangleFilled(to, {base.x - uy * head * 0.5f, base.y + ux * head * 0.5f},
                       {base.x + uy * head * 0.5f, base.y - ux * head * 0.5f}, colour);
}

std::vector<ImVec2> convexHull(std::vector<ImVec2> p) {
  std::sort(p.begin(), p.end(),
            [](ImVec2 a, ImVec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  p.erase(
      std::unique(p.begin(), p.end(), [](ImVec2 a, ImVec2 b) { return a.x == b.x && a.y == b.y; }),
      p.end());
  if (p.size() < 3) return p;
  const auto cross = [](ImVec2 o, ImVec2 a, ImVec2 b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
  };
  std::vector<ImVec2> h(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, lo = k + 1; i-- > 0;) {
    while (k >= lo && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  h.resize(k - 1);
  return h;
}

}  // namespace tv::ui::detail
