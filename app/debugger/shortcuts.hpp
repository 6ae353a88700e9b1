#pragma once
// Every shortcut, in one table: the Help window lists it and the menus and buttons label
// themselves from it, so what the Help says and what the menus show never disagree — for every
// source (a scene, a level, a recording, a live game).

#include <span>

#include "imgui.h"

namespace tv::viewer {

enum class Command {
  pause,
  step,
  stepBack,
  stepForward,
  nextCall,
  previousCall,
  frameEnd,
  restart,
  slower,
  faster,
  frameAll,
  follow,
  compare,
  overlay,
  whatIf,
  sweep,
  items,
  failures,
  firstFailure,
  openScene,
  openRecording,
  previousScene,
  nextScene,
  help,
  quit,
};

struct Shortcut {
  Command command;
  const char* keys;  ///< as shown in menus, buttons and Help
  const char* what;
};

[[nodiscard]] std::span<const Shortcut> shortcuts();
/// The keys of `c`, e.g. "Ctrl+O".
[[nodiscard]] const char* keysOf(Command c);

/// The Help window: every shortcut and the mouse; placed at `pos`, `size` while `place` (the
/// column's tabs, which move when the panel above them grows), until the person moves or
/// resizes it. Returns whether it is still to be placed next frame.
bool drawHelp(bool* open, ImVec2 pos, ImVec2 size, bool place);

}  // namespace tv::viewer
