-- bump.lua's World API, item bookkeeping: add, remove, update, getRect, hasItem, getItems,
-- countItems, countCells, toWorld, toCell, and the errors each raises.
local bump = require 'tunnelvision.bump'

describe('bump.newWorld', function()
  it('defaults to cells of 64 and exposes world.cellSize', function()
    assert.equal(64, bump.newWorld().cellSize)
    assert.equal(32, bump.newWorld(32).cellSize)
  end)

  it('refuses a cell size that is not a positive number, naming it', function()
    for _, bad in ipairs({ 0, -1, 'a', 0/0, math.huge }) do
      local ok, err = pcall(bump.newWorld, bad)
      assert.is_false(ok)
      assert.matches('cellSize must be a positive number, but was', err)
    end
  end)

  it('lets code (test spies) assign fields on a world', function()
    local world = bump.newWorld()
    local calls = 0
    local add = world.add
    world.add = function(...) calls = calls + 1; return add(...) end
    world:add('a', 0, 0, 1, 1)
    assert.equal(1, calls)
    assert.is_true(world:hasItem('a'))
  end)
end)

describe('world:add', function()
  it('returns the item and stores its rect', function()
    local world = bump.newWorld()
    local item = {}
    assert.equal(item, world:add(item, 1, 2, 3, 4))
    assert.same({ 1, 2, 3, 4 }, { world:getRect(item) })
  end)

  it('takes any Lua value but nil and NaN as an item: strings, numbers, tables, false', function()
    local world = bump.newWorld()
    local t, f = {}, function() end
    for i, item in ipairs({ 'player', 42, t, false, f, true }) do
      world:add(item, i * 10, 0, 5, 5)
    end
    assert.equal(6, world:countItems())
    assert.same({ 20, 0, 5, 5 }, { world:getRect(42) })
    assert.same({ 40, 0, 5, 5 }, { world:getRect(false) })
    -- 42 and 42.0 are the same table key, as in bump
    assert.has_error(function() world:add(42.0, 0, 0, 1, 1) end, 'Item 42 added to the world twice.')
    assert.has_error(function() world:add(nil, 0, 0, 1, 1) end, 'item must not be nil')
    assert.has_error(function() world:add(0/0, 0, 0, 1, 1) end, 'item must not be NaN')
  end)

  it('compares items by identity, not by contents', function()
    local world = bump.newWorld()
    world:add({}, 0, 0, 1, 1)
    world:add({}, 0, 0, 1, 1)
    assert.equal(2, world:countItems())
  end)

  it('raises naming the argument and its value, and adds nothing', function()
    local world = bump.newWorld()
    local cases = {
      { { 'x', 0, 1, 1 }, "x must be a number, but was 'x' (a string)" },
      { { 0, nil, 1, 1 }, 'y must be a number, but was nil (a nil)' },
      { { 0, 0, -1, 1 }, 'w must be a positive number, but was -1' },
      { { 0, 0, 1, 0 }, 'h must be a positive number, but was 0' },
      { { 0/0, 0, 1, 1 }, 'x must be a finite number, but was nan' },
      { { 0, 0, math.huge, 1 }, 'w must be a positive number, but was inf' },
    }
    for _, c in ipairs(cases) do
      local a = c[1]
      local ok, err = pcall(world.add, world, 'item', a[1], a[2], a[3], a[4])
      assert.is_false(ok)
      assert.equal(c[2], err:gsub('^.-:%d+: ', ''))
    end
    assert.equal(0, world:countItems())
    assert.is_false(world:hasItem('item'))
  end)

  it('passes the core\'s own refusals on as Lua errors (never a C++ exception), adding nothing', function()
    local world = bump.newWorld(1)
    local ok, err = pcall(world.add, world, 'far', 1e300, 0, 1, 1)
    assert.is_false(ok)
    assert.matches('tv::World::add', err)
    assert.matches('1e%+300', err)
    assert.is_false(world:hasItem('far'))
    assert.equal(0, world:countCells())
    world:add('near', 0, 0, 1, 1)
    assert.has_error(function() world:update('near', 1e300, 0) end)
    assert.same({ 0, 0, 1, 1 }, { world:getRect('near') })
  end)

  it('raises when the same item is added twice', function()
    local world = bump.newWorld()
    world:add('a', 0, 0, 1, 1)
    assert.has_error(function() world:add('a', 5, 5, 1, 1) end, "Item a added to the world twice.")
    assert.same({ 0, 0, 1, 1 }, { world:getRect('a') })
  end)
end)

describe('world:remove and world:update', function()
  it('removes an item, which may then be added again', function()
    local world = bump.newWorld()
    world:add('a', 0, 0, 1, 1)
    world:remove('a')
    assert.is_false(world:hasItem('a'))
    assert.equal(0, world:countItems())
    world:add('a', 3, 3, 1, 1)
    assert.same({ 3, 3, 1, 1 }, { world:getRect('a') })
  end)

  it('raises for an item that is not in the world', function()
    local world = bump.newWorld()
    assert.has_error(function() world:remove('ghost') end,
      'Item ghost must be added to the world before getting its rect. Use world:add(item, x,y,w,h) to add it first.')
    assert.has_error(function() world:getRect({}) end)
    assert.has_error(function() world:update('ghost', 0, 0) end)
  end)

  it('update teleports and may resize; w and h default to the current size', function()
    local world = bump.newWorld()
    world:add('a', 0, 0, 10, 10)
    world:update('a', 100, 200)
    assert.same({ 100, 200, 10, 10 }, { world:getRect('a') })
    world:update('a', 100, 200, 3, 4)
    assert.same({ 100, 200, 3, 4 }, { world:getRect('a') })
    assert.has_error(function() world:update('a', 0, 0, -3) end, 'w must be a positive number, but was -3')
    assert.same({ 100, 200, 3, 4 }, { world:getRect('a') })
  end)
end)

