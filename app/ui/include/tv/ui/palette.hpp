#pragma once
/// The one palette: every colour the debugger draws is chosen here, once, and the legend lists
/// them from the same table, so a colour on screen always means the same thing.
///
/// The hues keep the trace's story apart: yellow = where the broad phase looked, magenta =
/// what the narrow phase tested, white/cyan = the sweep, violet = substeps, red = hits, green =
/// what the response did, cyan/orange/yellow = physics vs render vs pixel.

#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

#include "imgui.h"

namespace tv::ui::palette {

// -- the world -----------------------------------------------------------------------------------
inline constexpr ImU32 kBackground = IM_COL32(24, 27, 34, 255);
inline constexpr ImU32 kGridLine = IM_COL32(52, 58, 70, 255);
/// Occupied cells: this colour, more opaque the more items the cell holds (see occupiedFill).
inline constexpr ImU32 kOccupied = IM_COL32(70, 110, 190, 255);
inline constexpr ImU32 kOccupiedText = IM_COL32(150, 180, 235, 255);
inline constexpr ImU32 kSolid = IM_COL32(112, 118, 132, 255);
inline constexpr ImU32 kSolidEdge = IM_COL32(160, 166, 180, 255);
inline constexpr ImU32 kBody = IM_COL32(72, 200, 170, 255);
/// A body that no longer moves (stopped, resolved).
inline constexpr ImU32 kBodyIdle = IM_COL32(52, 110, 98, 255);
inline constexpr ImU32 kSelected = IM_COL32(255, 255, 255, 255);
/// Bodies of a recording that never move but say what they are (a category: an enemy that
/// stands and shoots, a coin): one of these hues per category, picked from its name, so that
/// they do not read as level geometry (kSolid).
inline constexpr ImU32 kCategoryHues[] = {
    IM_COL32(230, 120, 200, 255), IM_COL32(240, 170, 70, 255),  IM_COL32(120, 170, 255, 255),
    IM_COL32(200, 220, 90, 255),  IM_COL32(250, 110, 110, 255), IM_COL32(170, 130, 250, 255),
    IM_COL32(90, 210, 230, 255),  IM_COL32(230, 200, 150, 255),
};

// -- what one move did (from its MoveTrace) ------------------------------------------------------
inline constexpr ImU32 kVisitedCell = IM_COL32(240, 190, 60, 60);
inline constexpr ImU32 kVisitedEdge = IM_COL32(240, 190, 60, 200);
inline constexpr ImU32 kCandidate = IM_COL32(220, 100, 230, 255);
inline constexpr ImU32 kSweep = IM_COL32(240, 240, 240, 255);
inline constexpr ImU32 kHull = IM_COL32(90, 180, 255, 48);
inline constexpr ImU32 kHullEdge = IM_COL32(90, 180, 255, 170);
inline constexpr ImU32 kSubstep = IM_COL32(170, 140, 255, 220);
inline constexpr ImU32 kHit = IM_COL32(255, 80, 80, 255);
inline constexpr ImU32 kResponse = IM_COL32(110, 230, 110, 255);
/// Earlier moves of the selected body, drawn faintly behind the last one.
inline constexpr ImU32 kHistory = IM_COL32(240, 240, 240, 70);

// -- moving solids and one-way platforms (tv/solid.hpp) ------------------------------------------
/// A solid the scene moves (a lift, a crusher, a door, a moving platform): solid, but not still.
inline constexpr ImU32 kMovingSolid = IM_COL32(150, 118, 78, 255);
/// The side a one-way solid blocks from (its top): a dashed line along it.
inline constexpr ImU32 kOneWay = IM_COL32(190, 255, 90, 255);
/// A body a moving solid carried this tick (it rode it): outlined, an arrow from where it was.
inline constexpr ImU32 kCarried = IM_COL32(110, 190, 255, 255);
/// A body a moving solid pushed out of its way this tick: outlined, an arrow from where it was.
inline constexpr ImU32 kPushed = IM_COL32(255, 120, 170, 255);
/// A body a moving solid pressed against something that would not give (a squish): filled.
inline constexpr ImU32 kSquished = IM_COL32(210, 30, 80, 255);
/// A corner correction (tv::moveCornered): the body where it met a ceiling's corner (dashed)
/// and beside it, nudged, with an arrow.
inline constexpr ImU32 kNudge = IM_COL32(0, 240, 0, 255);

// -- contact events (tv/contact.hpp) -------------------------------------------------------------
/// A contact that began this tick (tv::ContactPhase::begin): a filled diamond on the touching
/// edge, outlined dark so it reads on any fill.
inline constexpr ImU32 kContactBegin = IM_COL32(255, 196, 0, 255);
/// A contact that persists: a thin line along the touching edge, just inside the body.
inline constexpr ImU32 kContactPersist = IM_COL32(255, 236, 170, 255);
/// A contact that ended this tick: a hollow diamond where the edge last touched.
inline constexpr ImU32 kContactEnd = IM_COL32(255, 110, 60, 255);
/// The outline that keeps a contact marker readable on a light fill.
inline constexpr ImU32 kContactRim = IM_COL32(20, 20, 20, 230);

// -- where the body is drawn -------------------------------------------------------------------
inline constexpr ImU32 kPhysics = IM_COL32(80, 220, 255, 255);
inline constexpr ImU32 kRender = IM_COL32(255, 150, 50, 255);
inline constexpr ImU32 kPixel = IM_COL32(255, 230, 60, 255);
inline constexpr ImU32 kPixelGrid = IM_COL32(255, 255, 255, 22);

// -- text --------------------------------------------------------------------------------------
inline constexpr ImU32 kLabel = IM_COL32(235, 235, 235, 255);
inline constexpr ImU32 kLabelShadow = IM_COL32(0, 0, 0, 200);
inline constexpr ImU32 kBad = IM_COL32(255, 90, 90, 255);
inline constexpr ImU32 kGood = IM_COL32(110, 230, 110, 255);
inline constexpr ImU32 kDim = IM_COL32(150, 155, 165, 255);
/// A what-if run: the frame from which the game's recorded goals stop making sense.
inline constexpr ImU32 kImplausible = IM_COL32(200, 120, 255, 255);

// -- comparisons -----------------------------------------------------------------------------
/// The movers of a comparison drawn in one view: the first keeps the usual colours, the others
/// are outlined in these, in order (cycling).
inline constexpr ImU32 kCompareTints[] = {
    IM_COL32(255, 150, 50, 255),   // orange
    IM_COL32(200, 120, 255, 255),  // violet
    IM_COL32(255, 90, 160, 255),   // pink
    IM_COL32(120, 200, 255, 255),  // sky
};

/// Fill of an occupied cell holding `count` items: deeper with the count, saturating at 8 so
/// that one item is visible and a crowded cell still leaves its contents readable.
[[nodiscard]] ImU32 occupiedFill(std::size_t count);

/// The hue of a category (kCategoryHues), the same for the same name in every session.
[[nodiscard]] ImU32 categoryColour(std::string_view category);

/// How a legend entry is drawn: its swatch's shape says which overlay primitive it is.
enum class Swatch { fill, outline, line, arrow, dot, dashed, diamond, hollowDiamond };

struct LegendEntry {
  ImU32 colour;
  Swatch swatch;
  const char* label;
  /// Only a recording's or a live game's items are drawn so (a category's colour): a scene's
  /// legend leaves it out.
  bool recordedOnly = false;
  /// Only drawn where there are such things (kWithOneWay, kWithMovingSolids,
  /// kWithCornerNudge, kWithContacts): other views leave it out.
  std::uint8_t onlyWith = 0;
};

inline constexpr std::uint8_t kWithOneWay = 1;        ///< a one-way side in the view's world
inline constexpr std::uint8_t kWithMovingSolids = 2;  ///< a solid the scene moves
inline constexpr std::uint8_t kWithCornerNudge = 4;   ///< a body with corner correction
inline constexpr std::uint8_t kWithContacts = 8;  ///< bodies that read their contacts (events)

/// Which of the legend's optional entries a view lists: only those it can draw, so the legend
/// takes no height from the view for colours that cannot appear in it.
struct LegendScope {
  bool recorded = false;  ///< a recording's or a live game's view
  std::uint8_t has = 0;   ///< what its world has: kWithOneWay, kWithMovingSolids, ...
  [[nodiscard]] bool shows(const LegendEntry& e) const {
    return (!e.recordedOnly || recorded) && (e.onlyWith & has) == e.onlyWith;
  }
};

/// Every colour above that means something in the world view, in reading order.
[[nodiscard]] std::span<const LegendEntry> legend();

}  // namespace tv::ui::palette

namespace tv::ui {
/// The debugger's look (dark, compact, square), for every program that draws it.
void applyStyle(ImGuiStyle& style);
}  // namespace tv::ui
