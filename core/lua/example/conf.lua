function love.conf(t)
  t.identity = 'tunnelvision-platformer'
  t.version = '11.4'
  t.window.title = 'Tunnelvision: a bump.lua platformer'
  t.window.width, t.window.height = 640, 360
  t.modules.audio, t.modules.sound = false, false
  t.modules.joystick, t.modules.physics = false, false
end
