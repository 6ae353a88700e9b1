-- Contact events, ground state and corner correction from Lua, on both faces of the module
-- (`tunnelvision` and, as an extension of bump's API, `tunnelvision.bump`). y grows downwards.
local tv = require 'tunnelvision'

local faces = { { 'tunnelvision', tv.newWorld }, { 'tunnelvision.bump', tv.bump.newWorld } }

-- "begin tile0 | persist tile0, begin tile1": a list of updates' events in one line.
local function words(events)
  local out = {}
  for i, e in ipairs(events) do out[i] = e.phase .. ' ' .. (e.other and e.other.name or 'nil') end
  return table.concat(out, ', ')
end

for _, face in ipairs(faces) do
  local name, newWorld = face[1], face[2]

  describe(name .. ' world:contacts', function()
    --        +--+
    --        |b |          body {4, 88, 8, 12}, walking right 4 px a move
    --   +----------+----------+
    --   |  tile0   |  tile1   |   {0, 100, 16, 16}, {16, 100, 16, 16}
    it('keeps a resting body in contact and meets the next tile once, in add order', function()
      local world = newWorld(16)
      local tile0, tile1, body = { name = 'tile0' }, { name = 'tile1' }, { name = 'body' }
      world:add(tile0, 0, 100, 16, 16)
      world:add(tile1, 16, 100, 16, 16)
      world:add(body, 4, 88, 8, 12)
      local got = {}
      for _ = 1, 4 do
        local x, y = world:getRect(body)
        local _, _, cols = world:move(body, x + 4, y)
        got[#got + 1] = words((world:contacts(body, nil, cols)))
      end
      assert.same({ 'begin tile0', 'persist tile0, begin tile1', 'end tile0, persist tile1',
                    'persist tile1' }, got)
    end)

    it('negative control: contacts taken from the move lists end while the body stands', function()
      local world = newWorld(16)
      local tile0, body = { name = 'tile0' }, { name = 'body' }
      world:add(tile0, 0, 100, 64, 16)
      world:add(body, 4, 88, 8, 12)
      local naiveEnds, ends = 0, 0
      local before = {}
      for i = 1, 6 do
        local x, y = world:getRect(body)
        local _, _, cols, len = world:move(body, x + 0.5, y + (i % 2 == 1 and 1 or 0))
        local now = {}
        for j = 1, len do now[cols[j].other] = true end
        for o in pairs(before) do if not now[o] then naiveEnds = naiveEnds + 1 end end
        before = now
        for _, e in ipairs((world:contacts(body, nil, cols))) do
          if e.phase == 'end' then ends = ends + 1 end
        end
      end
      assert.equal(3, naiveEnds)
      assert.equal(0, ends)
    end)

    it('passes the filter: ignored items are no contact, a crossed coin begins then ends', function()
      local world = newWorld(16)
      local coin, ghost, body = { name = 'coin' }, { name = 'ghost' }, { name = 'body' }
      world:add(coin, 40, 0, 4, 4)
      world:add(ghost, 0, 0, 4, 8)
      world:add(body, 4, 0, 8, 8)
      local function filter(_, other)
        if other == coin then return 'cross' end
        if other == ghost then return nil end
        return 'slide'
      end
      local _, _, cols = world:move(body, 100, 0, filter)
      local events, n = world:contacts(body, filter, cols)
      assert.equal(1, n)
      assert.equal(coin, events[1].other)
      assert.equal('begin', events[1].phase)
      assert.is_true(events[1].met)
      assert.same({ x = -1, y = 0 }, events[1].normal)
      _, _, cols = world:move(body, 110, 0, filter)
      assert.equal('end coin', words((world:contacts(body, filter, cols))))
    end)

    it('says what a body stands on, with coyote time', function()
      --   +--+
      --   |b | ->    walks off the ledge {0, 10, 16, 10} (a one-way platform) 8 px a move
      --   +-------+
      local world = newWorld(16)
      local ledge, body = { name = 'ledge' }, { name = 'body' }
      world:add(ledge, 0, 10, 16, 10)
      world:add(body, 0, 0, 8, 10)
      local kinds = {}
      for _ = 1, 5 do
        local x, y = world:getRect(body)
        local _, _, cols = world:move(body, x + 8, y + 1)
        world:contacts(body, nil, cols, { oneWay = { ledge }, coyote = 2 })
        local kind, ground, nx, ny = world:ground(body)
        kinds[#kinds + 1] = kind
        if kind == 'oneWay' then
          assert.equal(ledge, ground)
          assert.same({ 0, -1 }, { nx, ny })
        end
      end
      assert.same({ 'oneWay', 'coyote', 'coyote', 'air', 'air' }, kinds)
    end)

    it('refuses bad input naming it, changing nothing', function()
      local world = newWorld(16)
      local body = { name = 'body' }
      world:add(body, 0, 0, 8, 8)
      assert.has_error(function() world:contacts({}) end)
      assert.error_matches(function() world:contacts(body, nil, nil, { coyote = -1 }) end,
                           'options.coyote')
      assert.error_matches(function() world:contacts(body, 3) end, 'filter must be a function')
      assert.equal('air', (world:ground(body)))
    end)
  end)

  describe(name .. ' world:moveCornered', function()
    --          +---------------------+
    --          | ceiling {16, 0, 32, 8} |
    --       +--+------------------+
    --       |b |   body {10, 40, 8, 12}: 2 px under the ceiling's left end, jumping straight up
    it('nudges a jump round a ceiling corner it clips by 2 px; world:move stops dead', function()
      local world = newWorld(16)
      local ceiling, body = { name = 'ceiling' }, { name = 'body' }
      world:add(ceiling, 16, 0, 32, 8)
      world:add(body, 10, 40, 8, 12)
      local x, y, _, len, dx, other = world:moveCornered(body, 10, 0)
      assert.same({ 8, 0, 0, -2, ceiling }, { x, y, len, dx, other })
      assert.same({ 8, 0, 8, 12 }, { world:getRect(body) })

      local plain = newWorld(16)
      plain:add(ceiling, 16, 0, 32, 8)
      plain:add(body, 10, 40, 8, 12)
      local px, py = plain:move(body, 10, 0)
      assert.same({ 10, 8 }, { px, py })
      local cx, cy, _, _, cdx = plain:moveCornered(body, 10, 0, nil, 0)  -- maxNudge 0: off
      assert.same({ 10, 8, 0 }, { cx, cy, cdx })
    end)

    it('does not nudge past maxNudge', function()
      local world = newWorld(16)
      local ceiling, body = { name = 'ceiling' }, { name = 'body' }
      world:add(ceiling, 16, 0, 32, 8)
      world:add(body, 13, 40, 8, 12)
      local x, y, _, _, dx = world:moveCornered(body, 13, 0, nil, 4)
      assert.same({ 13, 8, 0 }, { x, y, dx })
      assert.error_matches(function() world:moveCornered(body, 13, 0, nil, -1) end, 'maxNudge')
    end)
  end)
end
