-- The fast path under LuaJIT (world:move, check, getRect, go and getCollision through the FFI)
-- against the C API it falls back to: the same results, bit for bit, on the same calls; and
-- tunnelvision's own loop (getRect, go, getCollision) with nothing for the collector.
-- The whole suite also runs with TV_LUA_FFI=0 (the C API only) and under PUC Lua 5.1 (no ffi).
local tv = require 'tunnelvision'

-- A value as a string that tells every double apart (-0 from 0) and tables by content.
local function show(v, seen)
  local t = type(v)
  if t == 'number' then
    if v ~= v then return 'nan' end
    if v == 0 and 1 / v < 0 then return '-0' end
    return ('%a'):format(v)
  elseif t == 'table' then
    seen = seen or {}
    if seen[v] then return '<cycle>' end
    seen[v] = true
    local keys = {}
    for k in pairs(v) do keys[#keys + 1] = k end
    table.sort(keys, function(a, b) return tostring(a) < tostring(b) end)
    local parts = {}
    for _, k in ipairs(keys) do
      local key = type(k) == 'table' and (k.name or '<table>') or tostring(k)
      parts[#parts + 1] = key .. '=' .. show(v[k], seen)
    end
    seen[v] = nil
    return '{' .. table.concat(parts, ',') .. '}'
  end
  return tostring(v)
end

local function results(ok, ...)
  local out = { ok and 'ok' or 'error' }
  for i = 1, select('#', ...) do out[#out + 1] = show((select(i, ...))) end
  return table.concat(out, ' ')
end

-- Two worlds made the same way; the second calls the C API's methods (its own fields).
local function pair(newWorld)
  local a, b = newWorld(16), newWorld(16)
  for name, f in pairs(tv._capi) do b[name] = f end
  return a, b
end

-- A small deterministic generator (the same calls on both worlds).
local function rng(seed)
  local s = seed
  return function(n)
    s = (s * 1103515245 + 12345) % 2147483648
    return math.floor(s / 2147483648 * n)
  end
end

local fast = tv.fastPath

describe('the fast path', function()
  it('is on under LuaJIT with ffi (unless TV_LUA_FFI=0) and off in PUC Lua', function()
    local wanted = jit ~= nil and pcall(require, 'ffi') and os.getenv('TV_LUA_FFI') ~= '0'
    assert.equal(wanted, tv.fastPath)
    if fast then
      assert.equal('Lua', debug.getinfo(tv.bump.newWorld().move).what)
      for _, name in ipairs({ 'move', 'check', 'getRect', 'go', 'getCollision' }) do
        assert.equal('C', debug.getinfo(tv._capi[name]).what, name)
      end
    else
      assert.is_nil(tv._capi)
      assert.equal('C', debug.getinfo(tv.bump.newWorld().move).what)
    end
  end)

  --   tiles of 16 in a walled 12x12 field, 30 movers of 6x6 moving up to 20 a call, with and
  --   without filters, touching, crossing, sliding and bouncing: every call's results compared
  for _, rules in ipairs({ 'bump', 'tunnelvision' }) do
    it('gives the C API\'s results bit for bit (' .. rules .. '\'s rules), errors included', function()
      if not fast then return pending('no fast path here: the C API is the only path') end
      local newWorld = rules == 'bump' and tv.bump.newWorld or tv.newWorld
      local a, b = pair(newWorld)
      local rand = rng(7)
      local items = {}
      for _, w in ipairs({ a, b }) do
        for y = 0, 11 do
          for x = 0, 11 do
            if x == 0 or y == 0 or x == 11 or y == 11 or (x * 7 + y * 3) % 5 == 0 then
              w:add({ name = ('tile %d,%d'):format(x, y) }, x * 16, y * 16, 16, 16)
            end
          end
        end
      end
      for i = 1, 30 do
        items[i] = { name = 'mover ' .. i }
        local x, y = 20 + (i * 37) % 140, 20 + (i * 53) % 140
        a:add(items[i], x, y, 6, 6)
        b:add(items[i], x, y, 6, 6)
      end
      local responses = { 'touch', 'cross', 'slide', 'bounce' }
      local filters = {
        false,  -- no filter: the fast path
        function(_, other) return other.name:sub(1, 4) == 'tile' and 'slide' or nil end,
        function(_, other) return responses[1 + #other.name % 4] end,
      }
      local calls = 0
      -- A collection between the twin calls would forget one world's emptied cells and not the
      -- other's (countCells): none runs until both have made every call.
      collectgarbage('stop')
      for _ = 1, 3000 do
        local item = items[1 + rand(30)]
        local filter = filters[1 + rand(3)] or nil
        local op = rand(6)
        local gx, gy = rand(41) - 20, rand(41) - 20
        local ra = results(pcall(a.getRect, a, item))
        assert.equal(ra, results(pcall(b.getRect, b, item)))
        local x, y = a:getRect(item)
        gx, gy = x + gx + rand(4) / 8, y + gy - rand(4) / 8
        local ca, cb
        if op <= 1 then
          ca = results(pcall(a.move, a, item, gx, gy, filter))
          cb = results(pcall(b.move, b, item, gx, gy, filter))
        elseif op == 2 then
          ca = results(pcall(a.check, a, item, gx, gy, filter))
          cb = results(pcall(b.check, b, item, gx, gy, filter))
        elseif op == 3 then
          ca = results(pcall(a.go, a, item, gx, gy, filter))
          cb = results(pcall(b.go, b, item, gx, gy, filter))
          for i = 0, 3 do  -- 0 and one past the end are errors, as is a fraction
            assert.equal(results(pcall(a.getCollision, a, i)), results(pcall(b.getCollision, b, i)))
          end
          assert.equal(results(pcall(a.getCollision, a, 1.5)), results(pcall(b.getCollision, b, 1.5)))
        elseif op == 4 then  -- what the fast path leaves to the C API: the same errors
          local bad = ({ 0 / 0, 1 / 0, '12', {}, nil })[1 + rand(5)]
          ca = results(pcall(a.move, a, item, bad, gy))
          cb = results(pcall(b.move, b, item, bad, gy))
          assert.equal(results(pcall(a.move, a, 'stranger', 1, 2)),
                       results(pcall(b.move, b, 'stranger', 1, 2)))
          assert.equal(results(pcall(a.getRect, a, 0 / 0)), results(pcall(b.getRect, b, 0 / 0)))
          assert.equal(results(pcall(a.move, 'nope', item, 1, 2)), results(pcall(b.move, 'nope', item, 1, 2)))
        else  -- a world in use by its own filter refuses, through either path
          local inner = {}
          ca = results(pcall(a.move, a, item, gx, gy, function()
            inner[1] = results(pcall(a.move, a, item, 0, 0)); return 'slide'
          end))
          cb = results(pcall(b.move, b, item, gx, gy, function()
            inner[2] = results(pcall(b.move, b, item, 0, 0)); return 'slide'
          end))
          assert.equal(inner[1], inner[2])
        end
        assert.equal(ca, cb)
        calls = calls + 1
      end
      assert.equal(a:countCells(), b:countCells())
      collectgarbage('restart')
      collectgarbage('collect')
      assert.equal(a:countCells(), b:countCells())
      assert.equal(a:stateHash(), b:stateHash())
      assert.equal(3000, calls)
    end)
  end

  it('counts cells as bump does: emptied cells until the next collection', function()
    if not fast then return pending('no fast path here') end
    local a, b = pair(tv.bump.newWorld)
    for _, w in ipairs({ a, b }) do
      w:add('p', 1, 1, 4, 4)
      w:move('p', 40, 1)  -- leaves cell 1,1 empty: still counted until a collection
    end
    assert.equal(2, a:countCells())
    assert.equal(b:countCells(), a:countCells())
    collectgarbage('collect')
    assert.equal(1, a:countCells())
    assert.equal(b:countCells(), a:countCells())
  end)
end)

describe('tunnelvision\'s loop (getRect, go, getCollision)', function()
  local function crowd(newWorld)
    local world = newWorld(32)
    local movers = {}
    for i = 0, 199 do world:add({}, (i % 20) * 16, math.floor(i / 20) * 40, 16, 16) end
    for i = 1, 300 do
      local m = { vx = i % 7 - 3, vy = i % 5 - 2 }
      world:add(m, (i % 30) * 11 + 3, (i % 13) * 23 + 20, 8, 8)
      movers[i] = m
    end
    return world, movers
  end
  local function goTick(world, movers)
    local hits = 0
    for k = 1, #movers do
      local m = movers[k]
      local x, y = world:getRect(m)
      local _, _, len = world:go(m, x + m.vx, y + m.vy)
      if len > 0 then
        hits = hits + 1
        local _, _, nx, ny = world:getCollision(1)
        if nx ~= 0 then m.vx = -m.vx end
        if ny ~= 0 then m.vy = -m.vy end
      end
    end
    return hits
  end
  local function moveTick(world, movers)
    for k = 1, #movers do
      local m = movers[k]
      local x, y = world:getRect(m)
      local _, _, cols, len = world:move(m, x + m.vx, y + m.vy)
      if len > 0 then
        if cols[1].normal.x ~= 0 then m.vx = -m.vx end
        if cols[1].normal.y ~= 0 then m.vy = -m.vy end
      end
    end
  end
  -- Over `ticks` ticks after a warm-up, with the collector stopped: how many ticks allocated
  -- anything, and how many bytes in all. LuaJIT itself allocates a few hundred bytes now and then
  -- while it compiles a trace the crowd's changing paths make hot; garbage a call made would show
  -- in every tick.
  local function garbage(tick, world, movers, ticks)
    for _ = 1, 300 do tick(world, movers) end
    collectgarbage('collect')
    collectgarbage('stop')
    local allocating, bytes = 0, 0
    for _ = 1, ticks do
      local before = collectgarbage('count')
      tick(world, movers)
      local grew = collectgarbage('count') - before
      if grew ~= 0 then allocating = allocating + 1 end
      bytes = bytes + grew * 1024
    end
    collectgarbage('restart')
    return allocating, bytes
  end

  it('makes no garbage: the collector\'s count stays flat tick after tick (1000 ticks of 300 moves)', function()
    for _, newWorld in ipairs({ tv.newWorld, tv.bump.newWorld }) do
      local world, movers = crowd(newWorld)
      local hits = 0
      local counted = function(w, ms) hits = hits + goTick(w, ms) end
      local allocating, bytes = garbage(counted, world, movers, 1000)
      assert.is_true(allocating <= 10, allocating .. ' of 1000 ticks allocated')
      assert.is_true(bytes < 16 * 1024, bytes .. ' bytes')
      assert.is_true(hits > 1000)  -- collisions were met and read
    end
  end)

  it('(negative control) bump\'s world:move makes tables, which the same count sees every tick', function()
    local world, movers = crowd(tv.bump.newWorld)
    local allocating, bytes = garbage(moveTick, world, movers, 100)
    assert.equal(100, allocating)
    assert.is_true(bytes > 100 * 300 * 16)
  end)
end)
