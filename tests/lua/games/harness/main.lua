-- Runs a real LÖVE game unchanged for a number of frames with scripted input, and logs the
-- state of every bump world it creates after each frame. run.sh builds a directory holding
-- links to the game's files (its main.lua and conf.lua as tv_game_main.lua, tv_game_conf.lua)
-- and this file, and says what to do through TV_HARNESS (a Lua file returning a table):
--
--   mode     'bump': the game's own bump.lua (its hash orders fixed, see below);
--            'bump-as-shipped': the same file as it is; 'tunnelvision': `require
--            'tunnelvision.bump'` answers the game's require of bump, nothing else changes
--   profile  the game's profile (profiles/*.lua): its bump module names, keys, frames
--   frames   how many frames to play;  log  where to write the per-frame states
--   dump     frames whose whole state is written out (to explain a difference)
--   moduleDir  where tunnelvision.so and tunnelvision/bump.lua are
--   reference  tests/lua/reference/ordered_bump.lua
--
-- What is made repeatable, so that two runs can be compared frame by frame: the clock (each
-- frame is 1/60 s; love.timer and os.time read the frame count), the input (love.keyboard
-- and the key callbacks follow the profile's script), and — for bump.lua only — the orders it
-- leaves to Lua's hash tables (reference/ordered_bump.lua).

local config = dofile(assert(os.getenv('TV_HARNESS'), 'TV_HARNESS is not set'))
local profile = dofile(config.profile)
local dt = 1 / 60
local frame = 0
local log = assert(io.open(config.log, 'w'))

-- [clock] -------------------------------------------------------------------------------------
if love.timer then
  love.timer.getTime = function() return frame * dt end
  love.timer.getDelta = function() return dt end
  love.timer.getAverageDelta = function() return dt end
  love.timer.getFPS = function() return 60 end
  love.timer.step = function() return dt end
  love.timer.sleep = function() end
end
local realTime = os.time
os.time = function(t) if t then return realTime(t) end return 1500000000 end

-- [input] -------------------------------------------------------------------------------------
local held = {}
if love.keyboard then
  local function isDown(...)
    for i = 1, select('#', ...) do
      local k = select(i, ...)
      if type(k) == 'table' then
        for _, kk in ipairs(k) do if held[kk] then return true end end
      elseif held[k] then
        return true
      end
    end
    return false
  end
  love.keyboard.isDown = isDown
  love.keyboard.isScancodeDown = isDown
end

-- [bump] --------------------------------------------------------------------------------------
local ordered = dofile(config.reference)  -- tests/lua/reference/ordered_bump.lua
local serial = ordered.serial  -- item -> the order in which it was first added
local worlds = {}
local stats = { moves = 0, collisions = 0, mostCollisions = 0, movesOver16 = 0 }

local function instrument(world)
  worlds[#worlds + 1] = world
  local add, move = world.add, world.move
  world.add = function(self, item, ...)
    ordered.remember(item)
    return add(self, item, ...)
  end
  world.move = function(self, ...)
    local x, y, cols, len = move(self, ...)
    stats.moves = stats.moves + 1
    stats.collisions = stats.collisions + len
    if len > stats.mostCollisions then stats.mostCollisions = len end
    if len > 16 then stats.movesOver16 = stats.movesOver16 + 1 end
    return x, y, cols, len
  end
  return world
end

local function wrapModule(real)
  return setmetatable({ newWorld = function(...) return instrument(real.newWorld(...)) end },
                      { __index = real })
end

local function loadReferenceBump()
  if config.mode == 'bump-as-shipped' then return love.filesystem.load(profile.bumpFile)() end
  return ordered.load(assert(love.filesystem.read(profile.bumpFile)), '@' .. profile.bumpFile)
end

local bumpModule
local function provideBump()
  if bumpModule == nil then
    if config.mode == 'tunnelvision' then
      package.cpath = config.moduleDir .. '/?.so;' .. package.cpath
      package.path = config.moduleDir .. '/?.lua;' .. package.path
      bumpModule = wrapModule(require('tunnelvision.bump'))
    else
      bumpModule = wrapModule(loadReferenceBump())
    end
  end
  return bumpModule
end
for _, name in ipairs(profile.bump) do package.preload[name] = provideBump end

-- [the log] -----------------------------------------------------------------------------------
local ffi = require 'ffi'
local bits = ffi.new('union { double d; uint32_t w[2]; }')
local function mix(h1, h2, v)
  bits.d = v
  local lo, hi = bits.w[0], bits.w[1]
  h1 = bit.tobit(h1 * 31 + lo)
  h1 = bit.tobit(h1 * 31 + hi)
  h2 = bit.tobit(h2 * 131 + hi)
  h2 = bit.tobit(h2 * 131 + lo)
  return h1, h2
end

local function sortedItems(world)
  local items, len = world:getItems()
  table.sort(items, function(a, b) return (serial[a] or 0) < (serial[b] or 0) end)
  return items, len
end

local dumps = {}
for _, f in ipairs(config.dump or {}) do dumps[f] = true end

local function writeState()
  local parts = { ('frame %d worlds %d'):format(frame, #worlds) }
  for w, world in ipairs(worlds) do
    local items, len = sortedItems(world)
    -- Two hashes: of the rects bit for bit, and of the rects to the nearest 1e-6 (equal when
    -- the runs differ by rounding only).
    local h1, h2, r1, r2 = 17, 23, 17, 23
    for i = 1, len do
      local x, y, ww, hh = world:getRect(items[i])
      local s = serial[items[i]] or 0
      h1, h2 = mix(h1, h2, s)
      r1, r2 = mix(r1, r2, s)
      for _, v in ipairs({ x, y, ww, hh }) do
        h1, h2 = mix(h1, h2, v)
        r1, r2 = mix(r1, r2, math.floor(v * 1e6 + 0.5))
      end
    end
    parts[#parts + 1] = ('| %d %d %08x%08x ~%08x%08x'):format(w, len, bit.tobit(h1) % 2^32,
      bit.tobit(h2) % 2^32, bit.tobit(r1) % 2^32, bit.tobit(r2) % 2^32)
    if dumps[frame] then
      for i = 1, len do
        local x, y, ww, hh = world:getRect(items[i])
        log:write(('dump %d world %d item %d %s %.17g %.17g %.17g %.17g\n'):format(
          frame, w, serial[items[i]] or 0, profile.describe and profile.describe(items[i]) or '',
          x, y, ww, hh))
      end
    end
  end
  if profile.probe then parts[#parts + 1] = '| ' .. profile.probe() end
  log:write(table.concat(parts, ' '), '\n')
end

-- [the run] -----------------------------------------------------------------------------------
local function press(key, down)
  held[key] = down or nil
  local callback = down and love.keypressed or love.keyreleased
  if callback then callback(key, key, false) end
end

local function finish(how)
  log:write(('end %s moves %d collisions %d mostCollisions %d movesOver16 %d\n'):format(
    how, stats.moves, stats.collisions, stats.mostCollisions, stats.movesOver16))
  log:close()
end

love.errorhandler = function(message)
  local trace = debug.traceback(tostring(message), 2)
  io.stderr:write('game error at frame ', frame, ': ', trace, '\n')
  log:write('error at frame ', frame, ': ', trace:gsub('\n', ' / '), '\n')
  finish('error')
  return nil  -- LÖVE quits
end

love.filesystem.load('tv_game_main.lua')()

function love.run()
  if love.load then love.load(love.arg.parseGameArguments(arg), arg) end
  return function()
    if love.event then
      love.event.pump()
      for name in love.event.poll() do
        if name == 'quit' then finish('quit'); return 0 end
      end
    end
    frame = frame + 1
    for _, e in ipairs(profile.input(frame) or {}) do press(e[2], e[1] == 'press') end
    if love.update then love.update(dt) end
    if love.graphics and love.graphics.isActive() then
      love.graphics.origin()
      love.graphics.clear(love.graphics.getBackgroundColor())
      if love.draw then love.draw() end
      love.graphics.present()
    end
    writeState()
    if frame >= config.frames then
      finish('done')
      return 0
    end
  end
end
