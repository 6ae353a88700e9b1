-- The game's own conf.lua (linked in as tv_game_conf.lua), then what a headless, repeatable run
-- needs: no vsync wait, a window (SDL's offscreen driver gives it a real GL context), and a save
-- directory of the harness's own.
if love.filesystem.getInfo('tv_game_conf.lua') then love.filesystem.load('tv_game_conf.lua')() end
local gameConf = love.conf
function love.conf(t)
  if gameConf then gameConf(t) end
  t.identity = 'tunnelvision-game-harness'
  t.console = false
  if t.window then
    t.window.vsync = 0
    t.window.fullscreen = false
  end
end
