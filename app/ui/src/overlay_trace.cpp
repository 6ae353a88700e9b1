// One move, from its MoveTrace: where the broad phase looked, what the narrow phase tested, the
// sweep, the substeps, the hits and what each response did. Every shape is a field of the
// record; nothing is recomputed.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "draw_util.hpp"
#include "tv/ui/overlays.hpp"
#include "tv/ui/palette.hpp"

namespace tv::ui {

namespace pal = palette;
using detail::label;

namespace {

constexpr float kNormalLength = 28.0f;  // screen px: a normal is a direction, not a distance

ImVec2 centre(const Camera& cam, const Rect& r) {
  return cam.toScreen(r.center());
}

// The midpoint of the edge of `r` that faces along -normal: where the body met the obstacle.
Vec2 contactPoint(const Rect& r, Vec2 normal) {
  const Vec2 c = r.center();
  if (normal.x < 0) return {r.right(), c.y};
  if (normal.x > 0) return {r.x, c.y};
  if (normal.y < 0) return {c.x, r.bottom()};
  if (normal.y > 0) return {c.x, r.y};
  return c;
}

std::string format(const char* fmt, double a) {
  char text[64];
  std::snprintf(text, sizeof text, fmt, a);
  return text;
}

}  // namespace

void drawMoveBackdrop(ImDrawList& dl, const Camera& cam, const Grid& grid, const MoveTrace& m,
                      const Overlays& on) {
  if (on.visitedCells && !m.cells.empty()) {
    // Legs revisit cells; each is drawn once so the tint means "visited", not "how often".
    std::vector<Cell> cells = m.cells;
    std::sort(cells.begin(), cells.end(),
              [](Cell a, Cell b) { return a.y < b.y || (a.y == b.y && a.x < b.x); });
    cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
    for (const Cell c : cells) {
      const Rect b = grid.bounds(c);
      if (!cam.sees(b)) continue;
      detail::fill(dl, cam, b, pal::kVisitedCell);
      detail::outline(dl, cam, b, pal::kVisitedEdge);
    }
  }
  if (on.hull && cam.sees(unite(m.start, m.start.at(m.goal)))) {
    const Rect a = m.start, b = m.start.at(m.goal);
    std::vector<ImVec2> pts;
    for (const Rect& r : {a, b}) {
      pts.push_back(cam.toScreen({r.x, r.y}));
      pts.push_back(cam.toScreen({r.right(), r.y}));
      pts.push_back(cam.toScreen({r.x, r.bottom()}));
      pts.push_back(cam.toScreen({r.right(), r.bottom()}));
    }
    const std::vector<ImVec2> hull = detail::convexHull(std::move(pts));
    if (hull.size() >= 3) {
      dl.AddConvexPolyFilled(hull.data(), static_cast<int>(hull.size()), pal::kHull);
      dl.AddPolyline(hull.data(), static_cast<int>(hull.size()), pal::kHullEdge, ImDrawFlags_Closed,
                     1.0f);
    }
  }
}

void drawMove(ImDrawList& dl, const Camera& cam, const World& world, const MoveTrace& m,
              const Overlays& on) {
  if (on.candidates) {
    for (const ItemId id : m.candidates) {
      if (!world.has(id)) continue;  // removed since: nothing to point at
      const Rect r = world.rect(id);
      if (cam.sees(r)) detail::outline(dl, cam, r, pal::kCandidate, 2.0f);
    }
  }
  if (on.substeps) {
    for (const Vec2 p : m.substeps) {
      const Rect ghost = m.start.at(p);
      if (!cam.sees(ghost)) continue;
      detail::dashedOutline(dl, cam, ghost, pal::kSubstep, 2.0f);
      const ImVec2 c = centre(cam, ghost);
      dl.AddLine({c.x, c.y - 4}, {c.x, c.y + 5}, pal::kSubstep, 1.5f);
    }
  }
  if (on.sweep) {
    const Vec2 size = m.start.size();
    for (const TraceLeg& leg : m.legs) {
      const Rect goal{leg.goal.x, leg.goal.y, size.x, size.y};
      if (!cam.sees(unite(leg.start, goal))) continue;
      detail::arrow(dl, centre(cam, leg.start), centre(cam, goal), pal::kSweep, 1.5f);
      detail::dashedOutline(dl, cam, goal, pal::kSweep, 3.0f);
    }
    if (cam.sees(m.start)) detail::outline(dl, cam, m.start, pal::kSweep);
    if (on.labels && cam.sees(unite(m.start, m.start.at(m.goal)))) {
      const ImVec2 s = cam.toScreenMin(m.start);
      const ImVec2 g = cam.toScreenMin(m.start.at(m.goal));
      // Each marker keeps its own label over it; two that would overlap are stacked, the goal's
      // a line higher, rather than merged into one that covers both markers.
      const float width = ImGui::CalcTextSize("start").x + 8.0f;
      const bool same = g.x == s.x && g.y == s.y;
      const bool clash = !same && std::abs(g.x - s.x) < width && std::abs(g.y - s.y) < 16.0f;
      label(dl, {s.x, s.y - 15}, pal::kSweep, same ? "start, goal" : "start");
      // Stacked: a line above the start's label, wherever the goal is (a goal a little lower
      // than the start would otherwise put its label back on the start's line).
      if (!same) label(dl, {g.x, clash ? s.y - 29.0f : g.y - 15.0f}, pal::kSweep, "goal");
    }
  }
  // Hit labels stack in one column beside the first hit: right of it, or left of it when the
  // view's edge would cut them.
  std::vector<std::string> texts;
  float widest = 0.0f;
  for (std::size_t k = 0; k < m.hits.size(); ++k) {
    const Collision& c = m.hits[k];
    // An overlapping start has no time of impact (ti holds minus the overlap area).
    std::string text = "hit " + std::to_string(k + 1) +
                       (c.overlaps ? std::string("  overlapping") : format("  ti %.3f", c.ti));
    if (on.responses) text += "  " + std::string(world.responseName(c.response));
    widest = std::max(widest, ImGui::CalcTextSize(text.c_str()).x);
    texts.push_back(std::move(text));
  }
  ImVec2 labelAt{};
  if (!m.hits.empty()) {
    const Rect first = m.hits.front().itemRect.at(m.hits.front().touch);
    labelAt = cam.toScreenMax(first);
    labelAt.x += 6;
    if (labelAt.x + widest > cam.screenMax().x) labelAt.x = cam.toScreenMin(first).x - widest - 6;
  }
  for (std::size_t k = 0; k < m.hits.size(); ++k) {
    const Collision& c = m.hits[k];
    const Rect atTouch = c.itemRect.at(c.touch);
    if (!cam.sees(unite(atTouch, c.itemRect.at(c.target)))) continue;
    if (on.responses && c.target != c.touch) {
      const Rect to = c.itemRect.at(c.target);
      detail::dashedOutline(dl, cam, to, pal::kResponse, 3.0f);
      detail::arrow(dl, centre(cam, atTouch), centre(cam, to), pal::kResponse, 1.5f);
    }
    if (on.hits) {
      detail::outline(dl, cam, atTouch, pal::kHit, 2.0f);
      const ImVec2 from = cam.toScreen(contactPoint(atTouch, c.normal));
      const ImVec2 to{from.x + static_cast<float>(c.normal.x) * kNormalLength,
                      from.y + static_cast<float>(c.normal.y) * kNormalLength};
      detail::arrow(dl, from, to, pal::kHit, 2.0f);
      const ImVec2 t = cam.toScreen(c.touch);
      dl.AddCircleFilled(t, 3.5f, pal::kHit);
    }
    if (on.labels && (on.hits || on.responses)) {
      label(dl, {labelAt.x, labelAt.y + 2 + 14.0f * static_cast<float>(k)}, pal::kHit, texts[k]);
    }
  }
}

void drawMoveHistory(ImDrawList& dl, const Camera& cam, std::span<const TracedMove> moves) {
  // Earlier moves as a faint polyline of where the body started each tick, so a tunnelling
  // bullet's path shows the jump across the wall.
  for (const TracedMove& t : moves) {
    const MoveTrace& m = t.trace;
    if (!cam.sees(unite(m.start, m.start.at(m.final)))) continue;
    const ImVec2 a = centre(cam, m.start), b = centre(cam, m.start.at(m.final));
    dl.AddLine(a, b, pal::kHistory, 1.0f);
    detail::outline(dl, cam, m.start, pal::kHistory);
  }
}

}  // namespace tv::ui
