// bump.responses.*: the four responses with bump.lua's signature
// fn(world, col, x,y,w,h, goalX, goalY, filter) -> goalX, goalY, cols, len, callable directly
// (and usable in world:addResponse), as bump defines them. slide and bounce write col.slide /
// col.bounce. A world's moves run the same rules in the core (core/src/bump_move.cpp).

#include "boundary.hpp"
#include "lua_world.hpp"

namespace tvlua {
namespace {

double fieldNumber(lua_State* L, int table, const char* outer, const char* inner) {
  lua_getfield(L, table, outer);
  if (!lua_istable(L, -1)) luaL_error(L, "col.%s must be a table, but was a %s", outer, luaL_typename(L, -1));
  lua_getfield(L, -1, inner);
  if (lua_type(L, -1) != LUA_TNUMBER) {
    luaL_error(L, "col.%s.%s must be a number, but was a %s", outer, inner, luaL_typename(L, -1));
  }
  const double v = lua_tonumber(L, -1);
  lua_pop(L, 2);
  return v;
}

// world:project(col.item, x,y,w,h, goalX, goalY, filter) from the leg's new start; pushes
// cols, len.
void projectFrom(lua_State* L, double x, double y, double goalX, double goalY) {
  lua_getfield(L, 1, "project");
  lua_pushvalue(L, 1);
  lua_getfield(L, 2, "item");
  lua_pushnumber(L, x);
  lua_pushnumber(L, y);
  lua_pushvalue(L, 5);
  lua_pushvalue(L, 6);
  lua_pushnumber(L, goalX);
  lua_pushnumber(L, goalY);
  lua_pushvalue(L, 9);
  lua_call(L, 9, 2);
}

int touch(lua_State* L) {
  luaL_checktype(L, 2, LUA_TTABLE);
  lua_pushnumber(L, fieldNumber(L, 2, "touch", "x"));
  lua_pushnumber(L, fieldNumber(L, 2, "touch", "y"));
  lua_newtable(L);
  lua_pushinteger(L, 0);
  return 4;
}

// bump projects a cross again from x,y (the item's rect before the move), to the same goal.
int cross(lua_State* L) {
  luaL_checktype(L, 2, LUA_TTABLE);
  lua_settop(L, 9);
  const double x = luaL_checknumber(L, 3), y = luaL_checknumber(L, 4);
  const double gx = luaL_optnumber(L, 7, x), gy = luaL_optnumber(L, 8, y);
  lua_pushvalue(L, 7);  // the goal as given (nil stays nil, as in bump)
  lua_pushvalue(L, 8);
  projectFrom(L, x, y, gx, gy);
  return 4;
}

// slide: the goal keeps its coordinate along the surface and takes the contact's on the
// normal's axis (when the item moved at all); bounce: what is left of the move after the
// contact, mirrored on the normal's axis (the contact itself when it did not move). Both write
// col[field] and project from the contact.
int redirect(lua_State* L, bool bounce) {
  luaL_checktype(L, 2, LUA_TTABLE);
  lua_settop(L, 9);
  const double x = luaL_checknumber(L, 3), y = luaL_checknumber(L, 4);
  double gx = luaL_optnumber(L, 7, x), gy = luaL_optnumber(L, 8, y);
  const double tx = fieldNumber(L, 2, "touch", "x"), ty = fieldNumber(L, 2, "touch", "y");
  const double mx = fieldNumber(L, 2, "move", "x"), my = fieldNumber(L, 2, "move", "y");
  const double nx = fieldNumber(L, 2, "normal", "x");
  const bool moving = mx != 0 || my != 0;
  if (!bounce) {
    if (moving) {
      if (nx != 0) {
        gx = tx;
      } else {
        gy = ty;
      }
    }
  } else {
    double bx = tx, by = ty;
    if (moving) {
      double dx = gx - tx, dy = gy - ty;
      if (nx == 0) {
        dy = -dy;
      } else {
        dx = -dx;
      }
      bx = tx + dx;
      by = ty + dy;
    }
    gx = bx;
    gy = by;
  }
  lua_createtable(L, 0, 2);
  lua_pushnumber(L, gx);
  lua_setfield(L, -2, "x");
  lua_pushnumber(L, gy);
  lua_setfield(L, -2, "y");
  lua_setfield(L, 2, bounce ? "bounce" : "slide");
  lua_pushnumber(L, gx);
  lua_pushnumber(L, gy);
  projectFrom(L, tx, ty, gx, gy);
  return 4;
}

int slide(lua_State* L) { return redirect(L, false); }
int bounce(lua_State* L) { return redirect(L, true); }

}  // namespace

bool isBuiltinResponse(lua_CFunction f, tv::ResponseId& id) {
  if (f == nullptr) return false;
  const lua_CFunction fns[] = {guarded<touch>, guarded<cross>, guarded<slide>, guarded<bounce>};
  for (tv::ResponseId i = 0; i < 4; ++i) {
    if (f == fns[i]) {
      id = i;
      return true;
    }
  }
  return false;
}

void pushResponseFunctions(lua_State* L) {
  lua_createtable(L, 0, 4);
  lua_pushcfunction(L, guarded<touch>);
  lua_setfield(L, -2, "touch");
  lua_pushcfunction(L, guarded<cross>);
  lua_setfield(L, -2, "cross");
  lua_pushcfunction(L, guarded<slide>);
  lua_setfield(L, -2, "slide");
  lua_pushcfunction(L, guarded<bounce>);
  lua_setfield(L, -2, "bounce");
}

}  // namespace tvlua
