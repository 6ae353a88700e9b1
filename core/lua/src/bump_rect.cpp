// bump.rect.*: bump.lua's rectangle helpers, callable directly. All but detectCollision are
// plain arithmetic with bump's conventions (its 1e-10 margin in containsPoint included);
// detectCollision is the core's exact sweep in bump's table shape.

#include <cmath>
#include <limits>

#include "boundary.hpp"
#include "lua_world.hpp"
#include "tv/sweep.hpp"

namespace tvlua {
namespace {

constexpr double kDelta = 1e-10;  // bump.lua's margin, kept for containsPoint's callers

double nearest(double v, double a, double b) { return std::fabs(a - v) < std::fabs(b - v) ? a : b; }

int getNearestCorner(lua_State* L) {
  const double x = checkFinite(L, 1, "x"), y = checkFinite(L, 2, "y");
  const double w = checkFinite(L, 3, "w"), h = checkFinite(L, 4, "h");
  const double px = checkFinite(L, 5, "px"), py = checkFinite(L, 6, "py");
  lua_pushnumber(L, nearest(px, x, x + w));
  lua_pushnumber(L, nearest(py, y, y + h));
  return 2;
}

// Liang-Barsky clipping of the segment (x1,y1)->(x2,y2) against the rect, over the parameter
// range [ti1, ti2]: the entry and exit parameters and the normals of the sides crossed there.
int getSegmentIntersectionIndices(lua_State* L) {
  const double x = luaL_checknumber(L, 1), y = luaL_checknumber(L, 2);
  const double w = luaL_checknumber(L, 3), h = luaL_checknumber(L, 4);
  const double x1 = luaL_checknumber(L, 5), y1 = luaL_checknumber(L, 6);
  const double x2 = luaL_checknumber(L, 7), y2 = luaL_checknumber(L, 8);
  double t0 = luaL_optnumber(L, 9, 0.0), t1 = luaL_optnumber(L, 10, 1.0);
  const double dx = x2 - x1, dy = y2 - y1;
  double n0x = 0, n0y = 0, n1x = 0, n1y = 0;
  const struct {
    double nx, ny, p, q;
  } sides[4] = {{-1, 0, -dx, x1 - x}, {1, 0, dx, x + w - x1}, {0, -1, -dy, y1 - y}, {0, 1, dy, y + h - y1}};
  for (const auto& s : sides) {
    if (s.p == 0) {
      if (s.q <= 0) return 0;  // parallel to this side and outside it
      continue;
    }
    const double r = s.q / s.p;
    if (s.p < 0) {  // entering through this side
      if (r > t1) return 0;
      if (r > t0) t0 = r, n0x = s.nx, n0y = s.ny;
    } else {  // leaving through it
      if (r < t0) return 0;
      if (r < t1) t1 = r, n1x = s.nx, n1y = s.ny;
    }
  }
  lua_pushnumber(L, t0);
  lua_pushnumber(L, t1);
  lua_pushnumber(L, n0x);
  lua_pushnumber(L, n0y);
  lua_pushnumber(L, n1x);
  lua_pushnumber(L, n1y);
  return 6;
}

int getDiff(lua_State* L) {
  double v[8];
  for (int i = 0; i < 8; ++i) v[i] = luaL_checknumber(L, i + 1);
  lua_pushnumber(L, v[4] - v[0] - v[2]);
  lua_pushnumber(L, v[5] - v[1] - v[3]);
  lua_pushnumber(L, v[2] + v[6]);
  lua_pushnumber(L, v[3] + v[7]);
  return 4;
}

int containsPoint(lua_State* L) {
  double v[6];
  for (int i = 0; i < 6; ++i) v[i] = luaL_checknumber(L, i + 1);
  const double x = v[0], y = v[1], w = v[2], h = v[3], px = v[4], py = v[5];
  lua_pushboolean(L, px - x > kDelta && py - y > kDelta && x + w - px > kDelta && y + h - py > kDelta);
  return 1;
}

int isIntersecting(lua_State* L) {
  double v[8];
  for (int i = 0; i < 8; ++i) v[i] = luaL_checknumber(L, i + 1);
  lua_pushboolean(L, tv::overlaps({v[0], v[1], v[2], v[3]}, {v[4], v[5], v[6], v[7]}));
  return 1;
}

int getSquareDistance(lua_State* L) {
  double v[8];
  for (int i = 0; i < 8; ++i) v[i] = luaL_checknumber(L, i + 1);
  const double dx = v[0] - v[4] + (v[2] - v[6]) / 2;
  const double dy = v[1] - v[5] + (v[3] - v[7]) / 2;
  lua_pushnumber(L, dx * dx + dy * dy);
  return 1;
}

void setXY(lua_State* L, const char* field, double x, double y) {
  lua_createtable(L, 0, 2);
  lua_pushnumber(L, x);
  lua_setfield(L, -2, "x");
  lua_pushnumber(L, y);
  lua_setfield(L, -2, "y");
  lua_setfield(L, -2, field);
}

void setRect(lua_State* L, const char* field, const tv::Rect& r) {
  lua_createtable(L, 0, 4);
  lua_pushnumber(L, r.x);
  lua_setfield(L, -2, "x");
  lua_pushnumber(L, r.y);
  lua_setfield(L, -2, "y");
  lua_pushnumber(L, r.w);
  lua_setfield(L, -2, "w");
  lua_pushnumber(L, r.h);
  lua_setfield(L, -2, "h");
  lua_setfield(L, -2, field);
}

int detectCollision(lua_State* L) {
  const tv::Rect a{checkFinite(L, 1, "x1"), checkFinite(L, 2, "y1"), checkPositive(L, 3, "w1"),
                   checkPositive(L, 4, "h1")};
  const tv::Rect b{checkFinite(L, 5, "x2"), checkFinite(L, 6, "y2"), checkPositive(L, 7, "w2"),
                   checkPositive(L, 8, "h2")};
  const tv::Vec2 goal{optFinite(L, 9, "goalX", a.x), optFinite(L, 10, "goalY", a.y)};
  const tv::Sweep s = tv::sweepRect(a, goal, b);
  if (s.kind == tv::SweepKind::miss) return 0;
  lua_createtable(L, 0, 7);
  lua_pushboolean(L, s.kind == tv::SweepKind::overlap);
  lua_setfield(L, -2, "overlaps");
  lua_pushnumber(L, s.ti);
  lua_setfield(L, -2, "ti");
  setXY(L, "move", goal.x - a.x, goal.y - a.y);
  setXY(L, "normal", s.normal.x, s.normal.y);
  setXY(L, "touch", s.touch.x, s.touch.y);
  setRect(L, "itemRect", a);
  setRect(L, "otherRect", b);
  return 1;
}

}  // namespace

void pushRectFunctions(lua_State* L) {
  const luaL_Reg fns[] = {
      {"getNearestCorner", guarded<getNearestCorner>},
      {"getSegmentIntersectionIndices", guarded<getSegmentIntersectionIndices>},
      {"getDiff", guarded<getDiff>},
      {"containsPoint", guarded<containsPoint>},
      {"isIntersecting", guarded<isIntersecting>},
      {"getSquareDistance", guarded<getSquareDistance>},
      {"detectCollision", guarded<detectCollision>},
      {nullptr, nullptr},
  };
  lua_newtable(L);
  for (const luaL_Reg* f = fns; f->name; ++f) {
    lua_pushcfunction(L, f->func);
    lua_setfield(L, -2, f->name);
  }
}

}  // namespace tvlua
