-- busted --helper for bump.lua's own spec suite: `require 'bump'` gets tunnelvision.bump.
local dir = assert(os.getenv('TV_LUA_MODULE_DIR'), 'set TV_LUA_MODULE_DIR to the directory of tunnelvision.so')
package.cpath = dir .. '/?.so;' .. package.cpath
package.path = dir .. '/?.lua;' .. package.path
package.preload['bump'] = function() return require('tunnelvision.bump') end
