// Scene files: reading (strict, every error with its JSON path), writing, and exporting a
// built-in scene.
//
// Index: [SECTION] names · [SECTION] reading · [SECTION] writing · [SECTION] exporting
#include "tv/level/scene_file.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <initializer_list>

#include "file_text.hpp"
#include "json_reader.hpp"
#include "tv/error.hpp"
#include "tv/mover.hpp"

namespace tv::level {
namespace {

using detail::Json;
using detail::JsonAt;

constexpr std::string_view kFormat = "tunnelvision-scene";
constexpr std::int64_t kVersion = 1;
constexpr std::int64_t kMaxItems = 1'000'000;  // solids or bodies: far above any real level

// [SECTION] names ---------------------------------------------------------------------------------

constexpr std::array<std::pair<std::string_view, Motion>, 4> kMotions = {
    {{"fly", Motion::fly},
     {"bullet", Motion::bullet},
     {"walker", Motion::walker},
     {"player", Motion::player}}};
constexpr std::array<std::pair<std::string_view, sim::BodyRole>, 7> kRoles = {
    {{"projectile", sim::BodyRole::projectile},
     {"enemy", sim::BodyRole::enemy},
     {"ball", sim::BodyRole::ball},
     {"walker", sim::BodyRole::walker},
     {"player", sim::BodyRole::player},
     {"crowd", sim::BodyRole::crowd},
     {"block", sim::BodyRole::block}}};
// The built-in responses by name, from the one table of them (tv/response.hpp).
constexpr auto kResponses = [] {
  std::array<std::pair<std::string_view, ResponseId>, response::kBuiltinCount> a{};
  for (ResponseId i = 0; i < response::kBuiltinCount; ++i) a[i] = {kBuiltinResponses[i].name, i};
  return a;
}();

template <class T, std::size_t N>
T byName(const std::array<std::pair<std::string_view, T>, N>& names, const JsonAt& at,
         std::string_view what) {
  const std::string& s = at.string();
  std::string valid;
  for (const auto& [n, v] : names) {
    if (n == s) return v;
    valid += (valid.empty() ? "" : ", ") + std::string(n);
  }
  at.fail("expected a " + std::string(what) + " (" + valid + ")");
}

template <class T, std::size_t N>
std::string_view nameOf(const std::array<std::pair<std::string_view, T>, N>& names, T value) {
  for (const auto& [n, v] : names) {
    if (v == value) return n;
  }
  return "?";
}

void onlyKeys(const JsonAt& at, std::initializer_list<std::string_view> keys) {
  if (!at.isObject()) at.fail("expected an object");
  for (const auto& [key, value] : at.json().items()) {
    if (std::find(keys.begin(), keys.end(), key) == keys.end()) {
      std::string valid;
      for (const std::string_view k : keys) valid += (valid.empty() ? "" : ", ") + std::string(k);
      JsonAt(value, at.path().empty() ? key : at.path() + "." + key, at.file())
          .failPlain("unknown key \"" + key + "\" (valid: " + valid + ")");
    }
  }
}

// [SECTION] reading -------------------------------------------------------------------------------

std::uint32_t bits(const JsonAt& at) {
  return static_cast<std::uint32_t>(at.whole(0, 0xFFFFFFFFll));
}

LevelBody readBody(const JsonAt& at) {
  onlyKeys(at, {"rect", "motion", "velocity", "speed", "direction", "jump", "falls", "response",
                "role", "layer", "mask", "group", "state", "active", "solid", "oneWay",
                "maxNudge", "contacts"});
  LevelBody lb;
  sim::Body& b = lb.body;
  b.rect = at["rect"].rect();
  if (auto m = at.find("motion")) lb.motion = byName(kMotions, *m, "motion");
  const bool walks = lb.motion == Motion::walker || lb.motion == Motion::player;
  // Defaults by motion, so a hand-written body needs only its rect and motion.
  switch (lb.motion) {
    case Motion::bullet:
      b.role = sim::BodyRole::projectile, b.layer = sim::kLayerProjectile,
      b.response = response::touch;
      break;
    case Motion::walker:
      b.role = sim::BodyRole::walker, b.layer = sim::kLayerEnemy;
      break;
    case Motion::player:
      b.role = sim::BodyRole::player, b.layer = sim::kLayerPlayer;
      break;
    case Motion::fly:
      break;
  }
  b.falls = walks;
  if (auto v = at.find("velocity")) {
    b.velocity = v->vec2();
    if (std::abs(b.velocity.x) > 1e9 || std::abs(b.velocity.y) > 1e9)
      v->fail("expected a velocity within ±1e9 px/s");
  }
  if (auto v = at.find("speed")) {
    if (!walks)
      v->failPlain("\"speed\" is for walkers and players (a fly or bullet has a velocity)");
    lb.speed = v->positive();
  }
  if (auto v = at.find("direction")) {
    if (!walks) v->failPlain("\"direction\" is for walkers and players");
    const std::string& d = v->string();
    if (d != "left" && d != "right") v->fail("expected \"left\" or \"right\"");
    lb.facingLeft = d == "left";
  }
  if (auto v = at.find("jump")) {
    if (lb.motion != Motion::player) v->failPlain("\"jump\" is for players");
    onlyKeys(*v, {"every", "phase", "speed"});
    if (auto e = v->find("every")) lb.jump.every = e->whole(1, 1'000'000);
    if (auto e = v->find("phase")) lb.jump.phase = e->whole(0, 1'000'000);
    if (auto e = v->find("speed")) lb.jump.speed = e->positive();
  }
  if (auto v = at.find("falls")) b.falls = v->boolean();
  if (auto v = at.find("response")) b.response = byName(kResponses, *v, "response");
  if (auto v = at.find("role")) b.role = byName(kRoles, *v, "role");
  if (auto v = at.find("solid")) b.solid = v->boolean();
  if (auto v = at.find("oneWay")) b.oneWay = v->boolean();
  if (auto v = at.find("maxNudge")) b.maxNudge = v->number(0.0, 1e9);  // corner correction
  if (auto v = at.find("contacts")) b.contacts = v->boolean();
  if (auto v = at.find("layer")) b.layer = bits(*v);
  if (auto v = at.find("mask")) b.mask = bits(*v);
  if (auto v = at.find("group")) b.group = bits(*v);
  if (auto v = at.find("state")) {
    b.state = static_cast<std::int32_t>(v->whole(-2147483648ll, 2147483647ll));
  }
  if (auto v = at.find("active")) b.active = v->boolean();
  return lb;
}

sim::Solid readSolid(const JsonAt& at) {
  if (at.isArray()) return {at.rect(), 0};
  onlyKeys(at, {"rect", "tag", "oneWay"});
  sim::Solid s{at["rect"].rect(), 0};
  if (auto t = at.find("tag")) s.tag = static_cast<std::uint8_t>(t->whole(0, 255));
  if (auto v = at.find("oneWay")) s.oneWay = v->boolean();
  return s;
}

Level readLevel(const JsonAt& root, std::string_view file) {
  onlyKeys(root, {"format", "version", "name", "description", "mover", "dt", "cell", "tile",
                  "speed", "gravity", "camera", "rules", "params", "solids", "bodies"});
  if (root["format"].string() != kFormat) root["format"].fail("expected \"tunnelvision-scene\"");
  const std::int64_t version = root["version"].whole(1, 1'000'000);
  if (version > kVersion) {
    root["version"].failPlain("version " + std::to_string(version) +
                              " is newer than this build reads (" + std::to_string(kVersion) + ")");
  }
  Level lv;
  lv.source = std::string(file);
  lv.name = std::filesystem::path(file).stem().string();
  if (auto v = root.find("name")) {
    lv.name = v->string();
    if (lv.name.empty() || lv.name.size() > 100) v->fail("expected a name of 1 to 100 characters");
  }
  if (auto v = root.find("description")) lv.description = v->string();
  if (lv.description.empty()) lv.description = "scene file " + std::string(file);
  if (auto v = root.find("mover")) {
    try {
      (void)parseMover(v->string());
    } catch (const Error& e) {
      v->fail(std::string("expected a mover: ") + e.what());
    }
    lv.mover = v->string();
  }
  if (auto v = root.find("dt")) lv.dt = v->positive(1.0);
  if (auto v = root.find("cell")) lv.cell = v->positive(1e6);
  if (auto v = root.find("tile")) lv.tile = v->positive(1e4);
  if (auto v = root.find("speed")) lv.speed = v->positive();
  if (auto v = root.find("gravity")) {
    lv.gravity = v->vec2();
    if (std::abs(lv.gravity.x) > 1e7 || std::abs(lv.gravity.y) > 1e7)
      v->fail("expected a gravity within ±1e7 px/s²");
  }
  if (auto v = root.find("camera")) lv.camera = v->rect();
  if (auto v = root.find("rules")) {
    lv.rules = v->string();
    if (lv.rules == "level") lv.rules.clear();
  }
  if (auto v = root.find("params")) {
    if (lv.rules.empty())
      v->failPlain("\"params\" go with the rules of a built-in scene (\"rules\")");
    if (!v->isObject()) v->fail("expected an object of parameter values");
    for (const auto& [key, value] : v->json().items()) {
      lv.params.emplace_back(key, JsonAt(value, v->path() + "." + key, v->file()).number());
    }
  }
  if (auto v = root.find("solids")) {
    const std::size_t n = v->size();
    if (n > static_cast<std::size_t>(kMaxItems)) v->failPlain("more than 1000000 solids");
    lv.solids.reserve(n);  // bounded by the document, which is already in memory
    for (std::size_t i = 0; i < n; ++i) lv.solids.push_back(readSolid(v->at(i)));
  }
  if (auto v = root.find("bodies")) {
    const std::size_t n = v->size();
    if (n > static_cast<std::size_t>(kMaxItems)) v->failPlain("more than 1000000 bodies");
    lv.bodies.reserve(n);
    for (std::size_t i = 0; i < n; ++i) lv.bodies.push_back(readBody(v->at(i)));
  }
  return lv;
}

// [SECTION] writing -------------------------------------------------------------------------------

Json rectJson(const Rect& r) {
  return Json::array({r.x, r.y, r.w, r.h});
}

Json bodyJson(const LevelBody& lb) {
  const sim::Body& b = lb.body;
  Json j = Json::object();
  j["rect"] = rectJson(b.rect);
  j["motion"] = nameOf(kMotions, lb.motion);
  j["velocity"] = Json::array({b.velocity.x, b.velocity.y});
  if (lb.speed) j["speed"] = *lb.speed;
  if (lb.motion == Motion::walker || lb.motion == Motion::player)
    j["direction"] = lb.facingLeft ? "left" : "right";
  if (lb.motion == Motion::player) {
    Json jump = {{"every", lb.jump.every}, {"phase", lb.jump.phase}};
    if (lb.jump.speed > 0.0) jump["speed"] = lb.jump.speed;
    j["jump"] = jump;
  }
  j["falls"] = b.falls;
  j["response"] = nameOf(kResponses, b.response);
  j["role"] = nameOf(kRoles, b.role);
  j["layer"] = b.layer;
  j["mask"] = b.mask;
  j["group"] = b.group;
  j["state"] = b.state;
  j["active"] = b.active;
  // Written only when set, so that files of levels without them read as they always did.
  if (b.solid) j["solid"] = true;
  if (b.oneWay) j["oneWay"] = true;
  if (b.maxNudge > 0.0) j["maxNudge"] = b.maxNudge;
  if (b.contacts) j["contacts"] = true;
  return j;
}

}  // namespace

Level parseSceneFile(std::string_view text, std::string_view file) {
  const std::string name(file);
  const Json doc = detail::parseJson(text, name);
  return readLevel(JsonAt(doc, "", name), name);
}

Level loadSceneFile(const std::filesystem::path& path) {
  return parseSceneFile(detail::readFileText(path), path.string());
}

std::string writeSceneFile(const Level& lv) {
  // One solid or body per line: diffs of a level stay readable, and the file stays small.
  std::string out = "{\n";
  const auto field = [&out](std::string_view key, const Json& value) {
    out += "  \"" + std::string(key) + "\": " + value.dump() + ",\n";
  };
  field("format", kFormat);
  field("version", kVersion);
  field("name", lv.name);
  field("description", lv.description);
  if (lv.mover) field("mover", *lv.mover);
  field("dt", lv.dt);
  field("cell", lv.cell);
  field("tile", lv.tile);
  field("speed", lv.speed);
  field("gravity", Json::array({lv.gravity.x, lv.gravity.y}));
  if (lv.camera) field("camera", rectJson(*lv.camera));
  field("rules", lv.rules.empty() ? std::string("level") : lv.rules);
  if (!lv.params.empty()) {
    Json p = Json::object();
    for (const auto& [n, v] : lv.params) p[n] = v;
    field("params", p);
  }
  const auto list = [&out](std::string_view key, std::size_t n, auto&& item, bool last) {
    out += "  \"" + std::string(key) + "\": [";
    for (std::size_t i = 0; i < n; ++i) out += (i ? ",\n    " : "\n    ") + item(i).dump();
    out += n ? "\n  ]" : "]";
    out += last ? "\n" : ",\n";
  };
  list(
      "solids", lv.solids.size(),
      [&](std::size_t i) {
        const sim::Solid& s = lv.solids[i];
        if (s.tag == 0 && !s.oneWay) return rectJson(s.rect);
        Json j = {{"rect", rectJson(s.rect)}, {"tag", s.tag}};
        if (s.oneWay) j["oneWay"] = true;
        return j;
      },
      false);
  list(
      "bodies", lv.bodies.size(), [&](std::size_t i) { return bodyJson(lv.bodies[i]); }, true);
  out += "}\n";
  return out;
}

// [SECTION] exporting -----------------------------------------------------------------------------

Level exportScene(const sim::SceneDef& scene, const sim::Params& params,
                  std::optional<std::string> mover) {
  const sim::SceneSetup s = scene.build(params);
  Level lv;
  lv.name = scene.name;
  lv.description = scene.description;
  lv.source = scene.name;
  lv.mover = std::move(mover);
  lv.dt = params.get(sim::param::dt);
  lv.cell = s.cellSize;
  lv.tile = params.get(sim::param::tile);
  lv.speed = params.get(sim::param::speed);
  lv.gravity = s.gravity;
  lv.camera = scene.camera(params);
  lv.rules = scene.name;
  for (std::size_t i = 0; i < params.specs().size(); ++i)
    lv.params.emplace_back(params.specs()[i].name, params.values()[i]);
  lv.solids = s.solids;
  lv.bodies.reserve(s.bodies.size());
  for (const sim::Body& b : s.bodies) {
    if (b.response >= response::kBuiltinCount) {
      fail(scene.name, "a body responds with a user response (id " + std::to_string(b.response) +
                           "), which a scene file cannot name");
    }
    LevelBody lb;
    lb.body = b;
    lv.bodies.push_back(lb);
  }
  return lv;
}

}  // namespace tv::level