describe('world:hasItem, getItems, countItems', function()
  it('hasItem returns exactly true or false, also for nil', function()
    local world = bump.newWorld()
    world:add('a', 0, 0, 1, 1)
    assert.equal(true, world:hasItem('a'))
    assert.equal(false, world:hasItem('b'))
    assert.equal(false, world:hasItem(nil))
    assert.equal(false, world:hasItem(0/0))
  end)

  it('getItems returns a fresh array and its length, in add order', function()
    local world = bump.newWorld()
    local items, len = world:getItems()
    assert.same({}, items)
    assert.equal(0, len)
    world:add('a', 0, 0, 1, 1)
    world:add('b', 0, 0, 1, 1)
    world:add('c', 0, 0, 1, 1)
    world:remove('b')
    items, len = world:getItems()
    assert.same({ 'a', 'c' }, items)
    assert.equal(2, len)
    assert.equal(2, world:countItems())
  end)
end)

describe('world:toCell and world:toWorld', function()
  -- Cells are 1-based: cell 1 covers [0, cellSize).
  it('convert as bump does, negative coordinates included', function()
    local world = bump.newWorld(64)
    assert.same({ 0, 0 }, { world:toCell(-1, -1) })
    assert.same({ 1, 1 }, { world:toCell(0, 63.9) })
    assert.same({ 2, 3 }, { world:toCell(64, 128) })
    assert.same({ -128, 0 }, { world:toWorld(-1, 1) })
    assert.same({ 0, 64 }, { world:toWorld(1, 2) })
  end)
end)

describe('world:countCells', function()
  --   cell size 10; cells from floor(x/10)+1 to ceil((x+w)/10)
  --   a at (0,0) 10x10   -> cell (1,1) only (its right edge ends on the cell boundary)
  --   b at (5,5) 10x10   -> cells (1,1) (2,1) (1,2) (2,2)
  it('counts the cells the items are in, as bump lays them out', function()
    local world = bump.newWorld(10)
    assert.equal(0, world:countCells())
    world:add('a', 0, 0, 10, 10)
    assert.equal(1, world:countCells())
    world:add('b', 5, 5, 10, 10)
    assert.equal(4, world:countCells())
    world:add('c', 25, 0, 10, 10)   -- (3,1) (4,1)
    assert.equal(6, world:countCells())
  end)

  it('keeps an emptied cell until the next garbage collection, as bump\'s weak cells', function()
    local world = bump.newWorld(10)
    world:add('a', 0, 0, 10, 10)
    world:add('b', 30, 0, 10, 10)
    world:remove('b')
    assert.equal(2, world:countCells())
    collectgarbage('collect')
    assert.equal(1, world:countCells())
    world:update('a', 50, 0)
    assert.equal(2, world:countCells())
    collectgarbage('collect')
    assert.equal(1, world:countCells())
    world:move('a', 80, 0)             -- moves and batch steps too
    world:step({ 'a', 100, 0 })
    assert.equal(3, world:countCells())
    collectgarbage('collect')
    assert.equal(1, world:countCells())
  end)

  it('a cell emptied and filled again is counted once', function()
    local world = bump.newWorld(10)
    world:add('a', 0, 0, 10, 10)
    world:remove('a')
    world:add('b', 0, 0, 10, 10)
    assert.equal(1, world:countCells())
    collectgarbage('collect')
    assert.equal(1, world:countCells())
  end)
end)

describe('garbage collection', function()
  it('holds items strongly while they are in the world, and frees the world when dropped', function()
    local probe = setmetatable({}, { __mode = 'k' })
    local world = bump.newWorld()
    do
      local item = {}
      probe[item] = true
      world:add(item, 0, 0, 1, 1)
    end
    collectgarbage('collect')
    assert.equal(1, world:countItems())
    assert.is_not_nil(next(probe))
    local w2 = setmetatable({}, { __mode = 'k' })
    w2[world] = true
    world = nil
    collectgarbage('collect')
    collectgarbage('collect')
    assert.is_nil(next(w2))
    assert.is_nil(next(probe))
  end)

  it('frees a removed item', function()
    local probe = setmetatable({}, { __mode = 'k' })
    local world = bump.newWorld()
    local item = {}
    probe[item] = true
    world:add(item, 0, 0, 1, 1)
    world:remove(item)
    item = nil
    collectgarbage('collect')
    assert.is_nil(next(probe))
  end)

  it('a method called on something that is not a world raises', function()
    local world = bump.newWorld()
    assert.has_error(function() world.add({}, 'a', 0, 0, 1, 1) end)
    assert.has_error(function() world.getRect(io.stdout, 'a') end)
  end)
end)
