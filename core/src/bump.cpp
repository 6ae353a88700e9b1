// bump.lua 3.1.7's geometry and queries, written from its definitions: each function repeats
// bump's double operations in bump's order, so that its results are bump's bit for bit (Lua's
// numbers are IEEE doubles; we build with -ffp-contract=off). The move itself is World's
// (bump_move.cpp), over these.

#include "tv/bump.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "tv/world.hpp"

namespace tv::bump {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// bump's `nearest(x, a, b)`: a when strictly nearer, else b.
double nearest(double x, double a, double b) { return std::fabs(a - x) < std::fabs(b - x) ? a : b; }

double sign(double x) {
  if (x > 0) return 1.0;
  if (x == 0) return 0.0;
  return -1.0;
}

// Lua's math.min / math.max on two numbers: the second only when strictly smaller / larger.
double luaMin(double a, double b) { return b < a ? b : a; }
double luaMax(double a, double b) { return b > a ? b : a; }

// Keeps the inner calls of a query out of a recording: they are part of the bump call.
class Quiet {
 public:
  explicit Quiet(const World& w) {
    if (WorldObserver* o = w.observer()) scope_.emplace(*o);
  }

 private:
  std::optional<WorldObserver::Scope> scope_;
};

// Every item registered in bump's cells `c`: the core's items whose interior meets those cells'
// area, then bump's own cell test (an item is in the cells of its rect, as bump computes them).
void itemsInCells(const World& world, const Cells& c, std::vector<ItemId>& out) {
  const double size = world.cellSize();
  const Rect area{(c.left - 1) * size, (c.top - 1) * size, (c.right - c.left + 1) * size,
                  (c.bottom - c.top + 1) * size};
  world.queryRect(area, out);
  std::erase_if(out, [&](ItemId id) { return !cellsOf(size, world.rect(id)).meets(c); });
}

}  // namespace

Indices segmentIndices(const Rect& r, Vec2 a, Vec2 b, double ti1, double ti2) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  Vec2 n1, n2;
  for (int side = 0; side < 4; ++side) {
    double nx = 0, ny = 0, p = 0, q = 0;
    switch (side) {
      case 0: nx = -1, p = -dx, q = a.x - r.x; break;           // left
      case 1: nx = 1, p = dx, q = r.x + r.w - a.x; break;       // right
      case 2: ny = -1, p = -dy, q = a.y - r.y; break;           // top
      default: ny = 1, p = dy, q = r.y + r.h - a.y; break;      // bottom
    }
    if (p == 0) {
      if (q <= 0) return {};
      continue;
    }
    const double t = q / p;
    if (p < 0) {
      if (t > ti2) return {};
      if (t > ti1) ti1 = t, n1 = {nx, ny};
    } else {
      if (t < ti1) return {};
      if (t < ti2) ti2 = t, n2 = {nx, ny};
    }
  }
  return {true, ti1, ti2, n1, n2};
}

Vec2 nearestCorner(const Rect& r, Vec2 p) {
  return {nearest(p.x, r.x, r.x + r.w), nearest(p.y, r.y, r.y + r.h)};
}

bool containsPoint(const Rect& r, Vec2 p) {
  return p.x - r.x > kDelta && p.y - r.y > kDelta && r.x + r.w - p.x > kDelta &&
         r.y + r.h - p.y > kDelta;
}

double squareDistance(const Rect& a, const Rect& b) {
  const double dx = a.x - b.x + (a.w - b.w) / 2;
  const double dy = a.y - b.y + (a.h - b.h) / 2;
  return dx * dx + dy * dy;
}

bool isIntersecting(const Rect& a, const Rect& b) {
  return a.x < b.x + b.w && b.x < a.x + a.w && a.y < b.y + b.h && b.y < a.y + a.h;
}

