// Tiled JSON maps as levels: tile layers (CSV or base64, zlib or gzip, finite or infinite),
// object layers of rectangles, and objects that become bodies.
//
// Index: [SECTION] properties · [SECTION] tilesets · [SECTION] tile layers ·
//        [SECTION] objects · [SECTION] the map
#include "tv/level/tiled.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>

#include "file_text.hpp"
#include "json_reader.hpp"
#include "tile_data.hpp"
#include "tv/error.hpp"
#include "tv/mover.hpp"

namespace tv::level {
namespace {

using detail::Json;
using detail::JsonAt;

constexpr std::uint32_t kFlipBits = 0xF0000000u;  // horizontal, vertical, diagonal, hex-120
constexpr double kMaxCoordinate = 1e9;            // what a World accepts without losing cells
constexpr std::int64_t kMaxSide = 1 << 24;        // tiles along a layer or chunk side

// [SECTION] properties ----------------------------------------------------------------------------

/// A property's value by name: Tiled 1.2+ writes [{name, type, value}], older maps {name: value}.
std::optional<JsonAt> property(const JsonAt& owner, std::string_view name) {
  const auto props = owner.find("properties");
  if (!props) return std::nullopt;
  if (props->isObject()) return props->find(name);
  const std::size_t n = props->size();
  for (std::size_t i = 0; i < n; ++i) {
    const JsonAt p = props->at(i);
    if (!p.isObject()) p.fail("expected a property {name, type, value}");
    if (p["name"].string() == name) return p["value"];
  }
  return std::nullopt;
}

bool flag(const JsonAt& owner, std::string_view name) {
  const auto v = property(owner, name);
  return v && v->boolean();
}

std::optional<double> numberProperty(const JsonAt& owner, std::string_view name, double min,
                                     double max) {
  const auto v = property(owner, name);
  if (!v) return std::nullopt;
  return v->number(min, max);
}

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// [SECTION] tilesets ------------------------------------------------------------------------------

struct Tileset {
  std::uint32_t firstGid = 1;
  std::uint32_t count = 0;
  std::vector<std::uint32_t> solidIds;   // sorted local ids whose tile is collidable
  std::vector<std::uint32_t> oneWayIds;  // sorted local ids whose tile is one-way
  bool allSolid = false;                 // the tileset's own `collidable` property
  bool allOneWay = false;                // the tileset's own `oneway` property
};

// What a tile is: not solid, solid, or solid from above only (`oneway`, which implies solid).
struct TileKind {
  bool solid = false;
  bool oneWay = false;
};

Tileset readTileset(const JsonAt& ts, std::uint32_t firstGid) {
  Tileset t;
  t.firstGid = firstGid;
  t.count = static_cast<std::uint32_t>(ts["tilecount"].whole(0, kFlipBits - 1));
  t.allSolid = flag(ts, "collidable");
  t.allOneWay = flag(ts, "oneway");
  if (auto tiles = ts.find("tiles")) {
    const std::size_t n = tiles->size();
    for (std::size_t i = 0; i < n; ++i) {
      const JsonAt tile = tiles->at(i);
      const auto id = static_cast<std::uint32_t>(tile["id"].whole(0, kFlipBits - 1));
      if (flag(tile, "collidable")) t.solidIds.push_back(id);
      if (flag(tile, "oneway")) t.oneWayIds.push_back(id);
    }
  }
  std::sort(t.solidIds.begin(), t.solidIds.end());
  std::sort(t.oneWayIds.begin(), t.oneWayIds.end());
  return t;
}

struct Tilesets {
  std::vector<Tileset> sets;  // by firstGid
  std::uint32_t end = 1;      // one past the last gid any tileset covers

