-- tunnelvision.bump against bump.lua itself, move by move, on random worlds shaped like games
-- (tiles of odd sizes, bodies inside solids, every response, filters that ignore). bump.lua is
-- not part of this repository: TV_BUMP_LUA names its file (tests/lua/games/fetch.sh fetches
-- it); without it these are pending. Its hash orders are fixed (reference/ordered_bump.lua),
-- so that both sides are repeatable.
--
-- Each trial builds the same world in both, makes one move (or check, project, query) from the
-- same state and compares every returned value bit for bit. A difference must be one the README
-- documents: bump's contact a rounding step inside what it touched (ours is on the edge), or
-- bump passing into something its move already met (ours stops against it).
local source = os.getenv('TV_BUMP_LUA')
local here = debug.getinfo(1, 'S').source:match('^@(.*)/spec/[^/]*$') or '.'

local function read(path)
  local f = io.open(path)
  if not f then return nil end
  local s = f:read('*a')
  f:close()
  return s
end

local text = source and read(source)
if not text then
  describe('against bump.lua', function()
    pending('TV_BUMP_LUA does not name bump.lua 3.1.7: run tests/lua/games/fetch.sh DIR, then TV_BUMP_LUA=DIR/bump.lua/bump.lua')
  end)
  return
end

local ordered = dofile(here .. '/reference/ordered_bump.lua')
local ref = ordered.load(text, '@bump.lua')
local ours = require 'tunnelvision.bump'

-- A small deterministic generator (the same numbers under both VMs).
local function rng(seed)
  local s = seed
  return function(a, b)
    s = (s * 1103515245 + 12345) % 2147483648
    local u = s / 2147483648
    if a then return a + (b - a) * u end
    return u
  end
end

local sizes = { 16, 13.7, 10, 8, 32, 6.5, 20.25 }

