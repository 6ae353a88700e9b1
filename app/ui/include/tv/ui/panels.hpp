#pragma once
/// The panels, as widget contents: a layout (see layout.hpp) decides where each one goes.
/// Panels read the session; only the controls change anything, and they do it by returning
/// what was asked, so a caller decides when a restart happens.

#include <optional>
#include <string>

#include "tv/sim/params.hpp"
#include "tv/sim/scene.hpp"
#include "tv/ui/camera.hpp"
#include "tv/ui/overlays.hpp"
#include "tv/ui/session.hpp"

namespace tv::ui {

/// What the person is looking at and how; the viewer keeps one, the headless renderer fills one.
struct DebuggerState {
  Overlays overlays;
  Camera camera;
  /// The world rect to frame every frame (headless, or "frame" pressed); none: the camera
  /// keeps whatever the person zoomed and panned to.
  std::optional<Rect> frameView;
  /// Set by the world view when a wheel zoom or a right drag moved the camera this frame; the
  /// comparison copies that camera to its other panels and clears it.
  bool cameraMoved = false;
  /// Screen pixels at the top and bottom of the world view that the HUD and the legend covered
  /// in the last frame: framing keeps the action clear of them.
  float coveredTop = 0.0f;
  float coveredBottom = 0.0f;
  bool paused = true;
  /// Frames per second the picture is drawn at; physics keeps its own dt. 0: one frame per tick.
  double renderHz = 144.0;
  /// Edited copies, applied by a restart.
  sim::Params draft;
  std::string draftScene;
  MoverSpec draftMover;
  std::string error;  ///< the last rejected edit, shown in red until the next one
  /// How long the last re-run to the current tick took (wall ms, set by the viewer): sliders
  /// re-run live while it is under kLiveRerunMs, else on release.
  double lastRerunMs = 1e9;
};

/// Re-runs quicker than this follow a slider live.
inline constexpr double kLiveRerunMs = 30.0;

/// What the controls asked for this frame.
struct Actions {
  bool restart = false;   ///< apply the draft scene, parameters and mover from tick 0
  bool step = false;      ///< one tick
  bool stepBack = false;  ///< one tick back
  bool togglePause = false;
  std::optional<std::size_t> select;  ///< follow another body
};

/// Fills the draft from the session (call once, and after every restart).
void syncDraft(DebuggerState& state, const Session& session);

/// Scene, mover, parameters (velocity, dt, tile size, cell size, max substep length...), render
/// rate, traced body, overlay toggles; each control shows its shortcut.
Actions controlsContents(const Session& session, DebuggerState& state);
/// The selected body and its last moves: cells, candidates, legs, and each hit's other, ti,
/// normal, touch and response.
void inspectorContents(const Session& session);
/// Tunnelled so far and the scene's other counters, candidates and cells per move.
void countersContents(const Session& session);
/// One line of scene, mover, tick and paused; a second with the timing.
void hudContents(const Session& session, const DebuggerState& state);
/// Every palette entry with its swatch, in `columns` columns (palette::legend(withCategories)).
void legendContents(int columns, bool withCategories = false);

}  // namespace tv::ui
