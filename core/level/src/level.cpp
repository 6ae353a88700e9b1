// A loaded level as a scene: its parameters, its build function (the file's solids and bodies,
// moved by `offset`) and its rules (its own, or a built-in scene's).
#include "tv/level/level.hpp"

#include <algorithm>
#include <cmath>

#include "level_rules.hpp"
#include "tv/error.hpp"

namespace tv::level {
namespace {

sim::ParamSpec spec(std::string_view name, std::string unit, std::string description, double value,
                    double min, double max, bool integer = false) {
  sim::ParamSpec s;
  s.name = std::string(name);
  s.unit = std::move(unit);
  s.description = std::move(description);
  s.value = value;
  s.min = min;
  s.max = max;
  s.integer = integer;
  return s;
}

/// Fixed at the file's value: the range is that one value, so setting another names it.
sim::ParamSpec pinned(std::string_view name, std::string unit, std::string description,
                      double value, bool integer = false) {
  return spec(name, std::move(unit), std::move(description) + " (fixed by the file)", value, value,
              value, integer);
}

Rect shifted(Rect r, double by) {
  r.x += by;
  r.y += by;
  return r;
}

double paramOr(const Level& level, std::string_view name, double fallback) {
  for (const auto& [n, v] : level.params) {
    if (n == name) return v;
  }
  return fallback;
}

/// The scene's parameters: the built-in scene's (all fixed but dt, substep, cell, offset) when
/// its rules steer, else the nine common ones.
std::vector<sim::ParamSpec> levelParams(const Level& level, const sim::SceneDef* builtin) {
  using namespace tv::sim;
  std::vector<ParamSpec> out;
  if (builtin) {
    for (const ParamSpec& s : builtin->params) {
      double v = s.value;
      bool found = false;
      for (const auto& [n, value] : level.params) {
        if (n == s.name) {
          v = value;
          found = true;
        }
      }
      if (!found) {
        fail(level.source, "params: missing \"" + s.name + "\" (scene " + builtin->name + " has " +
                               std::to_string(builtin->params.size()) + " parameters)");
      }
      try {
        Params::validate(s, v);
      } catch (const Error& e) {
        fail(level.source, "params." + s.name + ": " + e.what());
      }
      ParamSpec p = s;
      p.value = v;
      const bool free = s.name == param::dt || s.name == param::substep || s.name == param::cell ||
                        s.name == param::offset;
      if (!free) {
        p.min = p.max = v;
        p.minExclusive = false;
        p.description += " (fixed by the file)";
      }
      out.push_back(std::move(p));
    }
    for (const auto& [n, value] : level.params) {
      const bool known = std::any_of(builtin->params.begin(), builtin->params.end(),
                                     [&](const ParamSpec& s) { return s.name == n; });
      if (!known)
        fail(level.source, "params." + n + ": scene " + builtin->name + " has no such parameter");
    }
    return out;
  }
  double size = 0.0;
  for (const LevelBody& b : level.bodies) size = std::max({size, b.body.rect.w, b.body.rect.h});
  out.push_back(spec(param::speed, "px/s", "walkers' and players' speed unless they have their own",
                     level.speed, 0.0, 1e9));
  out.back().minExclusive = true;
  out.push_back(pinned(param::size, "px", "side of the largest body", size == 0.0 ? 1.0 : size));
  out.push_back(pinned(param::tile, "px", "the map's tile", level.tile));
  out.push_back(spec(param::dt, "s", "the fixed physics step", level.dt, 0.0, 1.0));
  out.back().minExclusive = true;
  out.push_back(
      spec(param::substep, "px", "substep movers' longest piece; 0 = tile / 2", 0.0, 0.0, 1e9));
  out.push_back(spec(param::offset, "px", "added to every coordinate", 0.0, -1e9, 1e9));
  out.push_back(pinned(param::count, "", "bodies in the level",
                       static_cast<double>(level.bodies.size()), true));
  out.push_back(pinned(param::seed, "", "unused: a level has no random layout", 0.0, true));
  out.push_back(
      spec(param::cell, "px", "the world's spatial-hash cell size", level.cell, 0.0, 1e6));
  out.back().minExclusive = true;
  return out;
}

/// A built-in scene's rules index their bodies by position and by `group` (a bullet's partner is
/// the next body, a shot's target tile is tiles[group]), so a file whose bodies differ from what
/// the rules were built for in number or in groups is refused, not run out of bounds.
void checkAgainstRules(const Level& level, const sim::SceneDef& builtin,
                       const sim::SceneSetup& built) {
  if (level.bodies.size() != built.bodies.size()) {
    fail(level.source, "bodies: the rules of " + builtin.name + " expect " +
                           std::to_string(built.bodies.size()) +
                           " bodies (from its parameters), but the file has " +
                           std::to_string(level.bodies.size()));
  }
  for (std::size_t i = 0; i < built.bodies.size(); ++i) {
    if (level.bodies[i].body.group != built.bodies[i].group) {
      fail(level.source, "bodies[" + std::to_string(i) + "].group: the rules of " + builtin.name +
                             " expect " + std::to_string(built.bodies[i].group) + ", but got " +
                             std::to_string(level.bodies[i].body.group));
    }
  }
}

}  // namespace

Rect bounds(const Level& level) {
  bool any = false;
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  const auto grow = [&](const Rect& r) {
    if (!any) {
      x0 = r.x, y0 = r.y, x1 = r.right(), y1 = r.bottom();
      any = true;
      return;
    }
    x0 = std::min(x0, r.x), y0 = std::min(y0, r.y);
    x1 = std::max(x1, r.right()), y1 = std::max(y1, r.bottom());
  };
  for (const sim::Solid& s : level.solids) grow(s.rect);
  for (const LevelBody& b : level.bodies) grow(b.body.rect);
  if (!any) return {0, 0, 320, 180};
  return {x0, y0, x1 - x0, y1 - y0};
}

sim::SceneDef makeScene(Level level) {
  const sim::SceneDef* builtin = nullptr;
  if (!level.rules.empty()) {
    builtin = sim::builtinScenes().tryFind(level.rules);
    if (!builtin) {
      std::string valid;
      for (const std::string_view n : sim::builtinScenes().names())
        valid += (valid.empty() ? "" : ", ") + std::string(n);
      fail(level.source,
           "rules: no built-in scene is named '" + level.rules + "'; valid: level, " + valid);
    }
  }
  sim::SceneDef def;
  def.category = "Files";
  def.name = level.name;
  def.description = level.description;
  def.params = levelParams(level, builtin);
  if (builtin) {
    // Counted by the same rules, so read the same way.
    def.missesFail = builtin->missesFail;
    def.missesWord = builtin->missesWord;
    def.tagNames = builtin->tagNames;
  } else {
    def.tagNames = {"solid", "tile", "object"};  // a tile layer's tiles, an object layer's rects
  }
  if (builtin) checkAgainstRules(level, *builtin, builtin->build(def.defaults()));
  const double fileOffset = builtin ? paramOr(level, sim::param::offset, 0.0) : 0.0;
  const Rect frame = level.camera.value_or(bounds(level));
  def.camera = [frame, fileOffset](const sim::Params& p) {
    return shifted(frame, p.get(sim::param::offset) - fileOffset);
  };
  // Levels are immutable once loaded and the build function may be copied (SceneDef is a value),
  // so the level is shared, not copied per build.
  auto shared = std::make_shared<const Level>(std::move(level));
  def.build = [shared, builtin, fileOffset](const sim::Params& p) {
    const Level& lv = *shared;
    const double by = p.get(sim::param::offset) - fileOffset;
    sim::SceneSetup s;
    if (builtin) {
      s = builtin->build(p);  // its rules, rebuilt from the same parameters
      checkAgainstRules(lv, *builtin, s);
    } else {
      s.cellSize = p.get(sim::param::cell);
      std::vector<detail::BodyRule> rules;
      rules.reserve(lv.bodies.size());
      double bottom = bounds(lv).bottom();
      for (const LevelBody& b : lv.bodies) {
        detail::BodyRule r;
        r.motion = b.motion;
        r.speed = b.speed.value_or(p.get(sim::param::speed));
        r.jump = b.jump;
        if (r.jump.speed == 0.0)
          r.jump.speed = std::sqrt(2.0 * std::max(lv.gravity.y, 0.0) * 3.5 * lv.tile);
        r.start = shifted(b.body.rect, by).position();
        rules.push_back(r);
      }
      s.rules = detail::makeLevelRules(std::move(rules), bottom + by + 4.0 * lv.tile);
    }
    s.cellSize = p.get(sim::param::cell);
    s.gravity = lv.gravity;
    s.solids.clear();
    s.solids.reserve(lv.solids.size());
    for (const sim::Solid& solid : lv.solids)
      s.solids.push_back({shifted(solid.rect, by), solid.tag, solid.oneWay});
    s.solidNames = lv.solidNames;
    s.bodyNames.clear();
    s.bodies.clear();
    s.bodies.reserve(lv.bodies.size());
    for (const LevelBody& b : lv.bodies) {
      s.bodyNames.push_back(b.name);
      sim::Body body = b.body;
      body.rect = shifted(body.rect, by);
      if (!builtin && (b.motion == Motion::walker || b.motion == Motion::player) && b.facingLeft)
        body.state |= 2;
      s.bodies.push_back(body);
    }
    return s;
  };
  return def;
}

}  // namespace tv::level
