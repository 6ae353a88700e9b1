#pragma once
/// A what-if run drawn beside the recorded one: two world panels at the same frame and call
/// (recorded, re-run), one camera for both, and a side panel with the what-if report, the
/// frame's calls, the re-run's inspector and the outliner. The debugger draws it live while its
/// background job runs; `tv-render --open FILE --what-if MOVER` draws the same layout as a still,
/// so a game's CI gets the picture a person would look at.

#include <cstdint>
#include <optional>
#include <string>
#include <utility>

#include "imgui.h"
#include "tv/mover.hpp"
#include "tv/record/replay.hpp"
#include "tv/ui/panels.hpp"
#include "tv/ui/recording_session.hpp"
#include "tv/ui/recording_view.hpp"

namespace tv::ui {

/// The sentence every what-if view carries: the re-run replays the game's goals as recorded.
extern const char* const kOpenLoop;

/// "substep-discrete (8 px pieces)": the mover's name, and its piece length where it has one.
[[nodiscard]] std::string moverLabel(const MoverSpec& m);

/// The recorded run and its re-run, each a session kept at the same frame and call.
struct WhatIfPair {
  RecordingSession& recorded;
  RecordingViewState& recordedState;
  RecordingSession& whatIf;
  DebuggerState& whatIfView;
  MoverSpec mover;
  bool updatesAsMoves = false;
};

/// Where the whole-run report stands: done (report), still running, or failed (error).
struct WhatIfStatus {
  const WhatIfReport* report = nullptr;
  bool running = false;
  std::string error;
};

/// What the person asked for in the layout this frame.
struct WhatIfActions {
  RecordingActions recording;  ///< a call or an item picked (calls tab, outliner, a click)
  /// A report row or "go" button: show this frame, and this call of it.
  std::optional<std::pair<std::uint64_t, std::optional<std::uint32_t>>> goTo;
  bool cameraMoved = false;  ///< a zoom or pan in one panel, now applied to both
};

/// The whole what-if view in the screen rect at `origin` of size `size`.
WhatIfActions whatIfLayout(WhatIfPair& p, const WhatIfStatus& status, ImVec2 origin, ImVec2 size);

/// The first move of a what-if run that tunnelled or ended inside a solid, in recording order.
struct WhatIfFailure {
  std::uint64_t frame = 0;
  std::uint32_t call = 0;
  ItemId item;
  bool tunnelled = false;
};
[[nodiscard]] std::optional<WhatIfFailure> firstFailure(const WhatIfReport& report);

/// Runs the what-if of the recording at `path` to the end (in this thread): the report.
[[nodiscard]] WhatIfReport runWhatIf(const std::string& path, const MoverSpec& mover,
                                     bool updatesAsMoves, double farAway = 64.0);

}  // namespace tv::ui
