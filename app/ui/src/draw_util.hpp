#pragma once
// Small drawing helpers shared by the overlay files (internal to tv_ui).

#include <span>
#include <string_view>
#include <vector>

#include "imgui.h"
#include "tv/geometry.hpp"
#include "tv/ui/camera.hpp"

namespace tv::ui::detail {

/// Text with a one-pixel shadow on a dark plate, readable on any fill, moved inside the clip
/// rect whole rather than cut at its edge. `anchored` text (a cell's count) stays where it is
/// without a plate, and is left out where it would not fit whole.
void label(ImDrawList& dl, ImVec2 at, ImU32 colour, std::string_view text, bool anchored = false);
/// A label wrapped to lines of at most `width` px, its last line where `label` would put its
/// one (the lines above it), kept inside the clip rect the same way.
void labelWrapped(ImDrawList& dl, ImVec2 at, ImU32 colour, std::string_view text, float width);
/// A rect's outline, at least one screen pixel wide so a thin item never vanishes.
void outline(ImDrawList& dl, const Camera& cam, const Rect& r, ImU32 colour,
             float thickness = 1.0f);
void fill(ImDrawList& dl, const Camera& cam, const Rect& r, ImU32 colour);
void dashedOutline(ImDrawList& dl, const Camera& cam, const Rect& r, ImU32 colour,
                   float dash = 4.0f);
void dashedLine(ImDrawList& dl, ImVec2 a, ImVec2 b, ImU32 colour, float dash = 4.0f,
                float thickness = 1.0f);
/// A line with an arrow head at `to`.
void arrow(ImDrawList& dl, ImVec2 from, ImVec2 to, ImU32 colour, float thickness = 1.5f);
/// Convex hull of points (Andrew's monotone chain), counter-clockwise on screen.
[[nodiscard]] std::vector<ImVec2> convexHull(std::vector<ImVec2> points);

}  // namespace tv::ui::detail
