-- The crowd benchmark inside LÖVE, headless: no window, no sound, only LÖVE's LuaJIT and its
-- collector as a game has them.
function love.conf(t)
  t.identity = 'tunnelvision-crowd'
  t.version = '11.4'
  t.window = nil
  for _, m in ipairs({ 'window', 'graphics', 'audio', 'sound', 'joystick', 'physics', 'touch',
                       'video', 'image', 'font', 'mouse', 'keyboard' }) do
    t.modules[m] = false
  end
end
