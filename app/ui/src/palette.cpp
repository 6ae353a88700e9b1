#include "tv/ui/palette.hpp"

#include <cstdint>

#include <algorithm>

namespace tv::ui::palette {

ImU32 occupiedFill(std::size_t count) {
  const std::size_t n = std::min<std::size_t>(count, 8);
  const auto alpha = static_cast<unsigned>(24 + n * 14);  // 38 .. 136 of 255
  return (kOccupied & ~IM_COL32_A_MASK) | (alpha << IM_COL32_A_SHIFT);
}

std::span<const LegendEntry> legend() {
  static constexpr LegendEntry kEntries[] = {
      {kSolid, Swatch::fill, "solid"},
      {kOccupied, Swatch::fill, "cell: n items"},
      {kVisitedEdge, Swatch::fill, "visited cell"},
      {kCandidate, Swatch::outline, "candidate"},
      {kBody, Swatch::fill, "body, moving"},
      {kBodyIdle, Swatch::fill, "body, stopped"},
      {kCategoryHues[0], Swatch::fill, "never moves, by category", true},
      {kSelected, Swatch::outline, "traced body"},
      {kSweep, Swatch::arrow, "swept segment"},
      {kHullEdge, Swatch::fill, "swept hull"},
      {kSubstep, Swatch::dashed, "substep boundary"},
      {kHit, Swatch::outline, "hit rect, normal"},
      {kHit, Swatch::dot, "touch point"},
      {kResponse, Swatch::dashed, "response target"},
      {kPhysics, Swatch::outline, "physics position"},
      {kRender, Swatch::outline, "render position"},
      {kPixel, Swatch::outline, "floored pixel"},
      {kMovingSolid, Swatch::fill, "moving solid", false, kWithMovingSolids},
      {kOneWay, Swatch::line, "one-way side", false, kWithOneWay},
      {kCarried, Swatch::arrow, "carried by a solid", false, kWithMovingSolids},
      {kPushed, Swatch::arrow, "pushed by a solid", false, kWithMovingSolids},
      {kSquished, Swatch::fill, "squished", false, kWithMovingSolids},
      {kNudge, Swatch::arrow, "corner nudge", false, kWithCornerNudge},
      {kContactBegin, Swatch::diamond, "contact begins", false, kWithContacts},
      {kContactPersist, Swatch::line, "contact persists", false, kWithContacts},
      {kContactEnd, Swatch::hollowDiamond, "contact ends", false, kWithContacts},
  };
  return kEntries;
}

ImU32 categoryColour(std::string_view category) {
  // FNV-1a of the name: stable across runs and machines (std::hash is not promised to be).
  std::uint32_t h = 2166136261u;
  for (const char c : category) h = (h ^ static_cast<unsigned char>(c)) * 16777619u;
  return kCategoryHues[h % std::size(kCategoryHues)];
}

}  // namespace tv::ui::palette

namespace tv::ui {

void applyStyle(ImGuiStyle& style) {
  ImGui::StyleColorsDark(&style);
  // Tighter rows than ImGui's default: the column fits controls, counters and the inspector at
  // 720 px; square corners match the pixel grid.
  style.WindowRounding = 0.0f;
  style.FramePadding = {4.0f, 2.0f};
  style.ItemSpacing = {8.0f, 3.0f};
  style.CellPadding = {4.0f, 1.0f};
  style.WindowPadding = {8.0f, 6.0f};
  // Menus, combo lists and tooltips open over the panels: see-through, the labels beneath read
  // through their items.
  style.Colors[ImGuiCol_PopupBg].w = 1.0f;
}

}  // namespace tv::ui
