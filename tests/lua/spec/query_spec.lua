-- bump.lua's queries: queryRect, queryPoint, querySegment, querySegmentWithCoords, with their
-- one-argument filters. Results are fresh arrays in add order (segments: along the segment).
local bump = require 'tunnelvision.bump'

--   y 0  +---a---+          a (0,0 10x10)
--        |     +-|--b--+    b (5,5 10x10)
--     10 +-----|-+     |    c (20,0 5x5)
--              +-------+
local function scene()
  local world = bump.newWorld(8)
  world:add('a', 0, 0, 10, 10)
  world:add('b', 5, 5, 10, 10)
  world:add('c', 20, 0, 5, 5)
  return world
end

describe('world:queryRect', function()
  it('returns the items whose interiors overlap the rect, and their count', function()
    local world = scene()
    assert.same({ { 'a', 'b' }, 2 }, { world:queryRect(4, 4, 2, 2) })
    assert.same({ { 'b' }, 1 }, { world:queryRect(11, 11, 1, 1) })
    assert.same({ {}, 0 }, { world:queryRect(100, 100, 1, 1) })
  end)

  it('touching is not overlapping', function()
    local world = scene()
    assert.same({}, (world:queryRect(25, 0, 5, 5)))   -- shares c's right edge
  end)

  it('filters with filter(item)', function()
    local world = scene()
    assert.same({ 'b' }, (world:queryRect(0, 0, 30, 30, function(item) return item == 'b' end)))
  end)

  it('checks its arguments', function()
    local world = scene()
    assert.has_error(function() world:queryRect(0, 0, -1, 1) end, 'w must be a positive number, but was -1')
    assert.has_error(function() world:queryRect(0, 0, 1, 1, 'x') end, "filter must be a function, but was 'x' (a string)")
  end)

  it('a raising filter propagates its error', function()
    local world = scene()
    assert.has_error(function() world:queryRect(0, 0, 30, 30, function() error('stop') end) end)
    assert.same({ 'a', 'b', 'c' }, (world:queryRect(0, 0, 30, 30)))
  end)
end)

describe('world:queryPoint', function()
  it('returns the items containing the point', function()
    local world = scene()
    assert.same({ { 'a', 'b' }, 2 }, { world:queryPoint(7, 7) })
    assert.same({ { 'c' }, 1 }, { world:queryPoint(21, 1) })
    assert.same({ 'c' }, (world:queryPoint(21, 1, function(i) return i == 'c' end)))
    assert.same({}, (world:queryPoint(17, 17)))
  end)
end)

describe('world:querySegment', function()
  --   the segment (−5, 7) -> (30, 7) crosses a, then b; c is above it
  it('returns the items the segment crosses, in the order it meets them', function()
    local world = scene()
    assert.same({ { 'a', 'b' }, 2 }, { world:querySegment(-5, 7, 30, 7) })
    assert.same({ { 'b', 'a' }, 2 }, { world:querySegment(30, 7, -5, 7) })
    assert.same({ 'b' }, (world:querySegment(-5, 7, 30, 7, function(i) return i ~= 'a' end)))
  end)

  it('WithCoords adds where it enters and leaves each: ti1, ti2, x1, y1, x2, y2', function()
    local world = scene()
    -- from x = -5 to 35 along y = 2: a over [0, 10] (t 0.125..0.375), c over [20, 25] (t 0.625..0.75)
    local info, len = world:querySegmentWithCoords(-5, 2, 35, 2)
    assert.equal(2, len)
    assert.same({ item = 'a', ti1 = 0.125, ti2 = 0.375, x1 = 0, y1 = 2, x2 = 10, y2 = 2 }, info[1])
    assert.same({ item = 'c', ti1 = 0.625, ti2 = 0.75, x1 = 20, y1 = 2, x2 = 25, y2 = 2 }, info[2])
  end)
end)
