// The world itself: spatial-hash cells, solids and bodies.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "draw_util.hpp"
#include "tv/ui/overlays.hpp"
#include "tv/ui/palette.hpp"

namespace tv::ui {

namespace pal = palette;

namespace {
// Below this a cell's lines would merge into a flat tint, and its count would not fit.
constexpr float kMinCellLines = 6.0f;
constexpr float kMinCellCount = 18.0f;

// Calls f(cell, item count) for each occupied cell in view: whichever is smaller, the cells in
// view or the occupied cells (when zoomed far out).
template <class F>
void forEachOccupiedInView(const Camera& cam, const World& world, F&& f) {
  const CellRange inView = world.grid().cellsOf(cam.view());
  if (static_cast<std::size_t>(inView.count()) <= world.countCells()) {
    Grid::forEachCell(inView, [&](Cell c) {
      const std::size_t n = world.cellItems(c).size();
      if (n > 0) f(c, n);
    });
  } else {
    world.forEachOccupiedCell([&](Cell c, std::size_t n) {
      if (inView.contains(c)) f(c, n);
    });
  }
}
}  // namespace

std::span<const OverlayToggle> overlayToggles() {
  static constexpr OverlayToggle kToggles[] = {
      {"solids", &Overlays::solids},
      {"bodies", &Overlays::bodies},
      {"grid", &Overlays::grid},
      {"occupied", &Overlays::occupied},
      {"visited", &Overlays::visitedCells},
      {"candidates", &Overlays::candidates},
      {"sweep", &Overlays::sweep},
      {"hull", &Overlays::hull},
      {"substeps", &Overlays::substeps},
      {"hits", &Overlays::hits},
      {"responses", &Overlays::responses},
      {"history", &Overlays::history},
      {"positions", &Overlays::positions},
      {"pixel-grid", &Overlays::pixelGrid},
      {"labels", &Overlays::labels},
  };
  return kToggles;
}

void drawGrid(ImDrawList& dl, const Camera& cam, const World& world, const Overlays& on) {
  const Grid& grid = world.grid();
  const CellRange inView = grid.cellsOf(cam.view());
  if (on.occupied) {
    forEachOccupiedInView(cam, world, [&](Cell c, std::size_t n) {
      detail::fill(dl, cam, grid.bounds(c), pal::occupiedFill(n));
    });
  }
  if (on.grid && cam.toScreenLength(grid.cellSize()) >= kMinCellLines) {
    const ImVec2 lo = cam.screenMin(), hi = cam.screenMax();
    for (std::int64_t cx = inView.x0; cx <= inView.x1 + 1; ++cx) {
      const float x = cam.toScreen(grid.origin({cx, 0})).x;
      dl.AddLine({x + 0.5f, lo.y}, {x + 0.5f, hi.y}, pal::kGridLine);
    }
    for (std::int64_t cy = inView.y0; cy <= inView.y1 + 1; ++cy) {
      const float y = cam.toScreen(grid.origin({0, cy})).y;
      dl.AddLine({lo.x, y + 0.5f}, {hi.x, y + 0.5f}, pal::kGridLine);
    }
  }
}

void drawCellCounts(ImDrawList& dl, const Camera& cam, const World& world) {
  if (cam.toScreenLength(world.cellSize()) < kMinCellCount) return;
  forEachOccupiedInView(cam, world, [&](Cell c, std::size_t n) {
    char text[24];
    std::snprintf(text, sizeof text, "%zu", n);
    const ImVec2 at = cam.toScreenMin(world.grid().bounds(c));
    detail::label(dl, {at.x + 3, at.y + 2}, pal::kOccupiedText, text, true);
  });
}

namespace {

// A one-way solid's blocking side, its top: a dashed line along it, drawn on the edge so that a
// rider standing there sits on the line.
void drawOneWaySide(ImDrawList& dl, const Camera& cam, const Rect& r) {
  const ImVec2 a = cam.toScreenMin(r), b = cam.toScreenMax(r);
  detail::dashedLine(dl, {a.x, a.y + 1.0f}, {b.x, a.y + 1.0f}, pal::kOneWay, 5.0f, 2.0f);
}

// What moving solids did this tick: a carried or pushed body outlined with an arrow from where
// it was to where the solid put it, a squished one filled. A body squished by one solid and
// carried by another shows the squish (drawn last).
void drawSolidContacts(ImDrawList& dl, const Camera& cam, const WorldPicture& pic) {
  for (const sim::SolidAct act :
       {sim::SolidAct::carried, sim::SolidAct::pushed, sim::SolidAct::squished}) {
    for (const sim::SolidContact& c : pic.contacts) {
      if (c.act != act || c.body >= pic.bodies.size()) continue;
      const Rect now = c.body < pic.renderRects.size() ? pic.renderRects[c.body]
                                                        : pic.bodies[c.body].rect;
      if (!cam.sees(now) && !cam.sees(c.from)) continue;
      if (act == sim::SolidAct::squished) {
        detail::fill(dl, cam, c.to, pal::kSquished);
        detail::outline(dl, cam, c.to, pal::kSquished, 2.0f);
        continue;
      }
      const ImU32 colour = act == sim::SolidAct::carried ? pal::kCarried : pal::kPushed;
      detail::outline(dl, cam, now, colour, 2.0f);
      const ImVec2 from = cam.toScreen(c.from.center()), to = cam.toScreen(c.to.center());
      const float dx = to.x - from.x, dy = to.y - from.y;
      if (dx * dx + dy * dy >= 36.0f) detail::arrow(dl, from, to, colour, 1.5f);
    }
  }
}

// Corner corrections this tick: the body where it met the corner, dashed, and an arrow to where
// the nudge put it, outlined.
void drawCornerNudges(ImDrawList& dl, const Camera& cam, const WorldPicture& pic) {
  for (const sim::CornerNudgeAt& n : pic.nudges) {
    if (!cam.sees(n.from) && !cam.sees(n.to)) continue;
    detail::dashedOutline(dl, cam, n.from, pal::kNudge);
    detail::outline(dl, cam, n.to, pal::kNudge, 2.0f);
    detail::arrow(dl, cam.toScreen(n.from.center()), cam.toScreen(n.to.center()), pal::kNudge,
                  1.5f);
  }
}

}  // namespace

std::pair<Vec2, Vec2> contactEdge(const sim::ContactAt& c) {
  const Rect& a = c.bodyRect;
  const Rect& b = c.otherRect;
  const Vec2 n = c.event.normal;
  if (n.x == 0.0 && n.y == 0.0) {
    const double x0 = std::max(a.x, b.x), x1 = std::min(a.right(), b.right());
    const double y0 = std::max(a.y, b.y), y1 = std::min(a.bottom(), b.bottom());
    const Vec2 m = x0 <= x1 && y0 <= y1 ? Vec2{(x0 + x1) / 2, (y0 + y1) / 2} : a.center();
    return {m, m};
  }
  // The normal points from the other item towards the body: the body's edge facing it is the
  // one on the other side of the normal (standing on it, (0, −1): the body's bottom).
  if (n.y != 0.0) {
    const double y = n.y < 0.0 ? a.bottom() : a.y;
    double x0 = std::max(a.x, b.x), x1 = std::min(a.right(), b.right());
    if (!(x0 < x1)) x0 = a.x, x1 = a.right();
    return {{x0, y}, {x1, y}};
  }
  const double x = n.x < 0.0 ? a.right() : a.x;
  double y0 = std::max(a.y, b.y), y1 = std::min(a.bottom(), b.bottom());
  if (!(y0 < y1)) y0 = a.y, y1 = a.bottom();
  return {{x, y0}, {x, y1}};
}

namespace {

void diamond(ImDrawList& dl, ImVec2 c, float r, ImU32 colour, bool filled) {
  const ImVec2 d[4] = {{c.x, c.y - r}, {c.x + r, c.y}, {c.x, c.y + r}, {c.x - r, c.y}};
  if (filled) {
    dl.AddConvexPolyFilled(d, 4, colour);
    dl.AddPolyline(d, 4, pal::kContactRim, ImDrawFlags_Closed, 1.0f);
  } else {
    // A dark rim under the colour: an end reads on a light fill and on the dark background.
    dl.AddPolyline(d, 4, pal::kContactRim, ImDrawFlags_Closed, 3.5f);
    dl.AddPolyline(d, 4, colour, ImDrawFlags_Closed, 1.5f);
  }
}

}  // namespace

void drawContactEvents(ImDrawList& dl, const Camera& cam,
                       std::span<const sim::ContactAt> events) {
  // Persisting contacts first, then ends, then begins: a change reads over the steady state.
  constexpr float kMarker = 4.5f;  // px: the same at every zoom, so both window sizes read
  for (const ContactPhase phase : {ContactPhase::persist, ContactPhase::end, ContactPhase::begin}) {
    for (const sim::ContactAt& c : events) {
      if (c.event.phase != phase) continue;
      if (!cam.sees(c.bodyRect) && !cam.sees(c.otherRect)) continue;
      const auto [from, to] = contactEdge(c);
      const ImVec2 a = cam.toScreen(from), b = cam.toScreen(to);
      const ImVec2 mid{(a.x + b.x) * 0.5f, (a.y + b.y) * 0.5f};
      if (phase == ContactPhase::persist) {
        // The steady state is left out where a body is too small on screen to carry a line
        // beside its fill (a zoomed-out crowd would be striped); a change is always marked.
        const float side =
            std::min(cam.toScreenLength(c.bodyRect.w), cam.toScreenLength(c.bodyRect.h));
        if (side < 10.0f) continue;
        // Along the edge, a little inside the body (towards it along the normal; further in on
        // a big body): clear of a one-way side's dashed line, the other item's edge and the
        // traced body's position outlines, which all lie on the edge itself.
        const auto nx = static_cast<float>(c.event.normal.x);
        const auto ny = static_cast<float>(c.event.normal.y);
        const float depth = std::clamp(0.12f * side, 1.5f, 6.0f);
        const ImVec2 in{nx * depth, ny * depth};
        const float inset =
            std::min(1.0f, 0.25f * std::max(std::abs(b.x - a.x), std::abs(b.y - a.y)));
        const ImVec2 along{ny != 0.0f ? inset : 0.0f, nx != 0.0f ? inset : 0.0f};
        if (a.x == b.x && a.y == b.y) {
          dl.AddCircle(mid, 2.5f, pal::kContactPersist, 8, 1.5f);
        } else {
          dl.AddLine({a.x + in.x + along.x, a.y + in.y + along.y},
                     {b.x + in.x - along.x, b.y + in.y - along.y}, pal::kContactPersist, 2.0f);
        }
        continue;
      }
      diamond(dl, mid, kMarker,
              phase == ContactPhase::begin ? pal::kContactBegin : pal::kContactEnd,
              phase == ContactPhase::begin);
    }
  }
}

void drawSolids(ImDrawList& dl, const Camera& cam, std::span<const sim::Solid> solids) {
  // Edges only once a tile is big enough on screen that they do not swallow its fill.
  const bool edges = solids.empty() || cam.toScreenLength(solids.front().rect.w) >= 6.0f;
  for (const sim::Solid& s : solids) {
    if (!cam.sees(s.rect)) continue;
    detail::fill(dl, cam, s.rect, pal::kSolid);
    if (edges) detail::outline(dl, cam, s.rect, pal::kSolidEdge);
    if (s.oneWay) drawOneWaySide(dl, cam, s.rect);
  }
}

void drawBodies(ImDrawList& dl, const Camera& cam, const WorldPicture& pic) {
  for (std::size_t i = 0; i < pic.bodies.size(); ++i) {
    const sim::Body& b = pic.bodies[i];
    const Rect r = i < pic.renderRects.size() ? pic.renderRects[i] : b.rect;
    if (!cam.sees(r)) continue;
    const ImU32 own = i < pic.bodyFills.size() ? pic.bodyFills[i] : 0;
    // A body in the solid layer is a solid the scene moves (a lift, a door), moved by
    // tv::moveSolid or, in a scene's naive control, teleported by its rules.
    const bool moving = b.solid || b.layer == sim::kLayerSolid;
    detail::fill(dl, cam, r,
                 own != 0 ? own : moving ? pal::kMovingSolid : b.active ? pal::kBody : pal::kBodyIdle);
    if (b.oneWay) drawOneWaySide(dl, cam, r);
  }
  drawSolidContacts(dl, cam, pic);
  drawCornerNudges(dl, cam, pic);
  if (pic.selected && *pic.selected < pic.bodies.size()) {
    const std::size_t i = *pic.selected;
    const Rect r = i < pic.renderRects.size() ? pic.renderRects[i] : pic.bodies[i].rect;
    if (!cam.sees(r)) return;
    // A ring a few pixels outside the body, so even a 2 px bullet is easy to find.
    ImVec2 a = cam.toScreenMin(r), b = cam.toScreenMax(r);
    dl.AddRect({a.x - 4, a.y - 4}, {b.x + 4, b.y + 4}, pal::kSelected, 0.0f, 0, 1.5f);
  }
}

void drawWorld(ImDrawList& dl, const Camera& cam, const WorldPicture& pic, const Overlays& on) {
  dl.PushClipRect(cam.screenMin(), cam.screenMax(), true);
  dl.AddRectFilled(cam.screenMin(), cam.screenMax(), pal::kBackground);
  const MoveTrace* last = pic.moves.empty() ? nullptr : &pic.moves.back().trace;
  if (pic.world) drawGrid(dl, cam, *pic.world, on);
  if (last && pic.world) drawMoveBackdrop(dl, cam, pic.world->grid(), *last, on);
  if (on.solids) drawSolids(dl, cam, pic.solids);
  if (on.history && pic.moves.size() > 1)
    drawMoveHistory(dl, cam, pic.moves.first(pic.moves.size() - 1));
  if (on.bodies) drawBodies(dl, cam, pic);
  // Counts go over the items, where a tile cannot hide them.
  if (on.occupied && pic.world) drawCellCounts(dl, cam, *pic.world);
  if (last && pic.world) drawMove(dl, cam, *pic.world, *last, on);
  if (pic.selected && *pic.selected < pic.bodies.size()) {
    const std::size_t i = *pic.selected;
    const Rect physics = pic.bodies[i].rect;
    const Rect render = i < pic.renderRects.size() ? pic.renderRects[i] : physics;
    if (on.pixelGrid && cam.scale() >= kPixelGridScale) drawPixelGrid(dl, cam);
    if (on.positions) drawPositions(dl, cam, physics, render, on.labels);
  }
  // Over everything: a contact's marker sits on a body's edge, where the traced move's hit and
  // the positions' outlines would hide it.
  if (on.bodies) drawContactEvents(dl, cam, pic.contactEvents);
  dl.PopClipRect();
}

}  // namespace tv::ui
