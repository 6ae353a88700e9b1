-- A game that ships tunnelvision the way core/lua/README.md says ("Shipping a LÖVE game with
-- it"): the module beside the game, found through package.cpath before the first require; the
-- shim tunnelvision/bump.lua inside the .love. tests/lua/fused_game.cmake zips this folder into a
-- .love, fuses it with the love executable, and runs both with the module beside them.
local ext = love.system.getOS() == 'Windows' and 'dll' or 'so'
package.cpath = love.filesystem.getSourceBaseDirectory() .. '/?.' .. ext .. ';' .. package.cpath
local bump = require 'tunnelvision.bump'

function love.load()
  local world = bump.newWorld(16)
  world:add('wall', 100, 0, 2, 100)
  world:add('bullet', 0, 40, 4, 4)
  local x = world:move('bullet', 1000, 40)  -- one move of 1000 px: stops at the 2 px wall
  print(('fused=%s bullet stopped at x=%g'):format(tostring(love.filesystem.isFused()), x))
  love.event.quit(x == 96 and 0 or 1)
end