Sweep detect(const Rect& a, Vec2 goal, const Rect& b) {
  const double dx = goal.x - a.x, dy = goal.y - a.y;
  // The Minkowski difference, as bump's rect_getDiff builds it.
  const Rect d{b.x - a.x - a.w, b.y - a.y - a.h, a.w + b.w, a.h + b.h};
  Sweep s;
  Vec2 touch;
  if (containsPoint(d, {0, 0})) {
    const Vec2 c = nearestCorner(d, {0, 0});
    const double wi = luaMin(a.w, std::fabs(c.x)), hi = luaMin(a.h, std::fabs(c.y));
    s.kind = SweepKind::overlap;
    s.ti = -wi * hi;
    if (dx == 0 && dy == 0) {
      // Not moving: out along the minimum displacement; on a tie, vertically.
      Vec2 p = nearestCorner(d, {0, 0});
      if (std::fabs(p.x) < std::fabs(p.y)) {
        p.y = 0;
      } else {
        p.x = 0;
      }
      s.normal = {sign(p.x), sign(p.y)};
      touch = {a.x + p.x, a.y + p.y};
    } else {
      // Moving: back against the movement, to where the line entered the difference.
      const Indices i = segmentIndices(d, {0, 0}, {dx, dy}, -kInf, 1);
      if (!i.hit) return {};
      s.normal = i.normal1;
      touch = {a.x + dx * i.ti1, a.y + dy * i.ti1};
    }
  } else {
    const Indices i = segmentIndices(d, {0, 0}, {dx, dy}, -kInf, kInf);
    // bump's test: enters before the goal, not through a corner point only, and not behind
    // the start (but for its margin, or a contact at 0 that goes on inside).
    if (!(i.hit && i.ti1 < 1 && std::fabs(i.ti1 - i.ti2) >= kDelta &&
          (0 < i.ti1 + kDelta || (0 == i.ti1 && i.ti2 > 0)))) {
      return {};
    }
    s.kind = SweepKind::hit;
    s.ti = i.ti1;
    s.normal = i.normal1;
    touch = {a.x + dx * s.ti, a.y + dy * s.ti};
  }
  // The contact is never inside the other: bump's rounding can leave it a step in, which
  // stops a body sliding on a tiled floor at the next seam. On the normal's axis it then goes
  // against the other's edge; off that axis, and whenever bump's point is outside, it is bump's.
  if (overlaps(a.at(touch), b)) {
    if (s.normal.x < 0) touch.x = placeBefore(b.x, a.w);
    if (s.normal.x > 0) touch.x = b.right();
    if (s.normal.y < 0) touch.y = placeBefore(b.y, a.h);
    if (s.normal.y > 0) touch.y = b.bottom();
  }
  s.touch = touch;
  return s;
}

Cells cellsOf(double cellSize, const Rect& r) {
  return {std::floor(r.x / cellSize) + 1, std::floor(r.y / cellSize) + 1,
          std::ceil((r.x + r.w) / cellSize), std::ceil((r.y + r.h) / cellSize)};
}

Cells cellsOfLeg(double cellSize, const Rect& r, Vec2 goal) {
  const double tl = luaMin(goal.x, r.x), tt = luaMin(goal.y, r.y);
  const double tr = luaMax(goal.x + r.w, r.x + r.w), tb = luaMax(goal.y + r.h, r.y + r.h);
  return cellsOf(cellSize, {tl, tt, tr - tl, tb - tt});
}

void project(const World& world, ItemId item, const Rect& r, Vec2 goal, Filter filter,
             std::span<const ItemId> exclude, std::vector<Collision>& out) {
  const Quiet quiet(world);
  std::vector<ItemId> found;
  itemsInCells(world, cellsOfLeg(world.cellSize(), r, goal), found);
  struct Hit {
    Collision c;
    double distance;
    std::uint64_t order;
  };
  std::vector<Hit> hits;
  for (const ItemId other : found) {
    if (other == item || std::find(exclude.begin(), exclude.end(), other) != exclude.end()) {
      continue;
    }
    const Rect o = world.rect(other);
    const Sweep s = detect(r, goal, o);
    if (s.kind == SweepKind::miss) continue;
    Hit h;
    h.c.item = item;
    h.c.other = other;
    h.c.overlaps = s.kind == SweepKind::overlap;
    h.c.ti = s.ti;
    h.c.move = goal - r.position();
    h.c.normal = s.normal;
    h.c.touch = s.touch;
    h.c.itemRect = r;
    h.c.otherRect = o;
    h.distance = squareDistance(r, o);
    h.order = world.order(other);
    hits.push_back(h);
  }
  std::sort(hits.begin(), hits.end(), [](const Hit& a, const Hit& b) {
    if (a.c.ti != b.c.ti) return a.c.ti < b.c.ti;
    if (a.distance != b.distance) return a.distance < b.distance;
    return a.order < b.order;
  });
  for (Hit& h : hits) {
    h.c.response = filter(item, h.c.other);
    if (h.c.response == response::ignore) continue;
    h.c.target = h.c.touch;
    out.push_back(h.c);
  }
}

