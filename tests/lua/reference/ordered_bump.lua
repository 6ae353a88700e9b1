-- bump.lua itself (a file the caller names, never part of this repository), loaded so that the
-- orders it leaves to Lua's hash tables are fixed: its `pairs` over items run in the order the
-- items were first added, and its sorts are stable. That is one of the orders bump.lua can
-- produce, and the one tunnelvision.bump documents, so that a comparison is repeatable.
--
--   local ordered = dofile('tests/lua/reference/ordered_bump.lua')
--   local bump = ordered.load(source, chunkName)   -- source: bump.lua's text
--   ordered.serial[item]                           -- the add order of an item
local M = { serial = {} }
local serial, nextSerial = M.serial, 0

function M.remember(item)
  if serial[item] == nil then
    nextSerial = nextSerial + 1
    serial[item] = nextSerial
  end
end

local function orderedPairs(t)
  local keys = {}
  for k in next, t do keys[#keys + 1] = k end
  table.sort(keys, function(a, b)
    local sa, sb = serial[a], serial[b]
    if sa and sb then return sa < sb end
    if sa or sb then return sa ~= nil end
    local ta, tb = type(a), type(b)
    if ta ~= tb then return ta < tb end
    if ta == 'number' or ta == 'string' then return a < b end
    return tostring(a) < tostring(b)
  end)
  local i = 0
  return function()
    i = i + 1
    local k = keys[i]
    if k ~= nil then return k, t[k] end
  end, t, nil
end

-- Merge sort: equal elements keep the order they came in.
local function stableSort(t, less)
  less = less or function(a, b) return a < b end
  local n = #t
  if n < 2 then return end
  local src, dst, width = t, {}, 1
  while width < n do
    for lo = 1, n, 2 * width do
      local mid, hi = math.min(lo + width, n + 1), math.min(lo + 2 * width, n + 1)
      local i, j, k = lo, mid, lo
      while i < mid and j < hi do
        if less(src[j], src[i]) then dst[k] = src[j]; j = j + 1 else dst[k] = src[i]; i = i + 1 end
        k = k + 1
      end
      while i < mid do dst[k] = src[i]; i = i + 1; k = k + 1 end
      while j < hi do dst[k] = src[j]; j = j + 1; k = k + 1 end
    end
    src, dst = dst, src
    width = width * 2
  end
  if src ~= t then for i = 1, n do t[i] = src[i] end end
end

function M.load(source, name)
  local chunk = assert(loadstring(source, name))
  setfenv(chunk, setmetatable({
    pairs = orderedPairs,
    table = setmetatable({ sort = stableSort }, { __index = table }),
  }, { __index = _G }))
  local bump = chunk()
  -- Every world's add remembers the item's order (bump's World methods, shared by its worlds).
  local newWorld = bump.newWorld
  bump.newWorld = function(...)
    local world = newWorld(...)
    local World = getmetatable(world).__index
    if not World.tvOrdered then
      local add = World.add
      World.add = function(self, item, ...)
        M.remember(item)
        return add(self, item, ...)
      end
      World.tvOrdered = true
    end
    return world
  end
  return bump
end

return M
