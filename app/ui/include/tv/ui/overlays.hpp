#pragma once
/// World overlays, drawn through an ImDrawList from what the simulation and core recorded: the
/// world's grid and items, and the selected body's MoveTraces. Nothing here recomputes a sweep,
/// a cell or a hit — a picture shows what the game got. Only what the camera sees is drawn.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <utility>

#include "imgui.h"
#include "tv/sim/body.hpp"
#include "tv/sim/scene.hpp"
#include "tv/trace.hpp"
#include "tv/ui/camera.hpp"
#include "tv/world.hpp"

namespace tv::ui {

/// Which overlays are on; each is one toggle in the controls panel.
struct Overlays {
  bool solids = true;
  bool bodies = true;
  bool grid = true;          ///< spatial-hash cell lines
  bool occupied = true;      ///< occupied cells shaded by item count, the count printed
  bool visitedCells = true;  ///< cells the selected body's last move visited
  bool candidates = true;    ///< items its narrow phase tested
  bool sweep = true;         ///< the swept segment of each leg, start to goal
  bool hull = true;          ///< the swept hull from start to goal
  bool substeps = true;      ///< substep boundaries along the path (ghost rects and ticks)
  bool hits = true;          ///< rect at touch, normal arrow, touch point
  bool responses = true;     ///< where each response sent the body (slide, bounce target...)
  bool history = true;       ///< earlier moves of the selected body, faintly
  bool positions = true;     ///< physics vs interpolated render position vs floored pixel
  bool pixelGrid = true;     ///< one line per world unit, once zoomed in far enough
  bool labels = true;        ///< short text beside the traced move's parts
};

/// An overlay's name (as in the controls panel and tv-render's --hide/--show) and its flag.
struct OverlayToggle {
  const char* name;
  bool Overlays::*flag;
};
/// Every overlay, in the controls panel's order.
[[nodiscard]] std::span<const OverlayToggle> overlayToggles();

/// One recorded move of the selected body, with the tick that made it.
struct TracedMove {
  std::uint64_t tick = 0;
  MoveTrace trace;
};

/// Everything the world view draws, gathered for one frame.
struct WorldPicture {
  const World* world = nullptr;
  std::span<const sim::Solid> solids;
  std::span<const sim::Body> bodies;
  /// Per body, where it is drawn (interpolated between ticks); empty: at its physics rect.
  std::span<const Rect> renderRects;
  /// Per body, a fill of its own (0: the usual body colours): a recording's items that never
  /// move but have a category.
  std::span<const ImU32> bodyFills;
  /// What the moving solids did to bodies in the last tick (a scene's: carried, pushed,
  /// squished); drawn over the bodies in their own colours.
  std::span<const sim::SolidContact> contacts;
  /// The corner corrections made in the last tick (a scene's bodies with Body::maxNudge).
  std::span<const sim::CornerNudgeAt> nudges;
  /// Contact events of the frame (tv::Contacts updates: a scene's bodies with Body::contacts, a
  /// recording's Contacts::update calls), each with where both items stood at the update.
  std::span<const sim::ContactAt> contactEvents;
  std::optional<std::size_t> selected;
  /// The selected body's recent moves, oldest first; the last is drawn in full.
  std::span<const TracedMove> moves;
};

/// Screen pixels per world unit from which the pixel grid is drawn.
inline constexpr double kPixelGridScale = 6.0;

/// Draws the picture's overlays, clipped to the camera's screen rect.
void drawWorld(ImDrawList& dl, const Camera& cam, const WorldPicture& pic, const Overlays& on);

// The parts, for views that want only some of them.
void drawGrid(ImDrawList& dl, const Camera& cam, const World& world, const Overlays& on);
/// Each occupied cell's item count, at its top-left corner, once cells are big enough for it.
void drawCellCounts(ImDrawList& dl, const Camera& cam, const World& world);
void drawSolids(ImDrawList& dl, const Camera& cam, std::span<const sim::Solid> solids);
void drawBodies(ImDrawList& dl, const Camera& cam, const WorldPicture& pic);
/// Contact events on the touching edge: a begin a filled diamond, an end a hollow one, a contact
/// that persists a thin line along the edge just inside the body.
void drawContactEvents(ImDrawList& dl, const Camera& cam,
                       std::span<const sim::ContactAt> events);
/// Where a contact touches, in world units: the shared part of the body's edge facing `other`
/// (by the event's normal), or the body's whole edge when they no longer share one (an end);
/// for an overlap (normal 0), the centre of the overlap, as a segment of length 0.
[[nodiscard]] std::pair<Vec2, Vec2> contactEdge(const sim::ContactAt& c);
/// What a move covered — visited cells and the swept hull — drawn under the solids and bodies.
void drawMoveBackdrop(ImDrawList& dl, const Camera& cam, const Grid& grid, const MoveTrace& move,
                      const Overlays& on);
/// What a move did — candidates, substeps, sweep, hits, responses — drawn over everything.
void drawMove(ImDrawList& dl, const Camera& cam, const World& world, const MoveTrace& move,
              const Overlays& on);
void drawMoveHistory(ImDrawList& dl, const Camera& cam, std::span<const TracedMove> moves);
/// The selected body three ways: where physics has it, where the renderer interpolates it, and
/// the whole pixel that `floorOnDraw` snaps the render position to.
void drawPositions(ImDrawList& dl, const Camera& cam, const Rect& physics, const Rect& render,
                   bool labels);
void drawPixelGrid(ImDrawList& dl, const Camera& cam);

}  // namespace tv::ui
