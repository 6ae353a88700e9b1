#pragma once
/// How a recording is drawn: the world view (the same overlays as a built-in scene), the frame's
/// calls, the outliner of recorded items, the inspector of the selected call's whole trace, and
/// the layout that places them. tv-render and the debugger draw a recording with these, so a
/// test can demand the same pixels from both.

#include <cstdint>
#include <optional>
#include <string>

#include "imgui.h"
#include "tv/ui/panels.hpp"
#include "tv/ui/recording_session.hpp"

namespace tv::ui {

/// What the person is looking at in a recording.
struct RecordingViewState {
  DebuggerState view;       ///< overlays, camera, framing, paused (as for a scene)
  std::string itemFilter;   ///< the outliner's search
  bool movingOnly = false;  ///< the outliner lists only items that move
  /// Bring a tab of the panel under the calls forward once: 0 inspector, 1 items.
  std::optional<int> showTab;
  /// Scroll the call list to the selected call once (it was chosen from outside the list).
  bool revealCall = false;
};

/// What the person asked for this frame.
struct RecordingActions {
  std::optional<std::optional<std::uint32_t>> call;  ///< select a call (or the frame's end)
  std::optional<std::optional<ItemId>> item;         ///< trace another item (or none)
};

/// The world view at the cursor (as ui::worldView): camera, wheel zoom, right-drag pan; returns
/// the item clicked, if any.
std::optional<ItemId> recordingWorldView(const char* id, RecordingSession& session,
                                         DebuggerState& state, ImVec2 size);

/// One line per call of the frame, selectable.
void recordingCallsContents(const RecordingSession& session, RecordingViewState& state,
                            RecordingActions& actions);
/// The recorded items by label and category, filtered by the search; click to trace one.
void recordingOutlinerContents(const RecordingSession& session, RecordingViewState& state,
                               RecordingActions& actions);
/// The selected call's whole trace (cells, candidates with the filter's recorded answers,
/// sweeps, hits, responses, where it ended); with no call, the traced item and its moves.
void recordingInspectorContents(const RecordingSession& session);
/// File, frame and call, and what is traced, on one line; the zoom on a second.
void recordingHudContents(const RecordingSession& session, const DebuggerState& state);

/// The whole recording view in the screen rect at `origin` of size `size`.
RecordingActions recordingLayout(RecordingSession& session, RecordingViewState& state,
                                 ImVec2 origin, ImVec2 size);

}  // namespace tv::ui
