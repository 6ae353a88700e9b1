// The scene registry, the common parameters and the velocity responses.
#include <algorithm>

#include "scene_kit.hpp"
#include "tv/error.hpp"
#include "tv/sim/body.hpp"
#include "tv/sim/scene.hpp"

namespace tv::sim {

// [SECTION] velocity responses --------------------------------------------------------------------

Vec2 respondVelocity(Vec2 v, const Collision& c) {
  return velocityAfter(v, c);  // the response's own rule (kBuiltinResponses)
}

Vec2 respondVelocity(Vec2 v, std::span<const Collision> collisions) {
  for (const Collision& c : collisions) v = respondVelocity(v, c);
  return v;
}

// [SECTION] registry ------------------------------------------------------------------------------

namespace {
constexpr std::string_view kRegistry = "tv::sim::SceneRegistry";
constexpr std::string_view kCommon[] = {param::speed, param::size,    param::tile,
                                        param::dt,    param::substep, param::offset,
                                        param::count, param::seed,    param::cell};
}  // namespace

void SceneRegistry::add(SceneDef def) {
  if (def.name.empty()) fail(kRegistry, "a scene needs a name");
  if (tryFind(def.name)) fail(kRegistry, "a scene named '" + def.name + "' is already registered");
  if (!def.build || !def.camera) {
    fail(kRegistry, "scene '" + def.name + "' needs both a build and a camera function");
  }
  for (const std::string_view common : kCommon) {
    const bool found = std::any_of(def.params.begin(), def.params.end(),
                                   [&](const ParamSpec& s) { return s.name == common; });
    if (!found) {
      fail(kRegistry,
           "scene '" + def.name + "' lacks the common parameter '" + std::string(common) + "'");
    }
  }
  (void)def.defaults();  // throws on duplicate names or defaults out of their own range
  scenes_.push_back(std::move(def));
}

const SceneDef* SceneRegistry::tryFind(std::string_view name) const {
  for (const SceneDef& s : scenes_) {
    if (s.name == name) return &s;
  }
  return nullptr;
}

const SceneDef& SceneRegistry::find(std::string_view name) const {
  if (const SceneDef* s = tryFind(name)) return *s;
  std::string valid;
  for (const SceneDef& s : scenes_) valid += (valid.empty() ? "" : ", ") + s.name;
  fail("tv::sim::findScene", "no scene is named '" + std::string(name) + "'; valid: " + valid);
}

std::vector<std::string_view> SceneRegistry::names() const {
  std::vector<std::string_view> out;
  out.reserve(scenes_.size());
  for (const SceneDef& s : scenes_) out.push_back(s.name);
  return out;
}

const SceneRegistry& builtinScenes() {
  // Built once, on first use, then only read: no mutable global state.
  static const SceneRegistry registry = [] {
    SceneRegistry r;
    detail::registerProjectileScenes(r);
    detail::registerRestingScenes(r);
    detail::registerGameScenes(r);
    detail::registerPlatformScenes(r);
    return r;
  }();
  return registry;
}

const SceneDef& findScene(std::string_view name) {
  return builtinScenes().find(name);
}

// [SECTION] scene kit -----------------------------------------------------------------------------

namespace detail {

ParamSpec realParam(std::string name, std::string unit, std::string description, double value,
                    double min, double max, bool minExclusive) {
  return {std::move(name),
          std::move(unit),
          std::move(description),
          value,
          min,
          max,
          minExclusive,
          false};
}

ParamSpec intParam(std::string name, std::string description, double value, double min,
                   double max) {
  return {std::move(name), "", std::move(description), value, min, max, false, true};
}

std::vector<ParamSpec> commonParams(const CommonDefaults& d) {
  return {
      realParam(std::string(param::speed), "px/s", d.speedMeaning, d.speed, 0.0, 1e9, true),
      realParam(std::string(param::size), "px", d.sizeMeaning, d.size, 0.0, 1e4, true),
      realParam(std::string(param::tile), "px", "side of a solid tile", d.tile, 0.0, 1e4, true),
      realParam(std::string(param::dt), "s", "the fixed physics step", d.dt, 0.0, 1.0, true),
      realParam(std::string(param::substep), "px", "substep movers' longest piece; 0 = tile / 2",
                0.0, 0.0, 1e9, false),
      realParam(std::string(param::offset), "px",
                "added to every coordinate (precision far from the origin)", d.offset, -1e9, 1e9,
                false),
      intParam(std::string(param::count), d.countMeaning, d.count, 1.0, d.maxCount),
      intParam(std::string(param::seed), "seeds random phases and layouts", d.seed, 0.0,
               9007199254740992.0),
      realParam(std::string(param::cell), "px", "the world's spatial-hash cell size", d.cell, 0.0,
                1e6, true),
  };
}

Common readCommon(const Params& p) {
  return {p.get(param::speed),
          p.get(param::size),
          p.get(param::tile),
          p.get(param::dt),
          p.get(param::substep),
          p.get(param::offset),
          p.get(param::cell),
          p.getInt(param::count),
          static_cast<std::uint64_t>(p.getInt(param::seed))};
}

void sceneFail(std::string_view scene, const std::string& what) {
  fail("tv::sim::Scene '" + std::string(scene) + "'", what);
}

Body makeBody(Rect r, BodyRole role, std::uint32_t layer, std::uint32_t mask, ResponseId response,
              Vec2 velocity, std::uint32_t group) {
  Body b;
  b.rect = r;
  b.role = role;
  b.layer = layer;
  b.mask = mask;
  b.response = response;
  b.velocity = velocity;
  b.group = group;
  return b;
}

}  // namespace detail
}  // namespace tv::sim
