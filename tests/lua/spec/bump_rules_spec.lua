-- tunnelvision.bump follows bump.lua 3.1.7's rules as its source defines them: overlapping
-- starts, tie-breaks, the push back against a move, slide and bounce on overlaps, collision
-- order, cross projected from the move's start, bump's queries; and where it decides what bump
-- leaves to rounding or hash order (core/lua/README.md). y grows downwards.
local bump = require 'tunnelvision.bump'
local tv = require 'tunnelvision'
local detect = bump.rect.detectCollision

local function touch(...)
  local c = detect(...)
  return { c.touch.x, c.touch.y, c.normal.x, c.normal.y }
end

describe('bump.rect.detectCollision on an overlapping start', function()
  --   item (0,0 7x6) already holds other (5,5 1x1) in its corner
  --   +-------+     the Minkowski difference's nearest corner is (-2, -1): ti is minus
  --   |       |     the area of the minimum displacement, min(7, 2) * min(6, 1) = -2
  --   |     # |     (not minus the overlap's area, -1)
  --   +-------+
  it('has ti = minus the area of the minimum displacement', function()
    local c = detect(0, 0, 7, 6, 5, 5, 1, 1, 0, 0)
    assert.is_true(c.overlaps)
    assert.equal(-2, c.ti)
  end)

  --   a 2x2 item centred in an 8x8 one:    0 1 2 3 4 5 6 7 8
  --   four ways out of equal length; bump  . . . . . . . . .
  --   goes down (0, 1) when still          . . . +-+ . . . .
  --                                        . . . |i| . . . .
  --                                        . . . +-+ . . . .
  it('breaks a still tie the vertical way, down', function()
    assert.same({ 3, 8, 0, 1 }, touch(3, 3, 2, 2, 0, 0, 8, 8))
  end)

  it('pushes a moving item back against its movement', function()
    assert.same({ -2, 3, -1, 0 }, touch(3, 3, 2, 2, 0, 0, 8, 8, 4, 3))   -- moving right: out left
    assert.same({ 8, 3, 1, 0 }, touch(3, 3, 2, 2, 0, 0, 8, 8, 2, 3))     -- moving left: out right
    assert.same({ 3, -2, 0, -1 }, touch(3, 3, 2, 2, 0, 0, 8, 8, 3, 4))   -- moving down: out up
    assert.same({ 3, 8, 0, 1 }, touch(3, 3, 2, 2, 0, 0, 8, 8, 3, 2))     -- moving up: out down
  end)

  it('slides and bounces from where an overlap is pushed out to', function()
    local world = bump.newWorld()
    local c = detect(3, 3, 2, 2, 0, 0, 8, 8, 4, 5)
    bump.responses.slide(world, c, 3, 3, 2, 2, 4, 5)
    assert.same({ x = 0.5, y = -2 }, c.touch)
    assert.same({ x = 4, y = -2 }, c.slide)
    c = detect(3, 3, 2, 2, 0, 0, 8, 8, 4, 5)
    bump.responses.bounce(world, c, 3, 3, 2, 2, 4, 5)
    assert.same({ x = 4, y = -9 }, c.bounce)
  end)
end)

describe('a contact is never inside what it touched', function()
  --   a body 13.7 tall falling from y 64.589 by 32.82 onto a floor at y 100: bump.lua's
  --   start + ti * move is 86.300000000000011, whose bottom is past 100 — a step inside the
  --   floor, which is what stops a body at the next tile's seam. Here the bottom is on 100.
  it('against bump.lua\'s rounding, placing the body on the edge', function()
    local y, dy = 64.588999999999999, 32.82
    local c = detect(0, y, 10, 13.7, 0, 100, 16, 16, 0, y + dy)
    assert.equal(0.6615173674588668, c.ti)           -- bump's ti, bit for bit
    assert.is_true(y + dy * c.ti + 13.7 > 100)       -- negative control: bump's point is inside
    assert.equal(100, c.touch.y + 13.7)
  end)

  --   a body 13.7 tall walks over 1000 separate 16 px tiles under gravity
  it('so a body walking over tile seams never stops at one', function()
    local world = bump.newWorld(64)
    for i = 0, 999 do world:add({}, i * 16, 100, 16, 16) end
    local p = {}
    world:add(p, 0, 86.3, 10, 13.7)
    local vy, x, y = 0, 0, 86.3
    for _ = 1, 3000 do
      vy = vy + 9.8 / 60
      local cols, len
      x, y, cols, len = world:move(p, x + 3, y + vy)
      for i = 1, len do if cols[i].normal.y ~= 0 then vy = 0 end end
    end
    assert.equal(9000, x)
  end)
end)

