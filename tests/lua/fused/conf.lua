function love.conf(t)
  t.identity = 'tunnelvision-fused-test'
  t.modules.audio, t.modules.sound, t.modules.joystick, t.modules.physics = false, false, false, false
end