void queryPoint(const World& world, Vec2 p, std::vector<ItemId>& out) {
  const Quiet quiet(world);
  out.clear();
  // bump looks in the point's cell only; an item holding the point by more than its margin is
  // registered there, and the core's half-open point query finds it.
  for (const ItemId id : world.queryPoint(p)) {
    if (containsPoint(world.rect(id), p)) out.push_back(id);
  }
}

namespace {

// bump's grid_traverse_initStep (its odd `ct + v` included: it is bump's definition of which
// cells a segment touches).
struct Step {
  double step, delta, t;
};
Step initStep(double cellSize, double ct, double t1, double t2) {
  const double v = t2 - t1;
  if (v > 0) return {1, cellSize / v, ((ct + v) * cellSize - t1) / v};
  if (v < 0) return {-1, -cellSize / v, ((ct + v - 1) * cellSize - t1) / v};
  return {0, kInf, kInf};
}

// bump's grid_traverse: calls f(cx, cy) for each cell it visits. Bump's loop may fail to end
// for some inputs; here it stops after visiting as many cells as the segment's bounding box
// holds, plus the last one.
template <class F>
void traverse(double cellSize, Vec2 a, Vec2 b, F&& f) {
  const double cx1 = std::floor(a.x / cellSize) + 1, cy1 = std::floor(a.y / cellSize) + 1;
  const double cx2 = std::floor(b.x / cellSize) + 1, cy2 = std::floor(b.y / cellSize) + 1;
  Step sx = initStep(cellSize, cx1, a.x, b.x);
  Step sy = initStep(cellSize, cy1, a.y, b.y);
  double cx = cx1, cy = cy1;
  f(cx, cy);
  double budget = (std::fabs(cx2 - cx1) + 1) * (std::fabs(cy2 - cy1) + 1) * 2 + 4;
  while (std::fabs(cx - cx2) + std::fabs(cy - cy2) > 1 && budget-- > 0) {
    if (sx.t < sy.t) {
      sx.t += sx.delta;
      cx += sx.step;
      f(cx, cy);
    } else {
      if (sx.t == sy.t) f(cx + sx.step, cy);  // both cells when going through a corner
      sy.t += sy.delta;
      cy += sy.step;
      f(cx, cy);
    }
  }
  if (cx != cx2 || cy != cy2) f(cx2, cy2);
}

}  // namespace

void querySegment(const World& world, Vec2 a, Vec2 b, std::vector<SegmentHit>& out) {
  const Quiet quiet(world);
  out.clear();
  const double size = world.cellSize();
  std::vector<Cells> cells;
  Cells box{kInf, kInf, -kInf, -kInf};
  traverse(size, a, b, [&](double cx, double cy) {
    cells.push_back({cx, cy, cx, cy});
    box = {std::min(box.left, cx), std::min(box.top, cy), std::max(box.right, cx),
           std::max(box.bottom, cy)};
  });
  std::vector<ItemId> found;
  itemsInCells(world, box, found);
  struct Hit {
    SegmentHit h;
    double weight;
    std::uint64_t order;
  };
  std::vector<Hit> hits;
  const double dx = b.x - a.x, dy = b.y - a.y;
  for (const ItemId id : found) {
    const Cells c = cellsOf(size, world.rect(id));
    if (std::none_of(cells.begin(), cells.end(), [&](const Cells& v) { return c.meets(v); })) {
      continue;
    }
    const Rect r = world.rect(id);
    const Indices i = segmentIndices(r, a, b, 0, 1);
    if (!i.hit || !((0 < i.ti1 && i.ti1 < 1) || (0 < i.ti2 && i.ti2 < 1))) continue;
    // Sorted by where the infinite line enters the rect, not the segment.
    const Indices line = segmentIndices(r, a, b, -kInf, kInf);
    Hit h;
    h.h.item = id;
    h.h.t0 = i.ti1;
    h.h.t1 = i.ti2;
    h.h.entry = {a.x + dx * i.ti1, a.y + dy * i.ti1};
    h.h.exit = {a.x + dx * i.ti2, a.y + dy * i.ti2};
    h.weight = luaMin(line.ti1, line.ti2);
    h.order = world.order(id);
    hits.push_back(h);
  }
  std::sort(hits.begin(), hits.end(), [](const Hit& x, const Hit& y) {
    if (x.weight != y.weight) return x.weight < y.weight;
    return x.order < y.order;
  });
  for (const Hit& h : hits) out.push_back(h.h);
}

}  // namespace tv::bump
