#include "shortcuts.hpp"

#include <cmath>

#include "imgui.h"
#include "imgui_internal.h"
#include "tv/ui/palette.hpp"

namespace tv::viewer {

namespace {

constexpr Shortcut kShortcuts[] = {
    {Command::pause, "Space", "play / pause (P too)"},
    {Command::step, "O", "single step: one tick or frame, paused"},
    {Command::stepBack, ",", "step back one tick or frame through history"},
    {Command::stepForward, ".", "step forward one tick or frame"},
    {Command::nextCall, "Down", "next call (a body's move, a recorded call), across frames"},
    {Command::previousCall, "Up", "previous call"},
    {Command::frameEnd, "Enter", "the frame's end: no call selected"},
    {Command::restart, "R", "a scene from tick 0; a recording from its first frame"},
    {Command::slower, "-", "slower (down to 0.25x)"},
    {Command::faster, "=", "faster (up to 4x)"},
    {Command::frameAll, "Home", "frame everything"},
    {Command::follow, "F", "follow the traced move"},
    {Command::compare, "C", "compare discrete, substep and continuous (a recording: what-if "
                            "discrete); again: one panel"},
    {Command::overlay, "V", "compared panels side by side / overlaid"},
    {Command::whatIf, "W", "what-if: re-run under another mover, beside this run"},
    {Command::sweep, "T", "substep sweep (scenes): tunnelled, error, ms per tick against length"},
    {Command::items, "I", "the Items tab, its search ready to type in"},
    {Command::failures, "X", "the Failures tab: every move that failed"},
    {Command::firstFailure, "G", "go to the first failure: traced, centred, zoomed"},
    {Command::openScene, "Ctrl+O", "open a scene or a level file: type to filter, Enter opens"},
    {Command::openRecording, "Ctrl+R", "open a recording (or drop a .tvrec on the window)"},
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
    {"left click", "trace the item under the cursor; it stays traced while scrubbing"},
    {"timeline", "click or drag to scrub; red: first failure (ticks: every failure), orange: "
                 "first difference, violet: a what-if's goals stop making sense"},
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

bool drawHelp(bool* open, ImVec2 pos, ImVec2 size, bool place) {
  const char* title = "Help (F1)";
  // Being dragged: from now on where the person puts it.
  const ImGuiWindow* before = ImGui::FindWindowByName(title);
  if (before != nullptr && GImGui->MovingWindow == before) place = false;
  ImGui::SetNextWindowPos(pos, place ? ImGuiCond_Always : ImGuiCond_Appearing);
  ImGui::SetNextWindowSize(size, place ? ImGuiCond_Always : ImGuiCond_Appearing);
  ImGui::SetNextWindowBgAlpha(1.0f);  // over the panel: its labels must not show through
  if (!ImGui::Begin(title, open, ImGuiWindowFlags_NoCollapse)) {
    ImGui::End();
    return place;
  }
  // Resized by its grip this frame: the person's size from now on. (ImGui puts the size it is
  // given on whole pixels.)
  const ImVec2 now = ImGui::GetWindowSize();
  if (place && (std::fabs(now.x - size.x) > 1.0f || std::fabs(now.y - size.y) > 1.0f)) place = false;
  ImGui::TextWrapped(
      "Tunnelvision shows, frame by frame, what each move did: the cells it visited (yellow), "
      "the items it tested (magenta), its sweep (white), substeps (violet), hits (red) and what "
      "the response did (green), and says in words what happened. Where bodies read their "
      "contacts, a contact that began is a gold diamond on the touching edge, one that persists "
      "a cream line, one that ended a hollow orange diamond; the inspector says what the body "
      "stands on. The Failures tab lists every move that failed (and every rider a platform "
      "dropped or popped): click one to go there. A scene's frames are ticks, and a change in "
      "the panel on the right re-runs it to the same tick; a recording's frames are the game's, "
      "each a list of calls.");
  ImGui::Spacing();
  const ImVec4 key = ImGui::ColorConvertU32ToFloat4(ui::palette::kPixel);
  if (ImGui::BeginTable("keys", 2, ImGuiTableFlags_RowBg)) {
    ImGui::TableSetupColumn("keys", ImGuiTableColumnFlags_WidthFixed,
                            ImGui::CalcTextSize("right drag").x + 8.0f);
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
  return place;
}

}  // namespace tv::viewer
