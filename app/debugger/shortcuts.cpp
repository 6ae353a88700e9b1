#include "shortcuts.hpp"

#include "imgui.h"
#include "tv/ui/palette.hpp"

namespace tv::viewer {

namespace {

constexpr Shortcut kShortcuts[] = {
    {Command::pause, "P", "pause / play (Space too)"},
    {Command::step, "O", "single step: one tick, paused"},
    {Command::stepBack, ",", "step back one tick through history"},
    {Command::stepForward, ".", "step forward one tick through history"},
    {Command::restart, "R", "restart from tick 0"},
    {Command::slower, "-", "slower (down to 0.25x)"},
    {Command::faster, "=", "faster (up to 4x)"},
    {Command::frameAll, "Home", "frame everything (the scene's camera)"},
    {Command::follow, "F", "follow the traced body's last move"},
    {Command::compare, "C", "compare discrete, substep and continuous (again: one mover)"},
    {Command::overlay, "V", "compared movers side by side / overlaid"},
    {Command::sweep, "T", "substep sweep: tunnelled, error, ms per tick against length"},
    {Command::openScene, "Ctrl+O", "open a scene: type to filter, Enter opens"},
    {Command::previousScene, "[", "previous scene"},
    {Command::nextScene, "]", "next scene"},
    {Command::help, "F1", "this window (Esc closes the topmost window)"},
    {Command::quit, "Ctrl+Q", "quit (settings are saved)"},
};

struct MouseHelp {
  const char* what;
  const char* does;
};
constexpr MouseHelp kMouse[] = {
    {"wheel", "zoom about the cursor"},
    {"right drag", "pan"},
    {"left click", "select (trace) the body under the cursor; it stays selected while scrubbing"},
    {"timeline", "click or drag to scrub; red mark: first failure, orange: first difference"},
};

}  // namespace

std::span<const Shortcut> shortcuts() {
  return kShortcuts;
}

const char* keysOf(Command c) {
  for (const Shortcut& s : kShortcuts) {
    if (s.command == c) return s.keys;
  }
  return "";
}

void drawHelp(bool* open, ImVec2 pos, ImVec2 size) {
  // Over the column of controls, beside the world: the picture it explains stays in view.
  ImGui::SetNextWindowPos(pos, ImGuiCond_Appearing);
  ImGui::SetNextWindowSize(size, ImGuiCond_Appearing);
  ImGui::SetNextWindowBgAlpha(1.0f);  // over the panel: its labels must not show through
  if (!ImGui::Begin("Help (F1)", open, ImGuiWindowFlags_NoCollapse)) {
    ImGui::End();
    return;
  }
  ImGui::TextWrapped(
      "Tunnelvision shows, tick by tick, what each move did: the cells it visited (yellow), the "
      "items it tested (magenta), its sweep (white), substeps (violet), hits (red) and what the "
      "response did (green). Pause, step to the bad tick, change a number in the panel on the "
      "right, and the scene re-runs from tick 0 to the same tick.");
  ImGui::Spacing();
  const ImVec4 key = ImGui::ColorConvertU32ToFloat4(ui::palette::kPixel);
  if (ImGui::BeginTable("keys", 2, ImGuiTableFlags_RowBg)) {
    ImGui::TableSetupColumn("keys", ImGuiTableColumnFlags_WidthFixed, 80.0f);
    ImGui::TableSetupColumn("what", ImGuiTableColumnFlags_WidthStretch);
    for (const Shortcut& s : kShortcuts) {
      ImGui::TableNextColumn();
      ImGui::TextColored(key, "%s", s.keys);
      ImGui::TableNextColumn();
      ImGui::TextWrapped("%s", s.what);
    }
    for (const MouseHelp& m : kMouse) {
      ImGui::TableNextColumn();
      ImGui::TextColored(key, "%s", m.what);
      ImGui::TableNextColumn();
      ImGui::TextWrapped("%s", m.does);
    }
    ImGui::EndTable();
  }
  ImGui::Spacing();
  ImGui::TextWrapped(
      "Keys reach the world only while no text field is being edited. This window "
      "opens on the first run; F1 brings it back.");
  ImGui::End();
}

}  // namespace tv::viewer
