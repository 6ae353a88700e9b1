-- bump.lua's internal tables, which debug overlays and tools read: world.rows (cells with x, y,
-- itemCount, items), world.rects, world.nonEmptyCells, world.responses, in bump's shapes. Built
-- when read, refreshed at the next read after a change; writing to them changes nothing.
local bump = require 'tunnelvision.bump'

-- What bump_debug.lua (bump's own demo overlay) does with world.rows, without drawing.
local function debugCells(world)
  local out = {}
  for cy, row in pairs(world.rows) do
    for cx, cell in pairs(row) do
      local l, t = world:toWorld(cx, cy)
      out[#out + 1] = ('%d,%d n=%d at %g,%g'):format(cx, cy, cell.itemCount, l, t)
    end
  end
  table.sort(out)
  return out
end

describe('world.rows and world.nonEmptyCells', function()
  --   cell size 64: a (0,0 10x10) is in cell (1,1); b (60,0 10x10) in (1,1) and (2,1);
  --   c (0,100 10x10) in (1,2)
  --   +------+------+
  --   |a    b|b     |
  --   +------+------+
  --   |c     |
  --   +------+
  it('hold bump\'s cells, 1-based, with their items', function()
    local world = bump.newWorld(64)
    world:add('a', 0, 0, 10, 10)
    world:add('b', 60, 0, 10, 10)
    world:add('c', 0, 100, 10, 10)
    assert.same({ '1,1 n=2 at 0,0', '1,2 n=1 at 0,64', '2,1 n=1 at 64,0' }, debugCells(world))
    local cell = world.rows[1][1]
    assert.same({ x = 1, y = 1, itemCount = 2, items = { a = true, b = true } }, cell)
    assert.is_true(world.nonEmptyCells[cell])
    local n = 0
    for _ in pairs(world.nonEmptyCells) do n = n + 1 end
    assert.equal(3, n)
  end)

  it('follow moves, updates and removes at the next read', function()
    local world = bump.newWorld(64)
    world:add('a', 0, 0, 10, 10)
    local rows = world.rows
    world:move('a', 100, 0)
    assert.equal(rows, world.rows)                  -- the same table, refilled in place
    assert.same({ '2,1 n=1 at 64,0' }, debugCells(world))
    world:update('a', 0, 130)
    assert.same({ '1,3 n=1 at 0,128' }, debugCells(world))
    world:remove('a')
    assert.same({}, debugCells(world))
  end)

  it('read inside a filter, show the world as it was before the move', function()
    local world = bump.newWorld(64)
    world:add('a', 0, 0, 10, 10)
    world:add('b', 100, 0, 10, 10)
    local during
    world:move('a', 120, 0, function() during = debugCells(world); return 'cross' end)
    assert.same({ '1,1 n=1 at 0,0', '2,1 n=1 at 64,0' }, during)
    assert.same({ '2,1 n=2 at 64,0', '3,1 n=1 at 128,0' }, debugCells(world))
  end)
end)

describe('world.rects', function()
  it('maps each item to {x, y, w, h}', function()
    local world = bump.newWorld()
    local t = {}
    world:add(t, 1, 2, 3, 4)
    world:add('s', 5, 6, 7, 8)
    assert.same({ [t] = { x = 1, y = 2, w = 3, h = 4 }, s = { x = 5, y = 6, w = 7, h = 8 } }, world.rects)
  end)

  it('can be written to without changing the world (assigning replaces what Lua reads)', function()
    local world = bump.newWorld()
    world:add('a', 1, 2, 3, 4)
    world.rects.a.x = 99
    assert.same({ 1, 2, 3, 4 }, { world:getRect('a') })
    world:update('a', 5, 2)
    assert.equal(5, world.rects.a.x)               -- rebuilt from the world after the change
    local mine = {}
    world.rows = mine
    assert.equal(mine, world.rows)
    assert.same({ 5, 2, 3, 4 }, { world:getRect('a') })
  end)
end)

describe('world.responses', function()
  it('names bump\'s four responses and those added', function()
    local world = bump.newWorld()
    local stick = function(_, col) return col.touch.x, col.touch.y, {}, 0 end
    world:addResponse('stick', stick)
    local r = world.responses
    assert.equal(bump.responses.slide, r.slide)
    assert.equal(bump.responses.touch, r.touch)
    assert.equal(bump.responses.cross, r.cross)
    assert.equal(bump.responses.bounce, r.bounce)
    assert.equal(stick, r.stick)
  end)
end)

describe('a world nobody reads the internals of', function()
  it('builds none of them', function()
    local world = bump.newWorld()
    for i = 1, 100 do world:add(i, i * 3, 0, 2, 2) end
    for i = 1, 100 do world:move(i, i * 3 + 1, 0) end
    -- rawget on the field table: no key was stored by the moves
    assert.is_nil(rawget(getmetatable(world).__index, 'rows'))
    assert.is_nil(rawget(getmetatable(world).__index, 'rects'))
  end)
end)
