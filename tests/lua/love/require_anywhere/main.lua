-- A game folder holding what README's "From LÖVE" says to ship: tunnelvision.so and
-- tunnelvision/bump.lua (copied in by the test), started from another working directory.
local ok, bump = pcall(require, 'tunnelvision.bump')
if ok then
  print("require 'tunnelvision.bump': " .. bump._VERSION)
  local world = bump.newWorld()
  world:add('a', 0, 0, 1, 1)
  print('world:move', world:move('a', 1, 1))
else
  print("require 'tunnelvision.bump' failed: " .. tostring(bump))
end
love.event.quit(ok and 0 or 1)
