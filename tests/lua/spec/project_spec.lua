-- world:project on a world with the core's rules lists the straight leg's hits as the core's
-- moves take them (World::hitsAlong): its first collision is world:check's first collision,
-- also where two faces lie a rounding apart and a sort on the rounded ti would pick the farther.
local tv = require 'tunnelvision'

local function touchAll() return 'touch' end

describe('world:project on a core world', function()
  --        far  (added first)  |G####|        G = F + 1 ulp (2^-30 at 5e6)
  --   [m]------------------>  |F####|         near (added second)
  --   0                       F ~ 5e6
  it('lists the nearer of two faces a rounding apart first, as world:check meets it', function()
    local F = 5024691.3560000006
    local G = F + 2 ^ -30
    assert.is_true(G > F)
    local world = tv.newWorld(64)
    world:add('far', G, -50, 10, 100)
    world:add('near', F, -50, 10, 100)
    world:add('m', 0, 0, 1, 1)
    local cols, len = world:project('m', 0, 0, 1, 1, 1e7, 0, touchAll)
    assert.equal(2, len)
    assert.same({ 'near', 'far' }, { cols[1].other, cols[2].other })
    local _, _, checked = world:check('m', 1e7, 0, touchAll)
    assert.equal(cols[1].other, checked[1].other)
    assert.equal(F, cols[1].touch.x + 1)
    -- Negative control: the rounded ti are equal, so a sort on them keeps add order: far first.
    assert.equal(cols[1].ti, cols[2].ti)
    local byTi = { { other = 'far', ti = cols[2].ti }, { other = 'near', ti = cols[1].ti } }
    table.sort(byTi, function(a, b) return a.ti < b.ti end)   -- equal keys: no swap needed
    assert.equal('far', byTi[1].other)
  end)

  -- A field of 16 px tiles at decimal offsets (0.1 * 3 and 0.3 are an ulp apart), twins of some
  -- tiles at the other decimal; random legs: project's first collision is check's, field by field.
  it('agrees with world:check\'s first collision on random legs over a tile field', function()
    math.randomseed(2024)
    local world = tv.newWorld(16)
    local n = 0
    for row = 0, 15 do
      for col = 0, 15 do
        if math.random() < 0.3 then
          n = n + 1
          world:add('t' .. n, col * 16 + 0.1 * 3, row * 16 + 0.1 * math.random(0, 3), 16, 16)
          if math.random() < 0.3 then
            n = n + 1
            world:add('t' .. n, col * 16 + 0.3, row * 16 + 0.3, 16, 16)
          end
        end
      end
    end
    local legs, met = 0, 0
    for _ = 1, 400 do
      local x, y = math.random() * 290 - 20, math.random() * 290 - 20
      local w, h = 0.5 + math.random() * 19, 0.5 + math.random() * 19
      local gx, gy = x + math.random() * 400 - 200, y + math.random() * 400 - 200
      world:add('m', x, y, w, h)
      local cols, len = world:project('m', x, y, w, h, gx, gy, touchAll)
      local _, _, checked, clen = world:check('m', gx, gy, touchAll)
      legs = legs + 1
      if len == 0 then
        assert.equal(0, clen)
      else
        met = met + 1
        assert.is_true(clen >= 1)   -- more after an overlap's push out: the first is compared
        local a, b = cols[1], checked[1]
        assert.same({ a.other, a.ti, a.touch, a.normal, a.overlaps },
                    { b.other, b.ti, b.touch, b.normal, b.overlaps })
      end
      world:remove('m')
    end
    assert.equal(400, legs)
    assert.is_true(met > 200)
  end)
end)