describe('the order of collisions', function()
  --   the item falls on two tiles at the same ti:      . . i i . . .
  --   nearer centre first; at equal distances, the     . . i i . . .
  --   one added first (bump.lua: hash order)           A A A A B B B B
  it('is ti, then distance between centres, then add order', function()
    for _, aFirst in ipairs({ true, false }) do
      local world = bump.newWorld()
      if aFirst then
        world:add('A', 0, 10, 8, 8); world:add('B', 8, 10, 8, 8)
      else
        world:add('B', 8, 10, 8, 8); world:add('A', 0, 10, 8, 8)
      end
      world:add('centred', 4, 0, 8, 8)
      local cols = world:project('centred', 4, 0, 8, 8, 4, 5)
      assert.equal(aFirst and 'A' or 'B', cols[1].other)
      cols = world:project(nil, 3, 20, 8, 8, 3, 5)   -- moving up from below, centre 7: A nearer
      assert.equal('A', cols[1].other)
    end
  end)

  --   cross: bump projects again from where the move began
  --   the item (0,0 10x10) heads for (50,30); it slides on the floor f (y 20) and its slide
  --   leg crosses the cloud c; the cloud's collision is measured from the slide's contact
  it('runs a cross\'s next leg from the move\'s start, as bump does', function()
    local world = bump.newWorld()
    world:add('f', 0, 20, 100, 10)
    world:add('c', 30, 0, 4, 40)
    world:add('i', 0, 0, 10, 10)
    local x, y, cols, len = world:move('i', 50, 30, function(_, o) return o == 'c' and 'cross' or 'slide' end)
    assert.same({ 50, 10, 2 }, { x, y, len })
    assert.same({ 'f', 'c' }, { cols[1].other, cols[2].other })
    assert.same({ x = 50 * (10 / 30), y = 10, w = 10, h = 10 }, cols[2].itemRect)
  end)
end)

describe('a move never passes into what it already met', function()
  --   a ball 2 wide in a slot 4 wide, moving 64 right, bouncing:
  --   l 0..16 | ball 17..19 | r 20..36
  --   it meets r, then l; its third leg heads into r again, which bump.lua (having visited
  --   r) lets it pass through to x = 77. Here the move ends against r: one more collision.
  it('a ball bouncing in a slot narrower than its step stays in the slot', function()
    local world = bump.newWorld()
    world:add('l', 0, 0, 16, 64)
    world:add('r', 20, 0, 16, 64)
    world:add('ball', 17, 30, 2, 2)
    local x, y, cols, len = world:move('ball', 81, 30, function() return 'bounce' end)
    assert.same({ 18, 30, 3 }, { x, y, len })
    assert.same({ 'r', 'l', 'r' }, { cols[1].other, cols[2].other, cols[3].other })
    assert.same({ x = 77, y = 30 }, cols[2].bounce)
    -- negative control: bump's own third leg, from the contact with l to (77, 30), hits r
    assert.is_not_nil(detect(16, 30, 2, 2, 20, 0, 16, 64, 77, 30))
  end)
end)

