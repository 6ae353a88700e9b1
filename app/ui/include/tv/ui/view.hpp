#pragma once
/// The view: one layout for every source and every arrangement. One panel is the world with a
/// HUD and the legend; several are side by side under one title (a scene across movers, a
/// recording beside its what-if runs) or overlaid in one world. Beside them, one column: the
/// source's own controls (a scene's parameters, a recording's calls), then the tabs (Inspector,
/// Calls, Items, Failures, Counters). Every window is placed with ImGuiCond_Always, so a
/// picture depends on nothing but its inputs: tv-render and the debugger draw the same pixels.

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "imgui.h"
#include "tv/ui/panels.hpp"
#include "tv/ui/session.hpp"

namespace tv::ui {

/// What the person is looking at, for a whole session.
struct ViewState {
  std::vector<DebuggerState> panels;  ///< one per session panel; panel 0's holds the controls
  bool overlaid = false;              ///< several panels drawn in one world view
  std::size_t inspected = 0;          ///< the panel whose inspector is shown
  std::optional<Tab> showTab;         ///< bring a tab forward once
  OutlinerState items;
  bool revealCall = false;            ///< scroll the calls to the selected one once
  std::string caption;                ///< a line under a comparison's title (a still's)
  FailureList failures;               ///< filled by the debugger (a still: by its checks)
  /// The failure last gone to (its row is marked in the Failures tab), and scroll to it once.
  std::optional<std::size_t> shownFailure;
  bool revealFailure = false;
  /// Where the column's tabs were drawn in the last frame (screen px): a window that must not
  /// hide the world or the controls (Help on the first run) goes over them.
  ImVec2 tabsPos{0, 0}, tabsSize{0, 0};
};

/// One DebuggerState per panel of `session`; new ones take panel 0's overlays and framing.
void syncPanels(ViewState& view, const Session& session);

/// The world view of `source` in the current window at the cursor: reserves `size`, frames the
/// camera on `state.frameView` (or keeps it), zooms with the wheel and pans with a right drag
/// while hovered (either drops frameView), draws, and says in words what happened to the traced
/// move. Returns the item clicked, if any.
std::optional<ItemId> worldView(const char* id, Source& source, DebuggerState& state, ImVec2 size,
                                const FailureList* failures = nullptr, std::size_t panel = 0);

/// The earliest failure of `list`, whichever panel it is in (the list is by panel), if any.
[[nodiscard]] std::optional<std::size_t> firstFailureIndex(const FailureList& list);

/// What every "go" to failure `index` of `view.failures` does, in the debugger and in a still:
/// the session at the failure (Session::showFailure), the failing panel inspected, every panel
/// framed on the failing move, its row marked in the Failures tab. Throws what the session
/// throws; an index out of range changes nothing.
void goToFailure(Session& session, ViewState& view, std::size_t index);

/// The whole view in the screen rect at `origin` of `size`. Returns what was asked.
Actions sessionView(Session& session, ViewState& view, ImVec2 origin, ImVec2 size);

/// A scene's verdict for one panel, in the words of the scene ("discrete: 8 of 10 projectiles
/// tunnelled (first at tick 1)"); `all` decides which counters are shown so panels line up.
struct Verdict {
  std::string text;
  bool bad = false;
  bool neutral = false;  ///< neither good nor bad (nothing is solid)
};
[[nodiscard]] Verdict verdictOf(const SimSource& source, std::span<Source* const> all,
                                bool withMover);

}  // namespace tv::ui
