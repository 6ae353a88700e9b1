-- bump.lua's world:move, check and project, the four responses, custom responses and filters,
-- against hand-worked expectations. y grows downwards, as on screen.
local bump = require 'tunnelvision.bump'

local function strip(err) return (tostring(err):gsub('^.-:%d+: ', '')) end

describe('world:move', function()
  it('with nothing in the way goes to the goal: {x, y, {}, 0}', function()
    local world = bump.newWorld()
    world:add('a', 0, 0, 1, 1)
    assert.same({ 10, 20, {}, 0 }, { world:move('a', 10, 20) })
    assert.same({ 10, 20, 1, 1 }, { world:getRect('a') })
  end)

  --   a moves from (0,0) down to (0,5)      y
  --   +-+                                     0  a
  --   |a|                                     1
  --   +-+   <- stops here with touch          2  b (0,2 1x1)
  --   |b|
  --   +-+                    contact when 1 + 5t = 2: ti = 0.2
  it('touch stops at the contact and reports the whole collision', function()
    local world = bump.newWorld()
    world:add('a', 0, 0, 1, 1)
    world:add('b', 0, 2, 1, 1)
    local x, y, cols, len = world:move('a', 0, 5, function() return 'touch' end)
    assert.same({ 0, 1, 1 }, { x, y, len })
    assert.same({
      item = 'a', other = 'b', type = 'touch', overlaps = false, ti = 0.2,
      move = { x = 0, y = 5 }, normal = { x = 0, y = -1 }, touch = { x = 0, y = 1 },
      itemRect = { x = 0, y = 0, w = 1, h = 1 }, otherRect = { x = 0, y = 2, w = 1, h = 1 },
    }, cols[1])
  end)

  it('cross reports the collision and goes through', function()
    local world = bump.newWorld()
    world:add('a', 0, 0, 1, 1)
    world:add('b', 0, 2, 1, 1)
    local x, y, cols, len = world:move('a', 0, 5, function() return 'cross' end)
    assert.same({ 0, 5, 1 }, { x, y, len })
    assert.equal('cross', cols[1].type)
    assert.equal(0.2, cols[1].ti)
  end)

  --   a (0,0 1x1) moves to (4,5) onto a floor b (0,2 10x1):
  --   contact when 1 + 5t = 2, t = 0.2, at (0.8, 1); slide keeps x, stays on y = 1
  --   +-+
  --   |a| \
  --   +-+--\------> (4,1)
  --   |  b floor  |
  it('slide stops on the normal\'s axis and keeps going along the surface (col.slide)', function()
    local world = bump.newWorld()
    world:add('a', 0, 0, 1, 1)
    world:add('b', 0, 2, 10, 1)
    local x, y, cols, len = world:move('a', 4, 5)
    assert.same({ 4, 1, 1 }, { x, y, len })
    assert.equal('slide', cols[1].type)
    assert.same({ x = 0.8, y = 1 }, cols[1].touch)
    assert.same({ x = 4, y = 1 }, cols[1].slide)
  end)

  --   same, bounce: what is left of the move after the touch, (3.2, 4), is reflected to
  --   (3.2, -4): from (0.8, 1) to (4, -3)
  it('bounce reflects the rest of the move off the surface (col.bounce)', function()
    local world = bump.newWorld()
    world:add('a', 0, 0, 1, 1)
    world:add('b', 0, 2, 10, 1)
    local x, y, cols, len = world:move('a', 4, 5, function() return 'bounce' end)
    assert.same({ 4, -3, 1 }, { x, y, len })
    assert.same({ x = 4, y = -3 }, cols[1].bounce)
  end)

  it('a filter returning false or nil ignores the pair', function()
    for _, answer in ipairs({ false, 'nil' }) do
      local world = bump.newWorld()
      world:add('a', 0, 0, 1, 1)
      world:add('b', 0, 2, 10, 1)
      local x, y, _, len = world:move('a', 4, 5, function() if answer then return answer == 'nil' and nil end return false end)
      assert.same({ 4, 5, 0 }, { x, y, len })
    end
  end)

  --   a falls through a cloud c (cross) onto a floor f (touch)
  --   y 0  a
  --     2  c  (cross)
  --     5  f  (touch)     a stops at y = 4, having crossed c
  it('a filter chooses the response per pair, and is called with (item, other)', function()
    local world = bump.newWorld()
    world:add('a', 0, 0, 1, 1)
    world:add('c', 0, 2, 1, 1)
    world:add('f', 0, 5, 1, 1)
    local asked = {}
    local x, y, cols, len = world:move('a', 0, 10, function(item, other)
      asked[#asked + 1] = item .. '>' .. other
      return other == 'c' and 'cross' or 'touch'
    end)
    assert.same({ 0, 4, 2 }, { x, y, len })
    assert.same({ 'c', 'f' }, { cols[1].other, cols[2].other })
    assert.same({ 'cross', 'touch' }, { cols[1].type, cols[2].type })
    for _, q in ipairs(asked) do assert.equal('a', q:sub(1, 1)) end
  end)

  it('items of every kind are passed to filters and reported as they were added', function()
    local world = bump.newWorld()
    local t = {}
    world:add(false, 0, 0, 1, 1)
    world:add(7, 0, 2, 1, 1)
    world:add(t, 0, 4, 1, 1)
    local seen = {}
    local _, _, cols = world:move(false, 0, 10, function(item, other)
      assert.equal(false, item)
      seen[#seen + 1] = other
      return 'cross'
    end)
    assert.equal(7, cols[1].other)
    assert.equal(t, cols[2].other)
    assert.equal(false, cols[1].item)
  end)

  it('raises bump\'s error for an unknown response name, changing nothing', function()
    local world = bump.newWorld()
    world:add('a', 0, 0, 1, 1)
    world:add('b', 0, 2, 1, 1)
    local ok, err = pcall(world.move, world, 'a', 0, 5, function() return 'bogus' end)
    assert.is_false(ok)
    assert.equal('Unknown collision type: bogus (string)', strip(err))
    assert.same({ 0, 0, 1, 1 }, { world:getRect('a') })
  end)

  it('a filter that raises propagates its error and leaves the world as it was', function()
    local world = bump.newWorld()
    world:add('a', 0, 0, 1, 1)
    world:add('b', 0, 2, 1, 1)
    world:add('c', 0, 4, 1, 1)
    local calls = 0
    local ok, err = pcall(world.move, world, 'a', 0, 10, function(_, other)
      calls = calls + 1
      if other == 'c' then error({ code = 42 }) end   -- any error value, not only strings
      return 'cross'
    end)
    assert.is_false(ok)
    assert.same({ code = 42 }, err)
    assert.is_true(calls >= 2)
    assert.same({ 0, 0, 1, 1 }, { world:getRect('a') })
    -- and the world still works
    local x, y = world:move('a', 0, 5, function() return 'touch' end)
    assert.same({ 0, 1 }, { x, y })
  end)

  it('a world may not be changed from inside its own filter', function()
    local world = bump.newWorld()
    world:add('a', 0, 0, 1, 1)
    world:add('b', 0, 2, 1, 1)
    local ok, err = pcall(world.move, world, 'a', 0, 5, function() world:remove('b'); return 'slide' end)
    assert.is_false(ok)
    assert.matches('world:remove cannot be called while', err)
    assert.is_true(world:hasItem('b'))
    -- queries are fine
    local _, _, _, len = world:move('a', 0, 5, function() assert.equal(2, #world:queryRect(0, 0, 5, 5)); return 'touch' end)
    assert.equal(1, len)
  end)

  it('checks its arguments, naming them', function()
    local world = bump.newWorld()
    world:add('a', 0, 0, 1, 1)
    assert.has_error(function() world:move('a', 'x', 0) end, "goalX must be a number, but was 'x' (a string)")
    assert.has_error(function() world:move('a', 0, 0/0) end, 'goalY must be a finite number, but was nan')
    assert.has_error(function() world:move('a', 0, 0, 5) end, 'filter must be a function, but was 5 (a number)')
    assert.has_error(function() world:move('zz', 0, 0) end,
      'Item zz must be added to the world before getting its rect. Use world:add(item, x,y,w,h) to add it first.')
  end)

  --   a (0,0 2x2) overlaps b (1,0 2x2):   0 1 2 3
  --                                        a a+b b      bump's ti: minus the area of the minimum
  --                                        a a+b b      displacement, min(2, 1) * min(2, 2) = -2
  it('an item inside another that does not move stays, reporting the overlap (bump\'s rule)', function()
    local world = bump.newWorld()
    world:add('a', 0, 0, 2, 2)
    world:add('b', 1, 0, 2, 2)
    local x, y, cols, len = world:move('a', 0, 0)
    assert.equal(1, len)
    assert.is_true(cols[1].overlaps)
    assert.equal(-2, cols[1].ti)
    assert.same({ x = -1, y = 0 }, cols[1].touch)   -- the way out: one to the left
    assert.same({ 0, 0 }, { x, y })                 -- but slide keeps a still move's goal
  end)

  it('an item inside another that moves is pushed back against its move', function()
    local world = bump.newWorld()
    world:add('a', 0, 0, 2, 2)
    world:add('b', 1, 0, 2, 2)
    local x, y, cols = world:move('a', 0.5, 0)
    assert.same({ x = -1, y = 0 }, cols[1].touch)
    assert.same({ x = -1, y = 0 }, cols[1].normal)
    assert.same({ -1, 0 }, { x, y })
  end)
end)

describe('world:check', function()
  it('returns what move would, without moving', function()
    local world = bump.newWorld()
    world:add('a', 0, 0, 1, 1)
    world:add('b', 0, 2, 10, 1)
    local x, y, cols, len = world:check('a', 4, 5)
    assert.same({ 4, 1, 1 }, { x, y, len })
    assert.same({ x = 4, y = 1 }, cols[1].slide)
    assert.same({ 0, 0, 1, 1 }, { world:getRect('a') })
  end)
end)

describe('world:project', function()
  --   a rect (0,0 1x1) projected to (0,10) through b (0,2), c (0,4): every collision of the
  --   straight leg, by ti: b at 0.1, c at 0.3; item nil or an item of the world (left out)
  it('lists every collision of one straight leg, in ti order, with the filter\'s types', function()
    local world = bump.newWorld()
    world:add('c', 0, 4, 1, 1)
    world:add('b', 0, 2, 1, 1)
    local cols, len = world:project(nil, 0, 0, 1, 1, 0, 10)
    assert.equal(2, len)
    assert.same({ 'b', 'c' }, { cols[1].other, cols[2].other })
    assert.same({ 0.1, 0.3 }, { cols[1].ti, cols[2].ti })
    assert.same({ 'slide', 'slide' }, { cols[1].type, cols[2].type })
    assert.is_nil(cols[1].item)
    cols, len = world:project('b', 0, 0, 1, 1, 0, 10, function(_, other) return other == 'c' and 'touch' end)
    assert.equal(1, len)
    assert.same({ 'b', 'c', 'touch' }, { cols[1].item, cols[1].other, cols[1].type })
  end)

  it('goal defaults to the rect\'s position: only overlaps are reported', function()
    local world = bump.newWorld()
    world:add('b', 0, 0, 2, 2)
    world:add('c', 5, 0, 2, 2)
    local cols, len = world:project(nil, 1, 1, 2, 2)
    assert.equal(1, len)
    assert.is_true(cols[1].overlaps)
    assert.same({}, (world:project(nil, 10, 10, 1, 1)))
  end)

  it('checks the rect', function()
    local world = bump.newWorld()
    assert.has_error(function() world:project(nil, 0, 0, 0, 1) end, 'w must be a positive number, but was 0')
  end)
end)

describe('world:addResponse', function()
  it('adds a response with bump\'s signature, called with (world, col, x,y,w,h, goalX, goalY, filter)', function()
    local world = bump.newWorld()
    world:add('a', 0, 0, 1, 1)
    world:add('b', 0, 2, 10, 1)
    local got
    world:addResponse('stick', function(w, col, x, y, wd, h, goalX, goalY, filter)
      got = { w == world, col.other, x, y, wd, h, goalX, goalY, type(filter) }
      col.stuck = true
      return col.touch.x, col.touch.y, {}, 0
    end)
    local filter = function() return 'stick' end
    local x, y, cols, len = world:move('a', 4, 5, filter)
    assert.same({ 0.8, 1, 1 }, { x, y, len })
    assert.same({ true, 'b', 0, 0, 1, 1, 4, 5, 'function' }, got)
    assert.equal('stick', cols[1].type)
    assert.is_true(cols[1].stuck)   -- the table the response saw is the one returned
  end)

  it('bump.responses.* work as added responses, under any name', function()
    local world = bump.newWorld()
    world:add('a', 0, 0, 1, 1)
    world:add('b', 0, 2, 10, 1)
    world:addResponse('skate', bump.responses.slide)
    local x, y, cols = world:move('a', 4, 5, function() return 'skate' end)
    assert.same({ 4, 1 }, { x, y })
    assert.equal('skate', cols[1].type)
    assert.same({ x = 4, y = 1 }, cols[1].slide)
  end)

  it('re-adding a built-in name replaces it', function()
    local world = bump.newWorld()
    world:add('a', 0, 0, 1, 1)
    world:add('b', 0, 2, 10, 1)
    world:addResponse('slide', bump.responses.touch)
    local x, y = world:move('a', 4, 5)   -- no filter: every pair 'slide', now a touch
    assert.same({ 0.8, 1 }, { x, y })
    world:addResponse('slide', bump.responses.slide)
    world:update('a', 0, 0)
    x, y = world:move('a', 4, 5)
    assert.same({ 4, 1 }, { x, y })
  end)

  it('a response that raises propagates its error and leaves the world as it was', function()
    local world = bump.newWorld()
    world:add('a', 0, 0, 1, 1)
    world:add('b', 0, 2, 10, 1)
    world:addResponse('boom', function() error('no way') end)
    local ok, err = pcall(world.move, world, 'a', 4, 5, function() return 'boom' end)
    assert.is_false(ok)
    assert.matches('no way', err)
    assert.same({ 0, 0, 1, 1 }, { world:getRect('a') })
  end)

  it('a response that returns no goal is an error naming it', function()
    local world = bump.newWorld()
    world:add('a', 0, 0, 1, 1)
    world:add('b', 0, 2, 10, 1)
    world:addResponse('lost', function() end)
    local ok, err = pcall(world.move, world, 'a', 4, 5, function() return 'lost' end)
    assert.is_false(ok)
    assert.matches("response 'lost' must return goalX, goalY", err)
  end)

  it('checks its arguments', function()
    local world = bump.newWorld()
    assert.has_error(function() world:addResponse(3, print) end, 'name must be a string, but was 3 (a number)')
    assert.has_error(function() world:addResponse('x', 3) end, 'response must be a function, but was 3 (a number)')
  end)
end)
