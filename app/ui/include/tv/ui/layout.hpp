#pragma once
/// Where the panels go. Two layouts: the debugger (one session: world view with HUD and legend,
/// a column of controls, counters and inspector) and the comparison (several sessions of one
/// scene side by side, each labelled with its mover). Both place every window with
/// ImGuiCond_Always, so a picture depends on nothing but its inputs.

#include <optional>
#include <span>
#include <string>

#include "imgui.h"
#include "tv/ui/panels.hpp"
#include "tv/ui/session.hpp"

namespace tv::ui {

/// The world view in the current window at the cursor: reserves `size`, frames the camera on
/// `state.frameView` (or keeps it), zooms with the wheel and pans with a right drag while
/// hovered (either drops frameView), and draws. Returns the body clicked, if any.
std::optional<std::size_t> worldView(const char* id, Session& session, DebuggerState& state,
                                     ImVec2 size);

/// The whole debugger filling `display`.
Actions debuggerLayout(Session& session, DebuggerState& state, ImVec2 display);
/// The same in the screen rect at `origin` of size `size` (e.g. under a menu bar).
Actions debuggerLayout(Session& session, DebuggerState& state, ImVec2 origin, ImVec2 size);

/// One panel per session, left to right, filling `display`; `title` heads the picture.
/// `states` pairs with `sessions`.
void comparisonLayout(std::span<Session* const> sessions, std::span<DebuggerState> states,
                      const std::string& title, ImVec2 display);

/// A body clicked in one panel of the comparison.
struct PanelPick {
  std::size_t panel = 0;
  std::size_t body = 0;
};
/// The same in the screen rect at `origin` of size `size`, the legend in `legendColumns`
/// columns; returns the body clicked, if any.
std::optional<PanelPick> comparisonLayout(std::span<Session* const> sessions,
                                          std::span<DebuggerState> states, const std::string& title,
                                          ImVec2 origin, ImVec2 size, int legendColumns = 8);

}  // namespace tv::ui