  /// Whether `gid` (flags masked) is collidable, or one-way; throws naming `at` when no tileset
  /// holds it.
  TileKind kind(std::uint32_t gid, const JsonAt& at, const std::string& where) const {
    auto it = std::upper_bound(sets.begin(), sets.end(), gid,
                               [](std::uint32_t g, const Tileset& t) { return g < t.firstGid; });
    if (it == sets.begin() || gid - std::prev(it)->firstGid >= std::prev(it)->count) {
      at.failPlain(where + "gid " + std::to_string(gid) +
                   " is in no tileset (they hold gids 1 to " + std::to_string(end - 1) + ")");
    }
    const Tileset& t = *std::prev(it);
    const std::uint32_t id = gid - t.firstGid;
    TileKind k;
    k.oneWay = t.allOneWay || std::binary_search(t.oneWayIds.begin(), t.oneWayIds.end(), id);
    k.solid = k.oneWay || t.allSolid ||
              std::binary_search(t.solidIds.begin(), t.solidIds.end(), id);
    return k;
  }
};

Tilesets readTilesets(const JsonAt& map, const TiledOptions& options) {
  Tilesets out;
  const auto list = map.find("tilesets");
  if (!list) return out;
  const std::size_t n = list->size();
  for (std::size_t i = 0; i < n; ++i) {
    const JsonAt ts = list->at(i);
    const auto firstGid = static_cast<std::uint32_t>(ts["firstgid"].whole(1, kFlipBits - 1));
    if (auto source = ts.find("source")) {
      const std::string& file = source->string();
      const std::string ext = lower(std::filesystem::path(file).extension().string());
      if (ext != ".tsj" && ext != ".json") {
        source->fail(
            "unsupported: external tilesets must be JSON (.tsj); export it from Tiled as JSON or "
            "embed it");
      }
      if (!options.readTileset) source->fail("external tileset, and no way to read it was given");
      const std::string text = options.readTileset(file);
      const Json doc = detail::parseJson(text, file);
      out.sets.push_back(readTileset(JsonAt(doc, "", file), firstGid));
    } else {
      out.sets.push_back(readTileset(ts, firstGid));
    }
  }
  std::sort(out.sets.begin(), out.sets.end(),
            [](const Tileset& a, const Tileset& b) { return a.firstGid < b.firstGid; });
  for (std::size_t i = 0; i < out.sets.size(); ++i) {
    const std::uint64_t last = std::uint64_t{out.sets[i].firstGid} + out.sets[i].count;
    if (i + 1 < out.sets.size() && last > out.sets[i + 1].firstGid) {
      list->failPlain("tilesets overlap: one starting at gid " +
                      std::to_string(out.sets[i].firstGid) + " holds " +
                      std::to_string(out.sets[i].count) + " tiles, past gid " +
                      std::to_string(out.sets[i + 1].firstGid));
    }
    out.end = static_cast<std::uint32_t>(std::min<std::uint64_t>(last, kFlipBits));
  }
  return out;
}

// [SECTION] tile layers ---------------------------------------------------------------------------

struct MapContext {
  const JsonAt* map;
  const TiledOptions* options;
  Tilesets tilesets;
  double tileW = 16, tileH = 16;
  std::string encoding, compression;  // of the layer being read
  Level* level;
  std::vector<std::string> layerNames;  // every layer seen, groups' included
  // Objects of a class the loader makes nothing of (not a body, not collidable), by class:
  // how many, and the first one's name and place, for the note that says so.
  struct Ignored {
    std::string cls;
    std::size_t count = 0;
    std::string first;
  };
  std::vector<Ignored> ignored;
};

/// The gids of one block of `w`×`h` tiles (a finite layer, or a chunk), flip flags masked.
std::vector<std::uint32_t> readGids(const JsonAt& data, std::int64_t w, std::int64_t h,
                                    const std::string& encoding, const std::string& compression) {
  const auto n = static_cast<std::size_t>(w * h);
  std::vector<std::uint32_t> gids;
  if (encoding == "csv") {
    if (!data.isArray()) data.fail("expected an array of gids (the layer's encoding is csv)");
    if (data.size() != n) {
      data.failPlain("holds " + std::to_string(data.size()) + " gids, but width × height is " +
                     std::to_string(n));
    }
    gids.reserve(n);  // proven by the array, already in memory
    for (std::size_t i = 0; i < n; ++i) {
      gids.push_back(static_cast<std::uint32_t>(data.at(i).whole(0, 0xFFFFFFFFll)) & ~kFlipBits);
    }
    return gids;
  }
  const std::string& text = data.string();
  std::vector<std::uint8_t> bytes;
  try {
    bytes = detail::decodeBase64(text);
    if (compression == "zlib" || compression == "gzip") {
      if (n * 4 > detail::maxInflated(bytes.size())) {
        throw std::runtime_error("the layer declares " + std::to_string(n) + " tiles, more than " +
                                 std::to_string(bytes.size()) + " compressed bytes can hold");
      }
      bytes = detail::inflateExactly(bytes, n * 4, compression == "gzip");
    }
  } catch (const std::runtime_error& e) {
    data.failPlain(e.what());
  }
  if (bytes.size() != n * 4) {
    data.failPlain("holds " + std::to_string(bytes.size()) + " bytes, but width × height × 4 is " +
                   std::to_string(n * 4));
  }
  gids.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint32_t g = std::uint32_t{bytes[4 * i]} | std::uint32_t{bytes[4 * i + 1]} << 8 |
                            std::uint32_t{bytes[4 * i + 2]} << 16 |
                            std::uint32_t{bytes[4 * i + 3]} << 24;
    gids[i] = g & ~kFlipBits;
  }
  return gids;
}

void checkCoordinate(const JsonAt& at, double v) {
  if (std::abs(v) > kMaxCoordinate) {
    at.failPlain("reaches " + formatNumber(v) + " px, farther than 1e9 from the origin");
  }
}

/// Adds the solid tiles of one block whose top-left tile is (x0, y0) in tiles.
void addBlock(MapContext& m, const JsonAt& data, std::int64_t x0, std::int64_t y0, std::int64_t w,
              std::int64_t h, Vec2 offset, bool layerSolid, bool layerOneWay) {
  const std::vector<std::uint32_t> gids = readGids(data, w, h, m.encoding, m.compression);
  for (std::size_t i = 0; i < gids.size(); ++i) {
    const std::uint32_t gid = gids[i];
    if (gid == 0) continue;
    const std::string where = m.encoding == "csv" ? "" : "tile " + std::to_string(i) + ": ";
    const JsonAt at = m.encoding == "csv" ? data.at(i) : data;
    const TileKind tile = m.tilesets.kind(gid, at, where);
    if (!layerSolid && !layerOneWay && !tile.solid) continue;
    const auto col = x0 + static_cast<std::int64_t>(i) % w;
    const auto row = y0 + static_cast<std::int64_t>(i) / w;
    const Rect r{offset.x + static_cast<double>(col) * m.tileW,
                 offset.y + static_cast<double>(row) * m.tileH, m.tileW, m.tileH};
    checkCoordinate(at, std::max(std::abs(r.x), std::abs(r.y)) + std::max(r.w, r.h));
    m.level->solids.push_back({r, 1, layerOneWay || tile.oneWay});
  }
}

bool namedSolid(const MapContext& m, const std::string& name) {
  const auto& names = m.options->solidLayers;
  return std::find(names.begin(), names.end(), name) != names.end();
}

void readTileLayer(MapContext& m, const JsonAt& layer, Vec2 offset, bool infinite) {
  const std::string name = layer.has("name") ? layer["name"].string() : "";
  const bool layerSolid = flag(layer, "collidable") || namedSolid(m, name);
  const bool layerOneWay = flag(layer, "oneway");
  m.encoding = "csv";
  m.compression.clear();
  if (auto e = layer.find("encoding")) {
    m.encoding = e->string();
    if (m.encoding != "csv" && m.encoding != "base64")
      e->fail("unsupported encoding (csv or base64)");
  }
  if (auto c = layer.find("compression")) {
    m.compression = c->string();
    if (m.compression == "zstd") {
      c->fail("unsupported compression (zlib, gzip or none; re-save the map with zlib)");
    }
    if (!m.compression.empty() && m.compression != "zlib" && m.compression != "gzip") {
      c->fail("unsupported compression (zlib, gzip or none)");
    }
  }
  if (infinite) {
    const JsonAt chunks = layer["chunks"];
    const std::size_t n = chunks.size();
    for (std::size_t i = 0; i < n; ++i) {
      const JsonAt c = chunks.at(i);
      const std::int64_t x = c["x"].whole(-kMaxSide * 64, kMaxSide * 64);
      const std::int64_t y = c["y"].whole(-kMaxSide * 64, kMaxSide * 64);
      const std::int64_t w = c["width"].whole(1, kMaxSide);
      const std::int64_t h = c["height"].whole(1, kMaxSide);
      addBlock(m, c["data"], x, y, w, h, offset, layerSolid, layerOneWay);
    }
    return;
  }
  const std::int64_t w = layer["width"].whole(0, kMaxSide);
  const std::int64_t h = layer["height"].whole(0, kMaxSide);
  if (w == 0 || h == 0) return;
  addBlock(m, layer["data"], 0, 0, w, h, offset, layerSolid, layerOneWay);
}

// [SECTION] objects -------------------------------------------------------------------------------

double degrees(double d) {
  return d * std::numbers::pi / 180.0;
}

/// The object's rect, with a point's size from `size` centred on the point (bottom-centred for
/// walkers and players, so their feet are where the point is).
Rect objectRect(const JsonAt& o, Vec2 offset, double pointSize, bool feetAtPoint) {
  const double x = o["x"].number(-kMaxCoordinate, kMaxCoordinate) + offset.x;
  double y = o["y"].number(-kMaxCoordinate, kMaxCoordinate) + offset.y;
  const double w = o.has("width") ? o["width"].number(0, kMaxCoordinate) : 0.0;
  const double h = o.has("height") ? o["height"].number(0, kMaxCoordinate) : 0.0;
  if (w > 0 && h > 0) {
    if (o.has("gid")) y -= h;  // tile objects are anchored at their bottom-left
    return {x, y, w, h};
  }
  return {x - pointSize / 2, feetAtPoint ? y - pointSize : y - pointSize / 2, pointSize, pointSize};
}

std::string shapeOf(const JsonAt& o) {
  for (const char* s : {"ellipse", "point", "polygon", "polyline", "text"}) {
    if (auto v = o.find(s)) {
      if (!v->json().is_boolean() || v->json().get<bool>()) return s;
    }
  }
  return "";
}

LevelBody bodyOf(Motion motion, Rect r) {
  LevelBody lb;
  lb.motion = motion;
  sim::Body& b = lb.body;
  b.rect = r;
  switch (motion) {
    case Motion::bullet:
      b.role = sim::BodyRole::projectile, b.layer = sim::kLayerProjectile;
      b.response = response::touch;
      break;
    case Motion::walker:
      b.role = sim::BodyRole::walker, b.layer = sim::kLayerEnemy, b.falls = true;
      break;
    case Motion::player:
      b.role = sim::BodyRole::player, b.layer = sim::kLayerPlayer, b.falls = true;
      break;
    case Motion::fly:
      break;
  }
  return lb;
}

void readWalker(LevelBody& lb, const JsonAt& o) {
  if (auto s = numberProperty(o, "speed", 0.0, 1e9)) lb.speed = *s;
  if (auto d = property(o, "direction")) {
    const std::string& s = d->string();
    if (s != "left" && s != "right") d->fail("expected \"left\" or \"right\"");
    lb.facingLeft = s == "left";
  }
}

void readObject(MapContext& m, const JsonAt& o, Vec2 offset, bool layerSolid,
                bool layerOneWay) {
  std::string cls;
  if (auto c = o.find("class")) cls = c->string();
  if (cls.empty()) {
    if (auto t = o.find("type")) cls = t->string();
  }
  cls = lower(cls);
  Level& lv = *m.level;
  const std::string shape = shapeOf(o);
  const std::string name = o.has("name") ? o["name"].string() : "";
  const double size = numberProperty(o, "size", 0.0, 1e4).value_or(0.0);
  if (cls == "player" || cls == "walker") {
    const Motion motion = cls == "player" ? Motion::player : Motion::walker;
    LevelBody lb = bodyOf(motion, objectRect(o, offset, size > 0 ? size : 12.0, true));
    readWalker(lb, o);
    lb.name = name;
    if (motion == Motion::player) {
      if (auto e = property(o, "every")) lb.jump.every = e->whole(1, 1'000'000);
      if (auto e = property(o, "phase")) lb.jump.phase = e->whole(0, 1'000'000);
      if (auto j = numberProperty(o, "jump", 0.0, 1e6)) {
        lb.jump.speed = std::sqrt(2.0 * std::max(lv.gravity.y, 0.0) * *j);
      }
    }
    lv.bodies.push_back(lb);
    return;
  }
  if (cls == "bullet" || cls == "spawner") {
    const double speed = numberProperty(o, "speed", 0.0, 1e9).value_or(960.0);
    const double angle = numberProperty(o, "angle", -3600.0, 3600.0).value_or(0.0);
    const double side = size > 0 ? size : 4.0;
    if (cls == "bullet") {
      LevelBody lb = bodyOf(Motion::bullet, objectRect(o, offset, side, false));
      lb.body.velocity = Vec2{std::cos(degrees(angle)), std::sin(degrees(angle))} * speed;
      lb.name = name;
      lv.bodies.push_back(lb);
      return;
    }
    // A spawner fires `count` bullets at once, spread evenly along its longer side (a point
    // spawner lines them up across the direction of fire, two sizes apart), optionally fanned
    // over `spread` degrees.
    const std::int64_t count = property(o, "count") ? property(o, "count")->whole(1, 10'000) : 8;
    const double spread = numberProperty(o, "spread", 0.0, 360.0).value_or(0.0);
    const Rect area = objectRect(o, offset, 0.0, false);
    const Vec2 centre{area.x + area.w / 2, area.y + area.h / 2};
    for (std::int64_t k = 0; k < count; ++k) {
      const double f = count == 1 ? 0.5 : static_cast<double>(k) / static_cast<double>(count - 1);
      Vec2 at = centre;
      if (area.w > 0 && area.h > 0) {
        const double g = (static_cast<double>(k) + 0.5) / static_cast<double>(count);
        at = area.w >= area.h ? Vec2{area.x + g * area.w, centre.y}
                              : Vec2{centre.x, area.y + g * area.h};
      } else {
        const Vec2 across{-std::sin(degrees(angle)), std::cos(degrees(angle))};
        at = centre + across * ((f - 0.5) * 2.0 * side * static_cast<double>(count - 1));
      }
      const double a = degrees(angle + (f - 0.5) * spread);
      LevelBody lb = bodyOf(Motion::bullet, {at.x - side / 2, at.y - side / 2, side, side});
      lb.body.velocity = Vec2{std::cos(a), std::sin(a)} * speed;
      lb.body.group = static_cast<std::uint32_t>(k);
      // A spawner's bullets are its name and their number ("turret 3").
      if (!name.empty()) lb.name = name + " " + std::to_string(k);
      lv.bodies.push_back(lb);
    }
    return;
  }
  const bool oneWay = layerOneWay || flag(o, "oneway");
  const bool solid = layerSolid || oneWay || flag(o, "collidable");
  if (!solid) {
    // A class the loader knows nothing of is not dropped in silence: the notes say so, once per
    // class, with the first such object.
    if (!cls.empty()) {
      auto it = std::find_if(m.ignored.begin(), m.ignored.end(),
                             [&](const MapContext::Ignored& i) { return i.cls == cls; });
      if (it == m.ignored.end()) {
        const Rect r = objectRect(o, offset, 0.0, false);
        char where[96];
        std::snprintf(where, sizeof where, " at (%g, %g)", r.x, r.y);
        m.ignored.push_back({cls, 0, (name.empty() ? "an object" : "'" + name + "'") + where});
        it = m.ignored.end() - 1;
      }
      ++it->count;
    }
    return;
  }
  if (!shape.empty())
    o.failPlain("unsupported: a collidable " + shape + " (only rectangles can be solid)");
  if (auto r = o.find("rotation"); r && r->number() != 0.0) {
    r->fail("unsupported: a collidable rectangle must not be rotated");
  }
  const double w = o.has("width") ? o["width"].number() : 0.0;
  const double h = o.has("height") ? o["height"].number() : 0.0;
  if (!(w > 0 && h > 0)) o.failPlain("a collidable rectangle needs width and height > 0");
  const Rect r = objectRect(o, offset, 0.0, false);
  checkCoordinate(o, std::max(std::abs(r.x), std::abs(r.y)) + std::max(r.w, r.h));
  lv.solids.push_back({r, 2, oneWay});
  if (!name.empty()) {
    lv.solidNames.resize(lv.solids.size());
    lv.solidNames.back() = name;
  }
}

// [SECTION] the map -------------------------------------------------------------------------------

void readLayers(MapContext& m, const JsonAt& layers, Vec2 offset, bool infinite, int depth) {
  if (depth > 32) layers.failPlain("groups nested more than 32 deep");
  const std::size_t n = layers.size();
  for (std::size_t i = 0; i < n; ++i) {
    const JsonAt layer = layers.at(i);
    const std::string& type = layer["type"].string();
    if (layer.has("name")) m.layerNames.push_back(layer["name"].string());
    Vec2 at = offset;
    if (auto v = layer.find("offsetx")) at.x += v->number(-kMaxCoordinate, kMaxCoordinate);
    if (auto v = layer.find("offsety")) at.y += v->number(-kMaxCoordinate, kMaxCoordinate);
    if (type == "tilelayer") {
      readTileLayer(m, layer, at, infinite);
    } else if (type == "objectgroup") {
      const std::string name = layer.has("name") ? layer["name"].string() : "";
      const bool solid = flag(layer, "collidable") || namedSolid(m, name);
      const bool oneWay = flag(layer, "oneway");
      const JsonAt objects = layer["objects"];
      const std::size_t k = objects.size();
      for (std::size_t j = 0; j < k; ++j) readObject(m, objects.at(j), at, solid, oneWay);
    } else if (type == "group") {
      readLayers(m, layer["layers"], at, infinite, depth + 1);
    } else if (type != "imagelayer") {
      layer["type"].fail("unknown layer type (tilelayer, objectgroup, group, imagelayer)");
    }
  }
}

}  // namespace

Level parseTiledMap(std::string_view text, std::string_view file, const TiledOptions& options) {
  const std::string name(file);
  const Json doc = detail::parseJson(text, name);
  const JsonAt map(doc, "", name);
  if (!map.isObject()) map.fail("expected a Tiled map (an object)");
  if (auto t = map.find("type"); t && t->string() != "map") t->fail("expected \"map\"");
  const std::string& orientation = map["orientation"].string();
  if (orientation != "orthogonal") {
    map["orientation"].fail("unsupported orientation (orthogonal maps only)");
  }
  Level lv;
  lv.source = name;
  lv.name = std::filesystem::path(name).stem().string();
  lv.description = "Tiled map " + name;
  MapContext m{&map, &options, readTilesets(map, options), 16, 16, "", "", &lv, {}, {}};
  m.tileW = map["tilewidth"].positive(1e4);
  m.tileH = map["tileheight"].positive(1e4);
  lv.tile = std::min(m.tileW, m.tileH);
  lv.cell = 4.0 * std::max(m.tileW, m.tileH);
  const bool infinite = map.has("infinite") && map["infinite"].boolean();
  // Map properties: gravity before the objects (players' jump heights depend on it).
  const auto gravity = numberProperty(map, "gravity", -1e7, 1e7);
  lv.gravity = {0.0, gravity.value_or(1800.0)};
  if (auto v = numberProperty(map, "dt", 1e-6, 1.0)) lv.dt = *v;
  if (auto v = numberProperty(map, "cell", 1e-3, 1e6)) lv.cell = *v;
  if (auto v = numberProperty(map, "speed", 1e-3, 1e9)) lv.speed = *v;
  if (auto v = property(map, "mover")) {
    try {
      (void)parseMover(v->string());
    } catch (const Error& e) {
      v->fail(std::string("expected a mover: ") + e.what());
    }
    lv.mover = v->string();
  }
  readLayers(m, map["layers"], {}, infinite, 0);
  for (const std::string& wanted : options.solidLayers) {
    if (std::find(m.layerNames.begin(), m.layerNames.end(), wanted) == m.layerNames.end()) {
      std::string names;
      for (const std::string& n : m.layerNames) names += (names.empty() ? "" : ", ") + n;
      fail(name, "--solid-layer '" + wanted +
                     "': the map has no layer of that name (its layers: " + names + ")");
    }
  }
  if (!infinite) {
    const std::int64_t w = map["width"].whole(0, kMaxSide);
    const std::int64_t h = map["height"].whole(0, kMaxSide);
    if (w > 0 && h > 0) {
      lv.camera = Rect{0, 0, static_cast<double>(w) * m.tileW, static_cast<double>(h) * m.tileH};
    }
  }
  const bool anyWalker = std::any_of(lv.bodies.begin(), lv.bodies.end(), [](const LevelBody& b) {
    return b.motion == Motion::walker || b.motion == Motion::player;
  });
  if (!gravity && !anyWalker) lv.gravity = {};
  for (const MapContext::Ignored& i : m.ignored) {
    lv.notes.push_back(name + ": " + std::to_string(i.count) + " object" + (i.count == 1 ? "" : "s") +
                       " of class '" + i.cls + "' ignored (first: " + i.first +
                       "): a class makes a body when it is player, walker, bullet or spawner, "
                       "and a solid when the object is collidable");
  }
  if (lv.solids.empty()) {
    lv.notes.push_back(name +
                       ": nothing is solid: give a layer, tile or object the bool property "
                       "'collidable' = true, or name a layer with --solid-layer");
  }
  if (lv.bodies.empty()) {
    lv.notes.push_back(name +
                       ": no bodies: add objects of class player, walker, bullet or spawner");
  }
  return lv;
}

Level loadTiledMap(const std::filesystem::path& path, TiledOptions options) {
  if (!options.readTileset) {
    const std::filesystem::path dir = path.parent_path();
    options.readTileset = [dir](const std::string& source) {
      return detail::readFileText(dir / source);
    };
  }
  return parseTiledMap(detail::readFileText(path), path.string(), options);
}

}  // namespace tv::level
