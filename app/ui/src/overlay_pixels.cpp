// Where a body is drawn: the physics state is fractional, the render position is interpolated
// between two ticks, and pixel art snaps it to a whole pixel. Drawn together, the three show
// why a resting sprite can flicker (render != physics) or sit one pixel off (floor).
#include <cmath>
#include <string>

#include "draw_util.hpp"
#include "tv/timestep.hpp"
#include "tv/ui/overlays.hpp"
#include "tv/ui/palette.hpp"

namespace tv::ui {

namespace pal = palette;

void drawPositions(ImDrawList& dl, const Camera& cam, const Rect& physics, const Rect& render,
                   bool labels) {
  const Rect pixel = render.at(floorOnDraw(render.position()));
  if (!cam.sees(physics) && !cam.sees(render)) return;
  // Outlines of decreasing width, widest first: where two coincide the narrower one shows on
  // top of the wider one's fringe, so all three stay visible even when they agree.
  detail::outline(dl, cam, pixel, pal::kPixel, 6.0f);
  detail::outline(dl, cam, render, pal::kRender, 4.0f);
  detail::outline(dl, cam, physics, pal::kPhysics, 2.0f);
  // Names only once zoomed in enough that the three rects are told apart; on their left,
  // where the trace's labels (above and right) do not go.
  if (labels && cam.scale() >= kPixelGridScale) {
    const auto leftOf = [&](const Rect& r, float dy, ImU32 colour, const std::string& text) {
      const ImVec2 at = cam.toScreenMin(r);
      const float w = ImGui::CalcTextSize(text.c_str()).x;
      // Left of the rect, or right of it when the view's edge would cut the text.
      const float x = at.x - w - 8 >= cam.screenMin().x ? at.x - w - 8 : cam.toScreenMax(r).x + 8;
      detail::label(dl, {x, at.y + dy}, colour, text);
    };
    // Only what disagrees is named: drawn at the tick (physics = render), just the pixel.
    const bool pr = physics == render, rp = render == pixel;
    if (pr && !rp) {
      leftOf(pixel, -2, pal::kPixel, "pixel");
    } else if (!pr && rp) {
      leftOf(pixel, -2, pal::kPixel, "render = pixel");
      leftOf(physics, 12, pal::kPhysics, "physics");
    } else if (!pr) {
      leftOf(pixel, -2, pal::kPixel, "pixel");
      leftOf(render, 12, pal::kRender, "render");
      leftOf(physics, 26, pal::kPhysics, "physics");
    }
  }
}

void drawPixelGrid(ImDrawList& dl, const Camera& cam) {
  const Rect v = cam.view();
  const ImVec2 lo = cam.screenMin(), hi = cam.screenMax();
  for (double x = std::ceil(v.x); x <= v.right(); x += 1.0) {
    const float sx = cam.toScreen({x, v.y}).x + 0.5f;
    dl.AddLine({sx, lo.y}, {sx, hi.y}, pal::kPixelGrid);
  }
  for (double y = std::ceil(v.y); y <= v.bottom(); y += 1.0) {
    const float sy = cam.toScreen({v.x, y}).y + 0.5f;
    dl.AddLine({lo.x, sy}, {hi.x, sy}, pal::kPixelGrid);
  }
}

}  // namespace tv::ui
