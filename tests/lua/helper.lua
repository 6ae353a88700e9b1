-- busted --helper: makes `require 'tunnelvision'` find the module just built.
local dir = assert(os.getenv('TV_LUA_MODULE_DIR'), 'set TV_LUA_MODULE_DIR to the directory of tunnelvision.so')
package.cpath = dir .. '/?.so;' .. package.cpath
