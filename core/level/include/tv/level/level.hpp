#pragma once
/// A level: solids and bodies loaded from a scene file or a Tiled map, turned into an ordinary
/// scene (`tv::sim::SceneDef`) that every tool runs like a built-in one.
///
/// Bodies move by one of four motions (steered by the level's own rules), or, in a file exported
/// from a built-in scene, by that scene's rules (`rules` names it), so the export runs exactly
/// like the original.

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "tv/geometry.hpp"
#include "tv/sim/body.hpp"
#include "tv/sim/scene.hpp"

namespace tv::level {

/// How a level's body moves (ignored when a built-in scene's rules steer).
enum class Motion : std::uint8_t {
  fly,     ///< keeps its velocity; responds as its `response` says (gravity if it falls)
  bullet,  ///< flies until its first solid, then stops; counts hits and tunnelling
  walker,  ///< walks at `speed`, turns round at walls; falls
  player,  ///< a walker that also jumps on a script, and respawns when it falls out
};

/// A player's jumps: whenever grounded on ticks where (tick + phase) % every == 0.
struct JumpScript {
  std::int64_t every = 45;  ///< ticks, >= 1
  std::int64_t phase = 0;   ///< ticks, >= 0
  double speed = 0.0;       ///< px/s upwards at take-off; 0: enough to clear 3.5 tiles
};

/// One moving body of a level: the simulation's body and how the level's rules steer it.
struct LevelBody {
  sim::Body body;  ///< rect, velocity, response, role, layer, mask, group, state, falls, active
  Motion motion = Motion::fly;  ///< how it moves (default: keeps its velocity)
  /// px/s, walkers and players; nullopt: the scene's `speed` parameter.
  std::optional<double> speed;
  bool facingLeft = false;  ///< walkers and players: start walking left
  JumpScript jump;          ///< players only
  std::string name;         ///< what the tools call it (a map object's name); empty: "body N"
};

/// A level as loaded from a file (parseTiledMap, parseSceneFile...), before it is a scene.
struct Level {
  std::string name;            ///< shown in the tools (the file's stem unless the file names it)
  std::string description;     ///< one line
  std::string source;          ///< the file it came from, for messages
  double cell = 64.0;          ///< the world's spatial-hash cell, px
  double dt = 1.0 / 60.0;      ///< the fixed step, s
  double tile = 16.0;          ///< px: the substep movers' default piece is tile / 2
  double speed = 150.0;        ///< px/s: walkers and players with no speed of their own
  Vec2 gravity;                ///< px/s², for bodies that fall
  std::optional<Rect> camera;  ///< what to frame; nullopt: everything in the level
  std::optional<std::string> mover;  ///< the mover the file suggests, if any
  std::vector<sim::Solid> solids;  ///< static solids, added to the world first, in order
  /// What the tools call each solid (a map object's name), by index; missing or empty:
  /// unnamed ("tile 12").
  std::vector<std::string> solidNames;
  std::vector<LevelBody> bodies;  ///< moving bodies, added after the solids, in order
  /// A built-in scene whose rules steer and count (a file exported by tv-run --export-scene),
  /// and the values of all its parameters; empty: the level's own rules (the motions above).
  std::string rules;
  std::vector<std::pair<std::string, double>> params;  ///< name and value, with `rules` only
  /// What the loader wants the user to know (e.g. "nothing is collidable"); never errors.
  std::vector<std::string> notes;
};

/// Solids and bodies, merged: the bounding box of everything (camera default). Empty levels
/// give {0, 0, 320, 180}.
[[nodiscard]] Rect bounds(const Level& level);

/// The level as a scene. Its parameters: `dt`, `substep`, `cell` and `offset` (which moves
/// everything) can be changed like a built-in scene's; `speed` sets walkers' and players'
/// default speed (own rules only); the others are fixed at the file's values. Throws tv::Error
/// naming the file when the level cannot run (an unknown built-in rule set, parameters that do
/// not match it).
[[nodiscard]] sim::SceneDef makeScene(Level level);

}  // namespace tv::level
