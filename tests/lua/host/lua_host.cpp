// A Lua 5.1 interpreter with the tunnelvision module linked in rather than loaded, so that the
// module runs under the sanitizers this host is built with (an uninstrumented lua5.1 or luajit
// cannot load an instrumented .so). Usage: tv-lua-host script.lua [args...] — e.g. busted's
// runner with the spec folder. The state is closed at the end, os.exit included, so every
// world's __gc runs and LeakSanitizer sees what the module failed to free.

#include <cstdio>
#include <cstring>

#include <lua.hpp>

extern "C" int luaopen_tunnelvision(lua_State* L);
extern "C" int luaopen_tunnelvision_bump(lua_State* L);

namespace {

int exitCode = 0;
const char* const kExitTag = "tv-lua-host exit";

// os.exit(code): unwind to main with a marker instead of exiting with the state open.
int hostExit(lua_State* L) {
  if (lua_isboolean(L, 1)) {
    exitCode = lua_toboolean(L, 1) ? 0 : 1;
  } else {
    exitCode = static_cast<int>(luaL_optinteger(L, 1, 0));
  }
  lua_pushstring(L, kExitTag);
  return lua_error(L);
}

int traceback(lua_State* L) {
  lua_getglobal(L, "debug");
  lua_getfield(L, -1, "traceback");
  lua_pushvalue(L, 1);
  lua_pushinteger(L, 2);
  lua_call(L, 2, 1);
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s script.lua [args...]\n", argv[0]);
    return 2;
  }
  lua_State* L = luaL_newstate();
  luaL_openlibs(L);
  lua_getglobal(L, "package");
  lua_getfield(L, -1, "preload");
  lua_pushcfunction(L, luaopen_tunnelvision);
  lua_setfield(L, -2, "tunnelvision");
  lua_pushcfunction(L, luaopen_tunnelvision_bump);
  lua_setfield(L, -2, "tunnelvision.bump");
  lua_pop(L, 2);
  lua_getglobal(L, "os");
  lua_pushcfunction(L, hostExit);
  lua_setfield(L, -2, "exit");
  lua_pop(L, 1);
  lua_createtable(L, argc, 0);
  for (int i = 1; i < argc; ++i) {
    lua_pushstring(L, argv[i]);
    lua_rawseti(L, -2, i - 1);
  }
  lua_setglobal(L, "arg");

  lua_pushcfunction(L, traceback);
  if (luaL_loadfile(L, argv[1]) != 0) {
    std::fprintf(stderr, "%s\n", lua_tostring(L, -1));
    lua_close(L);
    return 2;
  }
  for (int i = 2; i < argc; ++i) lua_pushstring(L, argv[i]);
  if (lua_pcall(L, argc - 2, 0, 1) != 0) {
    const char* msg = lua_tostring(L, -1);
    if (msg == nullptr || std::strstr(msg, kExitTag) == nullptr) {
      std::fprintf(stderr, "%s\n", msg ? msg : "(error object is not a string)");
      exitCode = 1;
    }
  }
  lua_close(L);
  return exitCode;
}
