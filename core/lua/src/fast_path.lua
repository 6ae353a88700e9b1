-- The fast path under LuaJIT: the hot world methods as Lua functions that call the module's C
-- functions through the FFI. A call through the Lua C API costs a stack of pushes, a table
-- lookup through the C API for the item and a fresh table per result; through the FFI the call
-- compiles into the trace, the item's slot is a table read the JIT compiles too, and results
-- come back in buffers made once. Whatever the fast functions do not handle themselves (a
-- filter, an item not in the world, a goal that is not a finite number, a world in use by one of
-- its filters or responses, responses added from Lua, an error) goes to the C function they
-- replace, which does it, or raises its error, exactly as before: both paths give the same
-- results (the module's specs and bump.lua's run against each).
--
-- tunnelvision.so runs this file once per method table, with: the ffi module, the method table,
-- stateOf(world) (the world's item -> slot, slot -> item, sentinel and response-name tables, or
-- nothing for anything but a world), the C functions' addresses, and the ids of slide and
-- bounce.
local ffi, methods, stateOf, moveAddr, rectAddr, collisionAddr, SLIDE, BOUNCE = ...

-- The same declarations as lua_world.hpp's FastCollision and fast_path.cpp's FastResult. A
-- second load of the module (busted reloads it) finds them declared.
if not pcall(ffi.typeof, 'struct tvlua_fast_collision') then
  ffi.cdef [[
    struct tvlua_fast_collision {
      double ti, moveX, moveY, normalX, normalY, touchX, touchY;
      double itemX, itemY, itemW, itemH, otherX, otherY, otherW, otherH;
      double targetX, targetY;
      int32_t other, response, overlaps, unused;
    };
    struct tvlua_fast_result {
      double x, y;
      const struct tvlua_fast_collision* cols;
      int32_t n, emptied;
    };
  ]]
end

local fastMove = ffi.cast('int (*)(void*, double, double, double, int, struct tvlua_fast_result*)', moveAddr)
local fastRect = ffi.cast('int (*)(void*, double, double*)', rectAddr)
local fastCollision = ffi.cast('int (*)(void*, double, struct tvlua_fast_collision*)', collisionAddr)

local COMMIT, SENTINEL_ALIVE, KEEP_LAST = 1, 2, 4
local result = ffi.new('struct tvlua_fast_result')
local rect = ffi.new('double[4]')
local collision = ffi.new('struct tvlua_fast_collision')

-- Every call below first writes to the buffer the C function fills (`rect[0] = 0`, ...). The
-- write is what keeps the values the caller has read out of it values: LuaJIT 2.1's x86-64
-- backend may fuse a read from a buffer into the instruction that uses the value, reading the
-- memory there instead, and it checks only for stores in between, not for calls. Without a
-- store, `local _, y, _, h = world:getRect(a); local _, oy = world:getRect(b); if y + h <= oy`
-- compiled to an add of b's h (tests/lua/spec/fast_path_jit_spec.lua).

-- world -> its tables, found once per world (weak: a world collected takes its entry along).
local states = setmetatable({}, { __mode = 'k' })
local function state(world)
  local s = states[world]
  if s == nil then
    local itemToSlot, slotToItem, sentinel, names = stateOf(world)
    if itemToSlot == nil then return nil end  -- not a world: the C function says so
    s = { itemToSlot = itemToSlot, slotToItem = slotToItem, sentinel = sentinel, names = names }
    states[world] = s
  end
  return s
end

-- bump's collision tables for a move's `n` collisions, as pushCollision builds them.
local function collisionTables(s, item, n, c)
  local cols = {}
  local slotToItem, names = s.slotToItem, s.names
  for i = 0, n - 1 do
    local k = c[i]
    local response = k.response
    local col = {
      item = item,
      other = slotToItem[k.other + 1],
      type = names[response],
      overlaps = k.overlaps ~= 0,
      ti = k.ti,
      move = { x = k.moveX, y = k.moveY },
      normal = { x = k.normalX, y = k.normalY },
      touch = { x = k.touchX, y = k.touchY },
      itemRect = { x = k.itemX, y = k.itemY, w = k.itemW, h = k.itemH },
      otherRect = { x = k.otherX, y = k.otherY, w = k.otherW, h = k.otherH },
    }
    if response == SLIDE then
      col.slide = { x = k.targetX, y = k.targetY }
    elseif response == BOUNCE then
      col.bounce = { x = k.targetX, y = k.targetY }
    end
    cols[i + 1] = col
  end
  return cols
end

-- Runs a move (flags: COMMIT, KEEP_LAST) without a filter; false when the C function must.
local function run(world, s, item, goalX, goalY, flags)
  if type(goalX) ~= 'number' or type(goalY) ~= 'number' then return false end
  local slot = s.itemToSlot[item]
  if slot == nil then return false end
  -- A cell emptied since the last collection stays counted until the next one (countCells).
  local sentinel = s.sentinel
  if sentinel[1] ~= nil then flags = flags + SENTINEL_ALIVE end
  result.n = 0
  if fastMove(world, slot, goalX, goalY, flags, result) ~= 0 then return false end
  if result.emptied ~= 0 and sentinel[1] == nil then sentinel[1] = {} end
  return true
end

local cMove, cCheck, cGetRect, cGo, cGetCollision =
  methods.move, methods.check, methods.getRect, methods.go, methods.getCollision

local function moveOrCheck(world, item, goalX, goalY, filter, flags)
  if filter ~= nil or item == nil then return nil end
  local s = state(world)
  if s == nil or not run(world, s, item, goalX, goalY, flags) then return nil end
  local n = result.n
  if n == 0 then return result.x, result.y, {}, 0 end
  return result.x, result.y, collisionTables(s, item, n, result.cols), n
end

methods.move = function(world, item, goalX, goalY, filter)
  local x, y, cols, len = moveOrCheck(world, item, goalX, goalY, filter, COMMIT)
  if x == nil then return cMove(world, item, goalX, goalY, filter) end
  return x, y, cols, len
end

methods.check = function(world, item, goalX, goalY, filter)
  local x, y, cols, len = moveOrCheck(world, item, goalX, goalY, filter, 0)
  if x == nil then return cCheck(world, item, goalX, goalY, filter) end
  return x, y, cols, len
end

methods.getRect = function(world, item)
  local s = item ~= nil and state(world)
  if s then
    local slot = s.itemToSlot[item]
    rect[0] = 0
    if slot ~= nil and fastRect(world, slot, rect) == 0 then
      return rect[0], rect[1], rect[2], rect[3]
    end
  end
  return cGetRect(world, item)
end

-- tunnelvision's own: multiple returns only, nothing for the collector.
methods.go = function(world, item, goalX, goalY, filter)
  if filter == nil and item ~= nil then
    local s = state(world)
    if s ~= nil and run(world, s, item, goalX, goalY, COMMIT + KEEP_LAST) then
      return result.x, result.y, result.n
    end
  end
  return cGo(world, item, goalX, goalY, filter)
end

methods.getCollision = function(world, i)
  if type(i) == 'number' then
    local s = state(world)
    collision.unused = 0
    if s ~= nil and fastCollision(world, i, collision) == 0 then
      local c = collision
      return s.slotToItem[c.other + 1], s.names[c.response], c.normalX, c.normalY, c.ti,
             c.touchX, c.touchY, c.overlaps ~= 0, c.targetX, c.targetY
    end
  end
  return cGetCollision(world, i)
end

-- What the fast functions replaced, for benchmarks and tests (tunnelvision._capi).
return { move = cMove, check = cCheck, getRect = cGetRect, go = cGo, getCollision = cGetCollision }
