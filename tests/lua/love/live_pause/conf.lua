function love.conf(t)
  t.identity = 'tunnelvision-live-pause'
  t.window = nil
  t.modules.window, t.modules.graphics, t.modules.audio, t.modules.sound = false, false, false, false
end
