-- bump's crowd scene from Lua, inside LÖVE (crowd.lua beside this folder does the work):
--
--   love core/lua/bench/love [--quick] [--module-dir build/release/lua] [--bump PATH]
--
-- The same arguments as `luajit core/lua/bench/crowd.lua`; relative paths are taken from the
-- working directory. Prints the same table, from LÖVE's LuaJIT and with its collector's
-- settings, then quits.
function love.load(args)
  local here = love.filesystem.getSource()
  arg = {}
  for i, a in ipairs(args) do arg[i] = a end
  local ok, err = pcall(dofile, here .. '/../crowd.lua')
  if not ok then
    io.stderr:write(tostring(err), '\n')
    love.event.quit(1)
    return
  end
  io.stdout:flush()
  love.event.quit(0)
end
