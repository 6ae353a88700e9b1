#pragma once
// The fixed windows every layout places (internal to tv_ui): view.cpp builds its screens
// from these.

#include "imgui.h"
#include "tv/ui/palette.hpp"

namespace tv::ui::detail {

inline constexpr ImGuiWindowFlags kFixed =
    ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
    ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing;
inline constexpr ImGuiWindowFlags kOverlay =
    ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings |
    ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav;
inline constexpr float kMargin = 8.0f;

/// The next window's position (its `pivot` there) and size, every frame.
void place(ImVec2 pos, ImVec2 size, ImVec2 pivot = {0, 0});
/// A borderless window that only hosts a world view; pair with ImGui::End().
bool beginCanvas(const char* name, ImVec2 pos, ImVec2 size);
/// The colour legend across the bottom of a world view at `origin` of `size`, in `columns`;
/// returns how much of the view's bottom it covers. `scope`: the entries it lists
/// (legendContents).
float legendOverlay(ImVec2 origin, ImVec2 size, int columns, palette::LegendScope scope);

}  // namespace tv::ui::detail
