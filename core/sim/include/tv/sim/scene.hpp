#pragma once
/// Scenes: registered once (category, name, one-line description, default camera, parameters
/// with defaults) and shared by the viewer, the headless renderer, tv-run, the tests and the
/// benchmarks, so that all of them run the same thing.
///
/// A scene is data plus rules. Building it (from its parameters) yields the solids, the bodies
/// and a `SceneRules` object; the Simulation moves the bodies and asks the rules what to steer
/// and what to count. Rules keep no state of their own: everything that changes lives in the
/// bodies and the counters, so that a snapshot of those restores the scene exactly.

#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "tv/geometry.hpp"
#include "tv/response.hpp"
#include "tv/sim/body.hpp"
#include "tv/sim/params.hpp"

namespace tv {
class World;
}

namespace tv::sim {

/// A solid of the scene (a tile, a wall piece). `tag` is scene-defined (e.g. floor vs wall).
struct Solid {
  Rect rect;             ///< where it is, px
  std::uint8_t tag = 0;  ///< scene-defined kind (0 by default)
  /// Solid from above only (a jump-through platform): a body meets it only if it was entirely
  /// above it when its move began.
  bool oneWay = false;
};

class SceneRules;

/// What building a scene produces.
struct SceneSetup {
  double cellSize = 64.0;     ///< the world's spatial-hash cell, px
  std::vector<Solid> solids;  ///< added to the world first, in this order
  std::vector<Body> bodies;   ///< then these (their `item` is filled in by the simulation)
  Vec2 gravity;               ///< px/s², applied to bodies with `falls`
  std::shared_ptr<const SceneRules> rules;  ///< null: plain movement, nothing counted
  /// What the tools call each solid (a map object's name), by index; empty or missing entries
  /// are unnamed ("wall tile 12").
  std::vector<std::string> solidNames;
  /// What the tools call each body, by index, as `solidNames`; unnamed: "body 3".
  std::vector<std::string> bodyNames;
};

/// What the rules may see and change during a tick.
struct TickContext {
  std::span<Body> bodies;  ///< every body, in the scene's order (the rules may change them)
  Counters& counters;      ///< what the scene counts (the rules add to them)
  const World& world;      ///< the world after this tick's moves
  std::uint64_t tick = 0;                    ///< the tick being run: 0 for the first
  double dt = 0.0;                           ///< its length, s
  std::span<const Vec2> previous;            ///< every body's position before this tick
  std::span<const std::int32_t> bodyBySlot;  ///< world slot -> body index, or -1 for a solid
  std::span<const std::uint8_t> tagBySlot;   ///< world slot -> the solid's tag (0 for bodies)
  std::span<const std::uint8_t> oneWayBySlot;  ///< world slot -> 1 for a one-way solid
  /// Where count() names the bodies it counts for (the simulation's events); null: it only
  /// counts.
  std::vector<TickEvent>* named = nullptr;

  /// Raises the counter of `what` by one for body `i`, naming it (and `other`, what it failed
  /// against, if known), so the tools list the failure as that body's. Rules that count after
  /// every body moved (afterTick) use it instead of raising a counter themselves, which the
  /// tools can tie to no body. Counted::manyCollisions is not a counter: it is ignored.
  void count(Counted what, std::size_t i, ItemId other = {});

