-- kikito's bump.lua demo (the `demo` branch of kikito/bump.lua): a platformer in a 4000x2000
-- level of random blocks, guardians that aim at the player along querySegmentWithCoords and
-- throw grenades that bounce, explosions that destroy blocks into debris and push puffs of
-- smoke; Tab draws the grid from world.rows (bump_debug.lua), Return builds a new world.
local dir = debug.getinfo(1, 'S').source:match('^@(.*)/[^/]*$') or '.'
local timeline = dofile(dir .. '/timeline.lua')
return {
  name = 'bump-demo',
  repository = 'https://github.com/kikito/bump.lua',
  commit = '2f3692cb45beec3ff2dcc0bba8e9f34f2fb4b209',
  bump = { 'lib.bump' },
  bumpFile = 'lib/bump.lua',
  frames = 3600,
  input = timeline({
    { 'right', 1, 200 }, { 'up', 150, 230 }, { 'left', 250, 380 }, { 'right', 400, 700 },
    { 'up', 420, 460 }, { 'up', 600, 680 }, { 'left', 800, 1200 }, { 'up', 900, 1000 },
    { 'tab', 1000, 1001 }, { 'up', 1300, 1350 }, { 'right', 1500, 1900 }, { 'tab', 1600, 1601 },
    { 'up', 1700, 1800 }, { 'left', 2000, 2400 }, { 'up', 2200, 2260 }, { 'return', 2500, 2501 },
    { 'right', 2600, 3000 }, { 'tab', 2650, 2651 }, { 'up', 2700, 2800 }, { 'left', 3100, 3500 },
    { 'up', 3200, 3300 },
  }),
  describe = function(item)
    return type(item) == 'table' and item.class and item.class.name or tostring(item)
  end,
}
