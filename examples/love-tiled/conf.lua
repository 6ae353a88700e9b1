function love.conf(t)
  t.identity = 'tunnelvision-tiled'
  t.version = '11.4'
  t.window.title = 'Tunnelvision: a Tiled map on tunnelvision.bump'
  t.window.width, t.window.height = 640, 360
  t.modules.audio, t.modules.sound = false, false
  t.modules.joystick, t.modules.physics = false, false
end
