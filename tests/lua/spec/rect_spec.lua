-- bump.rect.* and bump.responses.*, called directly as bump's own specs do.
local bump = require 'tunnelvision.bump'
local rect = bump.rect

describe('bump.rect', function()
  it('getNearestCorner', function()
    assert.same({ 0, 0 }, { rect.getNearestCorner(0, 0, 10, 10, 1, 1) })
    assert.same({ 10, 10 }, { rect.getNearestCorner(0, 0, 10, 10, 9, 6) })
  end)

  it('getDiff: the Minkowski difference', function()
    assert.same({ 1, 1, 4, 4 }, { rect.getDiff(0, 0, 2, 2, 3, 3, 2, 2) })
  end)

  it('containsPoint excludes the edges (with bump\'s 1e-10 margin)', function()
    assert.is_true(rect.containsPoint(0, 0, 10, 10, 5, 5))
    assert.is_false(rect.containsPoint(0, 0, 10, 10, 0, 5))
    assert.is_false(rect.containsPoint(0, 0, 10, 10, 10 - 1e-11, 5))
  end)

  it('isIntersecting: interiors overlap', function()
    assert.is_true(rect.isIntersecting(0, 0, 2, 2, 1, 1, 2, 2))
    assert.is_false(rect.isIntersecting(0, 0, 2, 2, 2, 0, 2, 2))
  end)

  it('getSquareDistance between centres', function()
    assert.equal(25, rect.getSquareDistance(0, 0, 2, 2, 3, 4, 2, 2))
  end)

  it('getSegmentIntersectionIndices: entry and exit along the segment, and their normals', function()
    -- rect (0,0 10x10), segment (-10,5) -> (20,5): enters at t = 1/3 through the left side,
    -- leaves at t = 2/3 through the right side
    local t1, t2, nx1, ny1, nx2, ny2 = rect.getSegmentIntersectionIndices(0, 0, 10, 10, -10, 5, 20, 5)
    assert.same({ 1 / 3, 2 / 3, -1, 0, 1, 0 }, { t1, t2, nx1, ny1, nx2, ny2 })
    assert.is_nil(rect.getSegmentIntersectionIndices(0, 0, 10, 10, -10, 20, 20, 20))
  end)

  --   item (0,0 1x1) moving to (4,0), other (2,0 1x1): contact when 1 + 4t = 2, ti = 0.25
  it('detectCollision: nil, or bump\'s collision table', function()
    assert.is_nil(rect.detectCollision(0, 0, 1, 1, 5, 5, 1, 1, 1, 0))
    assert.same({
      overlaps = false, ti = 0.25, move = { x = 4, y = 0 }, normal = { x = -1, y = 0 },
      touch = { x = 1, y = 0 }, itemRect = { x = 0, y = 0, w = 1, h = 1 },
      otherRect = { x = 2, y = 0, w = 1, h = 1 },
    }, rect.detectCollision(0, 0, 1, 1, 2, 0, 1, 1, 4, 0))
    -- overlapping, not moving: ti is minus the area of the intersection (1x2)
    local col = rect.detectCollision(0, 0, 2, 2, 1, 0, 2, 2)
    assert.is_true(col.overlaps)
    assert.equal(-2, col.ti)
    -- ti is exact: 0.6 compares equal
    assert.equal(0.6, rect.detectCollision(0, 0, 1, 1, 0, 4, 1, 1, 0, 5).ti)
  end)
end)

describe('bump.responses', function()
  local function setup()
    local world = bump.newWorld()
    world:add('a', 0, 0, 1, 1)
    world:add('b', 0, 2, 10, 1)
    local col = bump.rect.detectCollision(0, 0, 1, 1, 0, 2, 10, 1, 4, 5)
    col.item, col.other = 'a', 'b'
    return world, col
  end

  it('touch returns the touch point and no further collisions', function()
    local world, col = setup()
    assert.same({ 0.8, 1, {}, 0 }, { bump.responses.touch(world, col, 0, 0, 1, 1, 4, 5) })
  end)

  it('cross keeps the goal and lists what the rest of the leg meets', function()
    local world, col = setup()
    local gx, gy, cols, len = bump.responses.cross(world, col, 0, 0, 1, 1, 4, 5, function(_, o) return o ~= 'b' and 'slide' end)
    assert.same({ 4, 5, 0 }, { gx, gy, len })
    assert.same({}, cols)
  end)

  it('slide writes col.slide and projects from the touch point', function()
    local world, col = setup()
    local gx, gy, _, len = bump.responses.slide(world, col, 0, 0, 1, 1, 4, 5)
    assert.same({ 4, 1, 0 }, { gx, gy, len })
    assert.same({ x = 4, y = 1 }, col.slide)
  end)

  it('bounce writes col.bounce', function()
    local world, col = setup()
    local gx, gy = bump.responses.bounce(world, col, 0, 0, 1, 1, 4, 5)
    assert.same({ 4, -3 }, { gx, gy })
    assert.same({ x = 4, y = -3 }, col.bounce)
  end)
end)
