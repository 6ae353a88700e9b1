-- marclurr/love2d-platformer ("Mushroom Massacre"): a platformer on tiny-ecs with a Tiled map,
-- a player that runs, jumps and attacks, mushrooms that walk, pushable stones, switches, spike
-- traps and one-way platforms; its physics system moves with world:move, steps up low ledges
-- with a second move, and snaps to the ground with world:project; triggers use world:check.
-- J starts a new game from the title menu; A/D run, J jumps, K attacks, S drops.
local dir = debug.getinfo(1, 'S').source:match('^@(.*)/[^/]*$') or '.'
local timeline = dofile(dir .. '/timeline.lua')
return {
  name = 'love2d-platformer',
  repository = 'https://github.com/marclurr/love2d-platformer',
  commit = '9e5a87f971d43498b5516a7db8d95a81149473e2',
  bump = { 'lib.bump' },
  bumpFile = 'lib/bump.lua',
  frames = 3600,
  input = timeline({
    { 'j', 30, 34 },                                        -- New Game
    { 'd', 100, 400 }, { 'j', 160, 175 }, { 'k', 300, 304 }, { 'j', 350, 380 },
    { 'a', 450, 600 }, { 'k', 520, 524 }, { 'j', 560, 590 },
    { 'd', 650, 1100 }, { 'j', 700, 720 }, { 'j', 800, 830 }, { 'k', 900, 904 },
    { 'j', 1000, 1030 }, { 's', 1150, 1180 }, { 'a', 1200, 1400 }, { 'j', 1250, 1275 },
    { 'd', 1450, 1900 }, { 'j', 1500, 1530 }, { 'k', 1600, 1604 }, { 'j', 1700, 1740 },
    { 'k', 1800, 1804 }, { 'a', 1950, 2150 }, { 'j', 2000, 2010 }, { 'd', 2200, 2700 },
    { 'j', 2250, 2290 }, { 'j', 2400, 2440 }, { 'k', 2500, 2504 }, { 's', 2600, 2640 },
    { 'a', 2750, 3000 }, { 'j', 2800, 2830 }, { 'd', 3050, 3550 }, { 'j', 3100, 3140 },
    { 'k', 3300, 3304 }, { 'j', 3400, 3440 },
  }),
}
