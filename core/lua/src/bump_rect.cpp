// bump.rect.*: bump.lua's rectangle helpers, callable directly, with bump's results bit for bit
// (the arithmetic is core/src/bump.cpp's, shared with the worlds' moves).

#include <cmath>
#include <limits>

#include "boundary.hpp"
#include "lua_world.hpp"
#include "tv/bump.hpp"

namespace tvlua {
namespace {

// n numbers from index 1 (bump's helpers take any numbers; infinities are fine there).
template <std::size_t N>
void numbers(lua_State* L, double (&v)[N]) {
  for (std::size_t i = 0; i < N; ++i) v[i] = luaL_checknumber(L, static_cast<int>(i) + 1);
}

int getNearestCorner(lua_State* L) {
  double v[6];
  numbers(L, v);
  const tv::Vec2 c = tv::bump::nearestCorner({v[0], v[1], v[2], v[3]}, {v[4], v[5]});
  lua_pushnumber(L, c.x);
  lua_pushnumber(L, c.y);
  return 2;
}

// (x,y,w,h, x1,y1,x2,y2 [, ti1 = 0, ti2 = 1]) -> ti1, ti2, nx1, ny1, nx2, ny2, or nil
int getSegmentIntersectionIndices(lua_State* L) {
  double v[8];
  numbers(L, v);
  const double t0 = luaL_optnumber(L, 9, 0.0), t1 = luaL_optnumber(L, 10, 1.0);
  const tv::bump::Indices i =
      tv::bump::segmentIndices({v[0], v[1], v[2], v[3]}, {v[4], v[5]}, {v[6], v[7]}, t0, t1);
  if (!i.hit) {
    lua_pushnil(L);
    return 1;
  }
  lua_pushnumber(L, i.ti1);
  lua_pushnumber(L, i.ti2);
  lua_pushnumber(L, i.normal1.x);
  lua_pushnumber(L, i.normal1.y);
  lua_pushnumber(L, i.normal2.x);
  lua_pushnumber(L, i.normal2.y);
  return 6;
}

int getDiff(lua_State* L) {
  double v[8];
  numbers(L, v);
  lua_pushnumber(L, v[4] - v[0] - v[2]);
  lua_pushnumber(L, v[5] - v[1] - v[3]);
  lua_pushnumber(L, v[2] + v[6]);
  lua_pushnumber(L, v[3] + v[7]);
  return 4;
}

int containsPoint(lua_State* L) {
  double v[6];
  numbers(L, v);
  lua_pushboolean(L, tv::bump::containsPoint({v[0], v[1], v[2], v[3]}, {v[4], v[5]}));
  return 1;
}

int isIntersecting(lua_State* L) {
  double v[8];
  numbers(L, v);
  lua_pushboolean(L, tv::bump::isIntersecting({v[0], v[1], v[2], v[3]}, {v[4], v[5], v[6], v[7]}));
  return 1;
}

int getSquareDistance(lua_State* L) {
  double v[8];
  numbers(L, v);
  lua_pushnumber(L, tv::bump::squareDistance({v[0], v[1], v[2], v[3]}, {v[4], v[5], v[6], v[7]}));
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

// (x1,y1,w1,h1, x2,y2,w2,h2 [, goalX, goalY]) -> nil, or bump's collision table
int detectCollision(lua_State* L) {
  const tv::Rect a{checkFinite(L, 1, "x1"), checkFinite(L, 2, "y1"), checkPositive(L, 3, "w1"),
                   checkPositive(L, 4, "h1")};
  const tv::Rect b{checkFinite(L, 5, "x2"), checkFinite(L, 6, "y2"), checkPositive(L, 7, "w2"),
                   checkPositive(L, 8, "h2")};
  const tv::Vec2 goal{optFinite(L, 9, "goalX", a.x), optFinite(L, 10, "goalY", a.y)};
  const tv::Sweep s = tv::bump::detect(a, goal, b);
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
