-- One-way platforms the way bump.lua games write them: the filter returns 'slide' for a
-- platform only when the body was entirely above it, and nil (or 'cross') otherwise. The filter
-- reads the body's rect with world:getRect, which is where the move started: the idiom is exact
-- at any speed, with bump's rules and with the core's swept movers. y grows downwards.
local tv = require 'tunnelvision'

local TILE = 16

--        x 0                 64
--   y 64 +-------------------+   platform p {0, 64, 64, 4}: one-way, solid from above only
--        +-------------------+
--   y 128 ===================    floor {0, 128, 64, 16}
--
--   body b, 8 x 8, starts at x 20
local function newLevel(make, mover)
  local world = make()
  if mover then world:setMover(mover) end
  local platform = { name = 'platform', oneway = true }
  local floor = { name = 'floor' }
  local body = { name = 'body' }
  world:add(platform, 0, 64, 64, 4)
  world:add(floor, 0, 128, 64, 16)
  local function filter(item, other)
    if other.oneway then
      local _, y, _, h = world:getRect(item)
      local _, oy = world:getRect(other)
      if y + h <= oy then return 'slide' end
      return nil
    end
    return 'slide'
  end
  return world, body, filter
end

-- bump's rules, and the core's with the movers that sweep (discrete teleports: see below).
local function worlds()
  local list = { { 'bump', tv.bump.newWorld } }
  for _, mover in ipairs({ 'sweep', 'substep-sweep', 'continuous', 'adaptive' }) do
    list[#list + 1] = { mover, tv.newWorld, mover }
  end
  return list
end

describe('a one-way platform written as a bump filter', function()
  it('lands a body falling from above at 1 to 10 tiles a move exactly on its top', function()
    for _, w in ipairs(worlds()) do
      for tiles = 1, 10 do
        local world, body, filter = newLevel(w[2], w[3])
        world:add(body, 20, 64 - 8 - 0.5, 8, 8)  -- half a pixel above the top
        local x, y, cols, len = world:move(body, 20 + 3, 64 - 8 - 0.5 + tiles * TILE, filter)
        assert.are.equal(64 - 8, y, w[1] .. ' at ' .. tiles .. ' tiles')
        -- Along the platform, substep-sweep's pieces add up to the goal within rounding.
        assert.is_true(math.abs(x - 23) < 1e-9, w[1] .. ': x = ' .. x)
        -- One landing (substep-sweep reports it again for each later piece, at ti 0).
        assert.is_true(len >= 1)
        for i = 1, len do
          assert.are.equal('platform', cols[i].other.name)
          assert.same({ x = 0, y = -1 }, cols[i].normal)
        end
      end
    end
  end)

  it('lets a body jump up through it at any speed, never snagged', function()
    for _, w in ipairs(worlds()) do
      for tiles = 1, 10 do
        local world, body, filter = newLevel(w[2], w[3])
        world:add(body, 20, 100, 8, 8)  -- between the platform and the floor
        local goalY = 100 - tiles * TILE
        local x, y, _, len = world:move(body, 21, goalY, filter)
        local where = w[1] .. ' at ' .. tiles .. ' tiles: ' .. x .. ', ' .. y
        assert.are.equal(0, len, where)
        assert.is_true(math.abs(x - 21) < 1e-9 and math.abs(y - goalY) < 1e-9, where)
      end
    end
  end)

  it('lets a body that is partly inside it fall on through, to the floor', function()
    for _, w in ipairs(worlds()) do
      local world, body, filter = newLevel(w[2], w[3])
      world:add(body, 20, 60, 8, 8)  -- its bottom 4 px below the top
      local _, y = world:move(body, 20, 60 + 10 * TILE, filter)
      assert.are.equal(128 - 8, y, w[1])
    end
  end)

  it('holds a rider pressed down by gravity, tick after tick, without a pop', function()
    for _, w in ipairs(worlds()) do
      local world, body, filter = newLevel(w[2], w[3])
      world:add(body, 20, 64 - 8, 8, 8)
      local vy = 0
      for _ = 1, 120 do
        vy = vy + 1800 / 60 / 60
        local x, y = world:getRect(body)
        local _, ny, cols = world:move(body, x + 0.25, y + vy, filter)  -- stays on it: 50 px
        assert.are.equal(64 - 8, ny, w[1])
        if #cols > 0 then vy = 0 end
      end
    end
  end)
end)

-- The negative control: a discrete step (teleport, then push out of overlaps) has no "before" to
-- ask about. A fall of more than the platform's thickness plus the body's height lands past it.
describe('a one-way platform with the discrete mover', function()
  it('is fallen through at 10 tiles a move (what the swept movers above never do)', function()
    local world, body, filter = newLevel(tv.newWorld, 'discrete')
    world:add(body, 20, 64 - 8 - 0.5, 8, 8)
    local _, y = world:move(body, 20, 64 - 8 - 0.5 + 10 * TILE, filter)
    assert.is_true(y > 64, 'discrete ended at y = ' .. y)
  end)
end)
