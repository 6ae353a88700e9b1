function love.conf(t)
  t.identity = 'tunnelvision-require-anywhere'
  t.window = nil
  t.modules.window, t.modules.graphics, t.modules.audio, t.modules.sound = false, false, false, false
end