  /// Index of the body whose item this is, or -1 (a solid).
  [[nodiscard]] std::int32_t bodyOf(ItemId id) const {
    return id.index < bodyBySlot.size() ? bodyBySlot[id.index] : -1;
  }
  /// True for a one-way solid (Solid::oneWay) of the scene.
  [[nodiscard]] bool isOneWay(ItemId id) const {
    return id.index < oneWayBySlot.size() && oneWayBySlot[id.index] != 0;
  }
  /// Tag of the solid this is (0 for bodies and unknown items).
  [[nodiscard]] std::uint8_t tagOf(ItemId id) const {
    return id.index < tagBySlot.size() ? tagBySlot[id.index] : std::uint8_t{0};
  }
};

/// A scene's behaviour. Every hook is const: rules read their constant data (wall rects, slot
/// boxes) from themselves and keep everything that changes in the bodies and counters. A hook
/// may teleport a body (a respawn) by writing its `rect`; the simulation moves the world's item
/// to match after the hook returns.
class SceneRules {
 public:
  virtual ~SceneRules() = default;
  /// Before any body moves this tick: steer (set velocities from input or a script).
  virtual void control(TickContext& /*ctx*/) const {}
  /// After body `i` moved towards `goal`, with the collisions its move reported.
  virtual void afterMove(TickContext& /*ctx*/, std::size_t /*i*/, Vec2 /*goal*/,
                         std::span<const Collision> /*collisions*/) const {}
  /// After every body moved.
  virtual void afterTick(TickContext& /*ctx*/) const {}
  /// True when nothing more can happen (every bullet resolved); tv-run stops there.
  [[nodiscard]] virtual bool finished(std::span<const Body> /*bodies*/) const { return false; }
  /// True when this tick's moves go through one tv::Batch (moving versus moving) instead of
  /// the chosen mover, one body at a time.
  [[nodiscard]] virtual bool batched() const { return false; }
};

/// A registered scene.
struct SceneDef {
  std::string category;           ///< "Tunnelling", "Resting", "Games"...
  std::string name;               ///< unique, lower-case-with-dashes
  std::string description;        ///< one line
  /// How the tools read its `misses` counter: true when a miss is a failure (a shot and a target
  /// that should have met did not), false when it is an expected near thing (an exact graze),
  /// which the tools call `missesWord` and never count against a mover.
  bool missesFail = false;
  std::string missesWord = "misses";  ///< the tools' word for the counter ("grazes")
  /// What the tools call a solid of each tag (index = tag; "floor tile", "wall tile"); a tag
  /// past the end is a "solid".
  std::vector<std::string> tagNames;
  std::vector<ParamSpec> params;  ///< every common parameter (see `param::`) plus its own
  /// The world rect to frame, for given parameters (cheap: does not build the scene).
  std::function<Rect(const Params&)> camera;
  /// Builds the scene. Throws tv::Error naming the parameter if a combination of values is
  /// impossible (e.g. movers larger than the tiles they must fit between).
  std::function<SceneSetup(const Params&)> build;

  /// Parameters at their defaults.
  [[nodiscard]] Params defaults() const { return Params(params); }
  /// The camera at the default parameters.
  [[nodiscard]] Rect defaultCamera() const { return camera(defaults()); }
};

/// A set of scenes by name (the built-in ones: builtinScenes()).
class SceneRegistry {
 public:
  /// Registers a scene. Throws tv::Error on an empty or duplicate name, missing functions, or
  /// parameters that lack one of the common ones.
  void add(SceneDef def);
  /// The scene named `name`; throws tv::Error naming it and listing the valid names otherwise.
  [[nodiscard]] const SceneDef& find(std::string_view name) const;
  /// Null when there is no such scene.
  [[nodiscard]] const SceneDef* tryFind(std::string_view name) const;
  /// In registration order.
  [[nodiscard]] std::span<const SceneDef> all() const { return scenes_; }
  /// Their names, in registration order.
  [[nodiscard]] std::vector<std::string_view> names() const;

 private:
  std::vector<SceneDef> scenes_;
};

/// The built-in scenes (bullets-wall, rest-wall, rest-floor, seam-walk, corner-graze,
/// bounce-gap, bullets-enemies, platformer, crowd, bump-crowd, one-way-rise, lift-crush,
/// corner-nudge). Built on first use, immutable after.
[[nodiscard]] const SceneRegistry& builtinScenes();
/// `builtinScenes().find(name)`.
[[nodiscard]] const SceneDef& findScene(std::string_view name);

}  // namespace tv::sim
