-- The crowd from Lua: N movers of 8x8 among 16x16 tiles (30% solid, walled) in a 2000x2000
-- world, one move each per tick with slide, driven through tunnelvision.bump (world:move, which
-- must return bump's tables) and through tunnelvision's world:go (no garbage). Prints ms per
-- tick, garbage per tick and the cost of a call from Lua into the module.
--
--   luajit core/lua/bench/crowd.lua [--quick] [--module-dir build/release/lua] [--bump PATH]
--   (--bump: also bump.lua itself, from a file of yours, in the same run)
--   lua5.1 core/lua/bench/crowd.lua ...          (PUC Lua, for comparison)
local moduleDir, quick, bumpPath = 'build/release/lua', false, nil
local i = 1
while arg and arg[i] do
  if arg[i] == '--quick' then quick = true
  elseif arg[i] == '--module-dir' then moduleDir = arg[i + 1]; i = i + 1
  elseif arg[i] == '--bump' then bumpPath = arg[i + 1]; i = i + 1
  else error('unknown argument ' .. arg[i] .. ' (expected --quick, --module-dir DIR, --bump PATH)') end
  i = i + 1
end
package.cpath = moduleDir .. '/?.so;' .. package.cpath
local tv = require 'tunnelvision'

local TILE, SIZE, SPEED, SIDE = 16, 8, 2, 125   -- 125 tiles of 16 = 2000 px

-- A small deterministic generator (the same scene in every VM).
local function rng(seed)
  local s = seed
  return function()
    s = (s * 1103515245 + 12345) % 2147483648
    return s / 2147483648
  end
end

-- newWorld: tunnelvision.bump's (bump.lua's rules) or tunnelvision's (the core's).
local function build(count, newWorld)
  local rand = rng(20240601)
  local world = newWorld(32)
  local free = {}
  for ty = 0, SIDE - 1 do
    for tx = 0, SIDE - 1 do
      local wall = tx == 0 or ty == 0 or tx == SIDE - 1 or ty == SIDE - 1
      if wall or rand() < 0.3 then
        world:add({ tile = true }, tx * TILE, ty * TILE, TILE, TILE)
      else
        free[#free + 1] = { tx, ty }
      end
    end
  end
  assert(#free >= count, ('only %d free tiles for %d movers'):format(#free, count))
  for k = #free, 2, -1 do  -- shuffle, then take the first `count`
    local j = 1 + math.floor(rand() * k)
    free[k], free[j] = free[j], free[k]
  end
  local movers = {}
  for k = 1, count do
    local a = rand() * 2 * math.pi
    local m = { vx = math.cos(a) * SPEED, vy = math.sin(a) * SPEED }
    world:add(m, free[k][1] * TILE + 4, free[k][2] * TILE + 4, SIZE, SIZE)
    movers[k] = m
  end
  return world, movers
end

-- One tick through the bump API: bump's results, a new direction on a hit.
local function tickBump(world, movers)
  for k = 1, #movers do
    local m = movers[k]
    local x, y = world:getRect(m)
    local _, _, cols, len = world:move(m, x + m.vx, y + m.vy)
    if len > 0 then
      local n = cols[1].normal
      if n.x ~= 0 then m.vx = -m.vx end
      if n.y ~= 0 then m.vy = -m.vy end
    end
  end
end

-- The same through world:go and getCollision: multiple returns only.
local function tickGo(world, movers)
  for k = 1, #movers do
    local m = movers[k]
    local x, y = world:getRect(m)
    local _, _, len = world:go(m, x + m.vx, y + m.vy)
    if len > 0 then
      local _, _, nx, ny = world:getCollision(1)
      if nx ~= 0 then m.vx = -m.vx end
      if ny ~= 0 then m.vy = -m.vy end
    end
  end
end

local function measure(count, tick, ticks, newWorld)
  local world, movers = build(count, newWorld)
  for _ = 1, 20 do tick(world, movers) end  -- warm up (traces, core buffers)
  collectgarbage('collect')
  -- garbage: a few ticks with the collector stopped
  collectgarbage('stop')
  local before = collectgarbage('count')
  for _ = 1, 5 do tick(world, movers) end
  local garbage = (collectgarbage('count') - before) / 5
  collectgarbage('restart')
  collectgarbage('collect')
  -- time: the collector running, as in a game
  local best = math.huge
  for _ = 1, 3 do
    local t0 = os.clock()
    for _ = 1, ticks do tick(world, movers) end
    best = math.min(best, (os.clock() - t0) / ticks)
  end
  return best * 1000, garbage
end

local function callCost()
  local world = tv.newWorld()
  local item = {}
  world:add(item, 0, 0, 1, 1)
  local n = quick and 200000 or 5000000
  local function timeIt(f)
    local best = math.huge
    for _ = 1, 3 do
      local t0 = os.clock()
      f()
      best = math.min(best, os.clock() - t0)
    end
    return best / n * 1e9
  end
  local empty = timeIt(function() for _ = 1, n do end end)
  local count = timeIt(function() for _ = 1, n do world:countItems() end end)
  local rect = timeIt(function() for _ = 1, n do world:getRect(item) end end)
  return count - empty, rect - empty
end

local vm = jit and jit.version or _VERSION
print(('crowd from Lua (%s)%s'):format(vm, quick and ', --quick' or ''))
print('')
print('| movers | API | ms/tick | garbage KB/tick | bytes/move |')
print('|---:|---|---:|---:|---:|')
for _, count in ipairs(quick and { 1000 } or { 1000, 10000 }) do
  local ticks = quick and 5 or (count >= 10000 and 30 or 100)
  local apis = { { 'tunnelvision.bump  world:move', tickBump, tv.bump.newWorld },
                 { 'tunnelvision  world:move', tickBump, tv.newWorld },
                 { 'tunnelvision  world:go', tickGo, tv.newWorld } }
  if bumpPath then table.insert(apis, 1, { 'bump.lua  world:move', tickBump, dofile(bumpPath).newWorld }) end
  for _, api in ipairs(apis) do
    local ms, kb = measure(count, api[2], ticks, api[3])
    print(('| %d | %s | %.2f | %.1f | %.1f |'):format(count, api[1], ms, kb, kb * 1024 / count))
  end
end
local c1, c2 = callCost()
print('')
print(('Lua -> C call: %.1f ns (world:countItems()), %.1f ns (world:getRect(item): + item lookup)'):format(c1, c2))