-- Bodies spawned inside solids, moving as debris does (gravity, bounce): out in a frame or
-- two, never meeting an item twice in a move. Negative control: the core's own rules
-- (tunnelvision.newWorld) bounce a body caught across two blocks 64 times a move, for ever.
local function spawns()
  local out = { { what = 'inside one block', blocks = { { 0, 0, 64, 64 } }, body = { 20, 20, 6, 6 } } }
  for gap = 0, 4 do
    --   [ block ]gap[ block ]     the body, 8 wide, straddles the gap
    out[#out + 1] = { what = 'across two blocks ' .. gap .. ' px apart',
                      blocks = { { 0, 0, 32, 64 }, { 32 + gap, 0, 32, 64 } },
                      body = { 32 + gap / 2 - 4, 20, 8, 8 } }
  end
  local pile = { what = 'inside a pile', blocks = {}, body = { 121, 121, 6, 6 } }
  for i = 0, 2 do
    for j = 0, 2 do pile.blocks[#pile.blocks + 1] = { 100 + i * 16, 100 + j * 16, 16, 16 } end
  end
  out[#out + 1] = pile
  return out
end

local function play(newWorld, spawn, answer)
  local world = newWorld(64)
  for i, b in ipairs(spawn.blocks) do world:add('block' .. i, b[1], b[2], b[3], b[4]) end
  world:add('body', spawn.body[1], spawn.body[2], spawn.body[3], spawn.body[4])
  local vx, vy, most, inside, repeated = 30, -60, 0, 0, false
  for _ = 1, 120 do
    vy = vy + 500 / 60
    local x, y = world:getRect('body')
    local _, _, cols, len = world:move('body', x + vx / 60, y + vy / 60, function() return answer end)
    most = math.max(most, len)
    local seen = {}
    for i = 1, len do
      repeated = repeated or seen[cols[i].other] == true
      seen[cols[i].other] = true
      local n = cols[i].normal
      if (n.x < 0 and vx > 0) or (n.x > 0 and vx < 0) then vx = -vx * 0.1 end
      if (n.y < 0 and vy > 0) or (n.y > 0 and vy < 0) then vy = -vy * 0.1 end
    end
    x, y = world:getRect('body')
    local _, n = world:queryRect(x, y, spawn.body[3], spawn.body[4], function(o) return o ~= 'body' end)
    if n > 0 then inside = inside + 1 end
  end
  return most, inside, repeated
end

describe('a body spawned inside solids', function()
  for _, spawn in ipairs(spawns()) do
    for _, answer in ipairs({ 'bounce', 'slide' }) do
      it(spawn.what .. ' (' .. answer .. ') gets out, meeting each item once a move', function()
        local most, inside, repeated = play(bump.newWorld, spawn, answer)
        assert.is_false(repeated)
        assert.is_true(most <= #spawn.blocks)
        assert.is_true(inside <= 2)
      end)
    end
  end

  it('negative control: the core\'s rules wedge one across two blocks 2 px apart', function()
    local most, inside = play(tv.newWorld, spawns()[4], 'bounce')
    assert.equal(64, most)
    assert.equal(120, inside)
  end)
end)

describe('bump\'s queries', function()
  --   t: 0..16 x 0..16. bump's queryPoint wants the point inside by more than 1e-10
  it('queryPoint leaves out points on an edge', function()
    local world = bump.newWorld()
    world:add('t', 0, 0, 16, 16)
    assert.same({ 0, 0, 1 }, { select(2, world:queryPoint(0, 8)), select(2, world:queryPoint(16, 8)),
                               select(2, world:queryPoint(8, 8)) })
  end)

  --   querySegment leaves out an item holding the whole segment, and sorts by where the
  --   infinite line enters each item
  it('querySegment leaves out an item that holds the whole segment', function()
    local world = bump.newWorld()
    world:add('big', 0, 0, 100, 100)
    world:add('small', 40, 10, 5, 5)
    assert.same({ 'small' }, (world:querySegment(10, 12, 60, 12)))
    local info = world:querySegmentWithCoords(10, 12, 60, 12)
    assert.same({ item = 'small', ti1 = 0.6, ti2 = 0.7, x1 = 40, y1 = 12, x2 = 45, y2 = 12 }, info[1])
  end)
end)

describe('responses added from Lua', function()
  --   bump's way: the response gets the item's rect before the move, the goal, and bump's
  --   visitedFilter, projects the next leg itself and returns goalX, goalY, cols, len
  --   i (0,0 10x10) heads for (50,15): it lands on the floor (y 20) first, at (33.3, 10);
  --   'glide' projects it along the floor, where it meets the wall (x 45), and slides there
  it('get bump\'s arguments, and their projection is the next leg', function()
    local world = bump.newWorld()
    world:add('floor', 0, 20, 100, 10)
    world:add('wall', 45, 0, 10, 20)
    world:add('i', 0, 0, 10, 10)
    local seen
    world:addResponse('glide', function(w, col, x, y, width, height, goalX, goalY, filter)
      seen = { x, y, width, height, goalX, goalY }
      assert.is_false(filter(col.item, col.other))   -- bump's visitedFilter: met already
      assert.equal('slide', filter(col.item, 'wall'))
      local cols, len = w:project(col.item, col.touch.x, col.touch.y, width, height, goalX, col.touch.y, filter)
      return goalX, col.touch.y, cols, len
    end)
    local x, y, cols, len = world:move('i', 50, 15, function(_, o) return o == 'floor' and 'glide' or 'slide' end)
    assert.same({ 0, 0, 10, 10, 50, 15 }, seen)
    assert.same({ 'floor', 'wall' }, { cols[1].other, cols[2].other })
    assert.same({ 35, 10, 2 }, { x, y, len })
  end)

  it('that return no collisions end the move at their goal', function()
    local world = bump.newWorld()
    world:add('floor', 0, 20, 100, 10)
    world:add('i', 0, 0, 10, 10)
    world:addResponse('stick', function(_, col) return col.touch.x, col.touch.y - 1, {}, 0 end)
    local x, y, _, len = world:move('i', 0, 30, function() return 'stick' end)
    assert.same({ 0, 9, 1 }, { x, y, len })
  end)
end)
