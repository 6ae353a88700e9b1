#pragma once
/// The panels, as widget contents: the view (view.hpp) decides where each one goes. Panels read
/// the session's sources; none changes anything: they return what was asked, so a caller
/// decides when a restart, a seek or a new trace happens.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>

#include "tv/sim/params.hpp"
#include "tv/sim/scene.hpp"
#include "tv/ui/camera.hpp"
#include "tv/ui/overlays.hpp"
#include "tv/ui/palette.hpp"
#include "tv/ui/source.hpp"

namespace tv::ui {

class Session;
class SimSource;

/// What the person is looking at in one panel, and how.
struct DebuggerState {
  Overlays overlays;
  Camera camera;
  /// The world rect to frame every frame (a still, "frame" pressed, follow); none: the camera
  /// keeps whatever the person zoomed and panned to.
  std::optional<Rect> frameView;
  /// Set by the world view when a wheel zoom or a right drag moved the camera this frame; the
  /// view copies that camera to its other panels and clears it.
  bool cameraMoved = false;
  /// Screen pixels at the top and bottom of the world view that the HUD and the legend covered
  /// in the last frame: framing keeps the action clear of them.
  float coveredTop = 0.0f;
  float coveredBottom = 0.0f;
  bool paused = true;
  /// Edited copies of a tunable source's settings, applied by a restart (panel 0's only).
  sim::Params draft;
  std::string draftScene;
  MoverSpec draftMover;
  double renderHz = 0.0;  ///< the render rate being edited (applied at once)
  std::string error;      ///< the last rejected edit, shown in red until the next one
  /// How long the last re-run to the current tick took (wall ms, set by the debugger): sliders
  /// re-run live while it is under kLiveRerunMs, else on release.
  double lastRerunMs = 1e9;
};

/// Re-runs quicker than this follow a slider live.
inline constexpr double kLiveRerunMs = 30.0;

/// The tabs of the column beside the world.
enum class Tab { inspector, calls, items, failures, counters };

/// What the person asked for this frame.
struct Actions {
  bool restart = false;   ///< from tick 0, with what the panel holds
  bool apply = false;     ///< apply the draft scene, parameters and mover, at the same tick
  bool step = false;      ///< one frame forward
  bool stepBack = false;  ///< one frame back
  bool togglePause = false;
  std::optional<std::optional<ItemId>> item;         ///< trace another item (or none)
  std::optional<std::optional<std::uint32_t>> call;  ///< select a call (or the frame's end)
  std::optional<std::size_t> inspect;                ///< show this panel's inspector
  std::optional<std::size_t> failure;                ///< go to this failure (its index)
  /// Merges what `other` asked for into this.
  void add(const Actions& other);
};

/// The failures found so far, per panel, for the Failures tab and the timeline.
struct FailureList {
  struct Entry {
    std::size_t panel = 0;  ///< which panel's run (mover) failed
    Failure failure;
  };
  std::vector<Entry> entries;  ///< in frame order within each panel
  bool complete = false;       ///< the whole run has been looked at
  std::uint64_t looked = 0;    ///< frames looked at so far
  std::string note;            ///< why there is none ("the debugger lists them", an error)
  /// Per panel, the whole run's figures in a line (a what-if run's report: moves re-run, how
  /// many ended elsewhere, where the runs part); empty where there is none.
  std::vector<std::string> summary;
};

/// Fills the draft from a tunable source (call once, and after every restart).
void syncDraft(DebuggerState& state, const SimSource& source);

/// Scene, mover, parameters (velocity, dt, tile size, cell size, max substep length...), render
/// rate, traced body, overlay toggles; each control shows its shortcut.
Actions controlsContents(const SimSource& source, DebuggerState& state);
/// The traced item and its last moves, or the selected call: what happened in words, cells,
/// candidates with the filter's answers, legs, substeps, and each hit's other, ti, normal, touch
/// and response. `failures` (may be null) gives the words for moves that failed.
void inspectorContents(const Source& source, const FailureList* failures, std::size_t panel);
/// One line per call of the frame, selectable; `reveal` scrolls to the selected call once.
void callsContents(const Source& source, bool& reveal, Actions& actions);
/// What the outliner keeps between frames.
struct OutlinerState {
  std::string filter;
  bool movingOnly = false;
  bool focus = false;  ///< give the search field the keyboard once (I)
};
/// The items by name and category, filtered by the search; click to trace one.
void itemsContents(const Source& source, OutlinerState& state, Actions& actions);
/// Every failure found, per panel (mover): frame, item, what happened; a click goes there. The
/// row `shown` (the failure last gone to) is marked, and scrolled to once when `reveal` is set
/// (cleared here).
void failuresContents(std::span<Source* const> panels, const FailureList& failures,
                      std::optional<std::size_t> shown, bool& reveal, Actions& actions);
/// Tunnelled so far and the scene's other counters, candidates and cells per move.
void countersContents(const SimSource& source);
/// Name, mover, frame and call, and paused, on one line; the timing and zoom on a second; a
/// scene's verdict on a third; the source's notes after.
void hudContents(const Source& source, const DebuggerState& state);
/// Every palette entry with its swatch that `scope` shows, in `columns` columns.
void legendContents(int columns, palette::LegendScope scope);
/// How many legend columns fit in `width` px with every label whole (1..8).
[[nodiscard]] int legendColumns(float width, palette::LegendScope scope);
/// What a view of `source` can draw: a recording's categories, a scene's moving solids and
/// one-way sides.
[[nodiscard]] palette::LegendScope legendScopeOf(const Source& source);

/// "tick" for a scene (its frames are ticks), "frame" otherwise.
[[nodiscard]] const char* frameWord(const Source& source);

}  // namespace tv::ui