local function scene(seed)
  local r = rng(seed)
  local cell = ({ 16, 32, 64, 50 })[1 + math.floor(r() * 4)]
  local items = {}
  for i = 0, 11 do   -- a floor of tiles, some with odd sizes
    items[#items + 1] = { name = 'tile' .. i, i * 16, 100, 16, 16 }
  end
  for i = 1, 10 do   -- blocks and bodies anywhere, inside each other too
    local w, h = sizes[1 + math.floor(r() * #sizes)], sizes[1 + math.floor(r() * #sizes)]
    items[#items + 1] = { name = 'b' .. i, math.floor(r(-20, 180) * 4) / 4 + (r() < 0.3 and 0.1 or 0),
                          math.floor(r(0, 110) * 4) / 4, w, h }
  end
  return cell, items, r
end

local responses = { 'slide', 'touch', 'cross', 'bounce' }

local function build(bump, cell, items)
  local world = bump.newWorld(cell)
  local byName = {}
  for _, it in ipairs(items) do
    local item = { name = it.name }
    byName[it.name] = item
    world:add(item, it[1], it[2], it[3], it[4])
  end
  return world, byName
end

-- Flattens a move's results so that two can be compared: names, not tables.
local function flat(x, y, cols, len)
  local out = { ('%.17g %.17g %d'):format(x, y, len) }
  for i = 1, len do
    local c = cols[i]
    out[#out + 1] = ('%s %s %s ti=%.17g move=%.17g,%.17g n=%g,%g touch=%.17g,%.17g ir=%.17g,%.17g or=%.17g,%.17g s=%s b=%s'):format(
      c.other.name, c.type, tostring(c.overlaps), c.ti, c.move.x, c.move.y, c.normal.x, c.normal.y,
      c.touch.x, c.touch.y, c.itemRect.x, c.itemRect.y, c.otherRect.x, c.otherRect.y,
      c.slide and ('%.17g,%.17g'):format(c.slide.x, c.slide.y) or '-',
      c.bounce and ('%.17g,%.17g'):format(c.bounce.x, c.bounce.y) or '-')
  end
  return table.concat(out, '\n')
end

-- Why two results differ, when the README says they may: bump's contact a rounding step inside
-- what it touched, or our move meeting an item again where bump's passed into it.
local function why(w, h, refCols, refLen, ourCols, ourLen)
  for i = 1, refLen do
    local c, o = refCols[i], refCols[i].otherRect
    local tx, ty = c.touch.x, c.touch.y
    if tx < o.x + o.w and o.x < tx + w and ty < o.y + o.h and o.y < ty + h then
      return 'bump\'s contact inside what it touched'
    end
  end
  local seen = {}
  for i = 1, ourLen do
    if seen[ourCols[i].other] then return 'bump passes into what it met' end
    seen[ourCols[i].other] = true
  end
  return nil
end

describe('against bump.lua', function()
  it('moves return what bump.lua returns, move by move, but where the README says', function()
    local trials, same, reasons, unexplained = 0, 0, {}, {}
    for seed = 1, 400 do
      local cell, items, r = scene(seed)
      local rw, rItems = build(ref, cell, items)
      local ow, oItems = build(ours, cell, items)
      local answer = {}
      for _, it in ipairs(items) do
        answer[it.name] = r() < 0.15 and false or responses[1 + math.floor(r() * #responses)]
      end
      local filter = function(_, other) return answer[other.name] end
      for _ = 1, 8 do
        local it = items[13 + math.floor(r() * 10)]
        local rx, ry, w, h = rw:getRect(rItems[it.name])
        local gx, gy = rx + r(-40, 40), ry + r(-40, 40)
        if r() < 0.2 then gx, gy = rx, ry end   -- a still move: overlaps decide alone
        local ax, ay, acols, alen = rw:move(rItems[it.name], gx, gy, filter)
        local bx, by, bcols, blen = ow:move(oItems[it.name], gx, gy, filter)
        local a, b = flat(ax, ay, acols, alen), flat(bx, by, bcols, blen)
        trials = trials + 1
        if a == b then
          same = same + 1
        else
          local reason = why(w, h, acols, alen, bcols, blen)
          if reason then
            reasons[reason] = (reasons[reason] or 0) + 1
          else
            unexplained[#unexplained + 1] = { seed = seed, bump = a, ours = b }
          end
          rw:update(rItems[it.name], bx, by)   -- go on from the same state
        end
      end
    end
    print(('\n  against bump.lua: %d moves, %d identical bit for bit'):format(trials, same))
    for reason, n in pairs(reasons) do print(('  %d differ: %s'):format(n, reason)) end
    for i = 1, math.min(3, #unexplained) do
      print(('  unexplained, seed %d\n    bump.lua:\n      %s\n    ours:\n      %s'):format(unexplained[i].seed,
        unexplained[i].bump:gsub('\n', '\n      '), unexplained[i].ours:gsub('\n', '\n      ')))
    end
    assert.equal(3200, trials)
    assert.equal(0, #unexplained)
  end)

  it('queries, project, check and the cells return what bump.lua returns', function()
    local function names(list, len)
      local out = {}
      for i = 1, len do out[i] = list[i].name or list[i].item.name end
      return table.concat(out, ' ')
    end
    local function coords(info, len)
      local out = {}
      for i = 1, len do
        local v = info[i]
        out[i] = ('%s %.17g %.17g %.17g %.17g %.17g %.17g'):format(v.item.name, v.ti1, v.ti2, v.x1, v.y1, v.x2, v.y2)
      end
      return table.concat(out, '\n')
    end
    local function cells(world)
      local out = {}
      for cy, row in pairs(world.rows) do
        for cx, cell in pairs(row) do
          if cell.itemCount > 0 then out[#out + 1] = ('%d,%d:%d'):format(cx, cy, cell.itemCount) end
        end
      end
      table.sort(out)
      return table.concat(out, ' ')
    end
    local sorted = function(s)   -- bump's queryRect/queryPoint order is a hash order: compare sets
      local t = {}
      for w in s:gmatch('%S+') do t[#t + 1] = w end
      table.sort(t)
      return table.concat(t, ' ')
    end
    local compared, total, unexplained = 0, 0, 0
    for seed = 1, 150 do
      local cell, items, r = scene(seed)
      local rw, rItems = build(ref, cell, items)
      local ow, oItems = build(ours, cell, items)
      assert.equal(cells(rw), cells(ow))
      assert.equal(rw:countCells(), ow:countCells())
      for _ = 1, 6 do
        local x, y = r(-30, 200), r(-10, 130)
        local x2, y2 = r(-30, 200), r(-10, 130)
        local w, h = sizes[1 + math.floor(r() * #sizes)], sizes[1 + math.floor(r() * #sizes)]
        assert.equal(sorted(names(rw:queryRect(x, y, w, h))), sorted(names(ow:queryRect(x, y, w, h))))
        assert.equal(sorted(names(rw:queryPoint(x, y))), sorted(names(ow:queryPoint(x, y))))
        assert.equal(names(rw:querySegment(x, y, x2, y2)), names(ow:querySegment(x, y, x2, y2)))
        assert.equal(coords(rw:querySegmentWithCoords(x, y, x2, y2)), coords(ow:querySegmentWithCoords(x, y, x2, y2)))
        local it = items[13 + math.floor(r() * 10)].name
        local px, py, pw, ph = rw:getRect(rItems[it])
        for _, call in ipairs({ 'project', 'check' }) do
          local ra, rb, rc, rl, oa, ob, oc, ol
          if call == 'project' then
            rc, rl = rw:project(rItems[it], px, py, pw, ph, x, y)
            oc, ol = ow:project(oItems[it], px, py, pw, ph, x, y)
            ra, rb, oa, ob = 0, 0, 0, 0
          else
            ra, rb, rc, rl = rw:check(rItems[it], x, y)
            oa, ob, oc, ol = ow:check(oItems[it], x, y)
          end
          total = total + 1
          if flat(ra, rb, rc, rl) == flat(oa, ob, oc, ol) then
            compared = compared + 1
          elseif not why(pw, ph, rc, rl, oc, ol) then
            unexplained = unexplained + 1
          end
        end
      end
    end
    print(('\n  against bump.lua: %d projects and checks, %d identical bit for bit, the rest bump\'s contact inside what it touched'):format(total, compared))
    assert.equal(0, unexplained)
  end)
end)
