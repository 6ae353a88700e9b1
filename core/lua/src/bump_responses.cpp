// bump.responses.*: the four responses (and `oneway`, ours) with bump.lua's signature
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

// A one-way platform (tv::onewayResponse): bump's slide when the item met its top from entirely
// above it (col.itemRect's bottom at or above col.otherRect's top, not overlapping), else its
// cross. An extension: bump.lua has no such response.
int oneway(lua_State* L) {
  luaL_checktype(L, 2, LUA_TTABLE);
  lua_getfield(L, 2, "overlaps");
  const bool overlapping = lua_toboolean(L, -1);
  lua_pop(L, 1);
  const double ny = fieldNumber(L, 2, "normal", "y"), nx = fieldNumber(L, 2, "normal", "x");
  const double bottom = fieldNumber(L, 2, "itemRect", "y") + fieldNumber(L, 2, "itemRect", "h");
  const double top = fieldNumber(L, 2, "otherRect", "y");
  return !overlapping && nx == 0 && ny == -1 && bottom <= top ? redirect(L, false) : cross(L);
}

}  // namespace

namespace {
// bump's own response functions, by ResponseId: one for each built-in of the core's table.
constexpr lua_CFunction kBumpFunctions[] = {guarded<touch>, guarded<cross>, guarded<slide>,
                                            guarded<bounce>, guarded<oneway>};
static_assert(std::size(kBumpFunctions) == tv::response::kBuiltinCount,
              "every built-in response (tv::kBuiltinResponses) has bump's function here");
}  // namespace

bool isBuiltinResponse(lua_CFunction f, tv::ResponseId& id) {
  if (f == nullptr) return false;
  for (tv::ResponseId i = 0; i < tv::response::kBuiltinCount; ++i) {
    if (f == kBumpFunctions[i]) {
      id = i;
      return true;
    }
  }
  return false;
}

void pushResponseFunctions(lua_State* L) {
  lua_createtable(L, 0, tv::response::kBuiltinCount);
  for (tv::ResponseId i = 0; i < tv::response::kBuiltinCount; ++i) {
    lua_pushcfunction(L, kBumpFunctions[i]);
    const std::string_view name = tv::kBuiltinResponses[i].name;
    lua_pushlstring(L, name.data(), name.size());
    lua_insert(L, -2);
    lua_rawset(L, -3);
  }
}

}  // namespace tvlua
