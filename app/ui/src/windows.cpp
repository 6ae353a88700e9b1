// The fixed windows every layout places.
#include "windows.hpp"

#include "tv/ui/panels.hpp"

namespace tv::ui::detail {

void place(ImVec2 pos, ImVec2 size, ImVec2 pivot) {
  ImGui::SetNextWindowPos(pos, ImGuiCond_Always, pivot);
  ImGui::SetNextWindowSize(size, ImGuiCond_Always);
}

bool beginCanvas(const char* name, ImVec2 pos, ImVec2 size) {
  place(pos, size);
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, {0, 0});
  ImGui::PushStyleVar(ImGuiStyleVar_WindowBorderSize, 0.0f);
  const bool open = ImGui::Begin(
      name, nullptr,
      kOverlay | ImGuiWindowFlags_NoBringToFrontOnFocus | ImGuiWindowFlags_NoScrollWithMouse);
  ImGui::PopStyleVar(2);
  return open;
}

float legendOverlay(ImVec2 origin, ImVec2 size, int columns, palette::LegendScope scope) {
  ImGui::SetNextWindowBgAlpha(0.82f);
  place({origin.x + kMargin, origin.y + size.y - kMargin}, {size.x - 2 * kMargin, 0}, {0, 1});
  float covered = 0.0f;
  if (ImGui::Begin("Legend", nullptr, kOverlay)) {
    legendContents(columns, scope);
    covered = origin.y + size.y - ImGui::GetWindowPos().y + kMargin;
  }
  ImGui::End();
  return covered;
}

}  // namespace tv::ui::detail
