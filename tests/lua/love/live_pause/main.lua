-- A LÖVE game that knows nothing of live streams: a body walks along a floor and the game prints
-- each frame's number as it ends one (tests/lua/live_pause_test.cpp reads them while a receiver
-- pauses, steps and resumes it through TV_LIVE). `love . N` plays N frames (default 400).
local dir = os.getenv('TV_LUA_MODULE_DIR')  -- where the test built tunnelvision.so
if dir then
  package.cpath = dir .. '/?.so;' .. package.cpath
  package.path = dir .. '/?.lua;' .. package.path
end
local bump = require 'tunnelvision.bump'
io.stdout:setvbuf('line')
local frames = tonumber(arg[#arg]) or 400
local world = bump.newWorld(32)
local player = { name = 'player' }
world:add({ name = 'floor' }, 0, 20, 10000, 10)
world:add(player, 0, 0, 8, 8)
local n = 0
function love.update()
  local x = world:getRect(player)
  world:move(player, x + 1, 0)
  n = n + 1
  print('frame ' .. n)
  love.timer.sleep(0.005)  -- a few seconds of play, at most
  if n == frames then love.event.quit(0) end
end
