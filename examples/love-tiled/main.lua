-- A Tiled map played on tunnelvision.bump, its solids loaded the way STI's bump plugin loads a
-- map into bump.lua: every tile whose tileset tile has the property `collidable`, every tile of
-- a tile layer that has it, every rectangle of an object layer that has it and every object
-- that has it itself becomes one item of the world, so seams between tiles are real (and, on
-- tunnelvision.bump, never snag). A game using STI keeps `map:bump_init(world)`; this file does
-- the same in a few lines so the example needs nothing but LÖVE and tunnelvision.so.
--
--   love .                                   play: arrows or A/D to run, Space/Up/W to jump
--   love . --frames 600                      play itself, check what it saw, exit 0 or 1
--   love . --frames 600 --expect-solids N    ... and that the map gave N collidable items
--
-- Without tunnelvision.so in this directory (or the save directory), the module is looked for in
-- $TV_LUA_MODULE_DIR and then in package.cpath.
local dir = os.getenv('TV_LUA_MODULE_DIR')
if dir then package.cpath = dir .. '/?.so;' .. package.cpath end

local bump = require 'tunnelvision.bump'

local map = love.filesystem.load('meadow.lua')()
local GRAVITY = map.properties.gravity or 1800  -- px/s², a map property

-- [STI's bump plugin, in effect] -----------------------------------------------------------------

-- The tileset tile of a gid (flip flags, the top four bits, masked off), or nil.
local function tileOf(gid)
  gid = gid % 0x10000000
  for i = #map.tilesets, 1, -1 do
    local ts = map.tilesets[i]
    if gid >= ts.firstgid then
      for _, tile in ipairs(ts.tiles or {}) do
        if tile.id == gid - ts.firstgid then return tile end
      end
      return nil
    end
  end
end

local function collidable(t) return t and t.properties and t.properties.collidable == true end

-- Adds one item per collidable tile and rectangle; returns them.
local function addCollidables(world)
  local solids = {}
  local function add(kind, x, y, w, h)
    local item = { kind = kind, name = ('%s %d'):format(kind, #solids + 1) }
    world:add(item, x, y, w, h)
    solids[#solids + 1] = item
  end
  for _, layer in ipairs(map.layers) do
    local ox, oy = layer.offsetx or 0, layer.offsety or 0
    if layer.type == 'tilelayer' then
      for i, gid in ipairs(layer.data) do
        if gid ~= 0 and (collidable(layer) or collidable(tileOf(gid))) then
          local col, row = (i - 1) % layer.width, math.floor((i - 1) / layer.width)
          add('tile', (layer.x + col) * map.tilewidth + ox, (layer.y + row) * map.tileheight + oy,
              map.tilewidth, map.tileheight)
        end
      end
    elseif layer.type == 'objectgroup' then
      for _, o in ipairs(layer.objects) do
        if (collidable(layer) or collidable(o)) and o.shape == 'rectangle' and o.width > 0 then
          add('platform', o.x + ox, o.y + oy, o.width, o.height)
        end
      end
    end
  end
  return solids
end

-- [the game] -------------------------------------------------------------------------------------

local world, solids, bodies, player
local frame, maxFrames, expectSolids, failures = 0, nil, nil, {}

local function isSolid(other) return other.kind == 'tile' or other.kind == 'platform' end

-- The actors layer: a player, walkers, a turret's bullets and a drop (as tv::level reads them).
local function addActors()
  bodies = {}
  local function body(b, x, y, w, h)
    world:add(b, x, y, w, h)
    bodies[#bodies + 1] = b
    return b
  end
  for _, layer in ipairs(map.layers) do
    for _, o in ipairs(layer.type == 'objectgroup' and layer.objects or {}) do
      local p = o.properties or {}
      if o.type == 'player' then
        local jump = p.jump or 3.5 * map.tileheight
        player = body({ kind = 'player', name = o.name, vx = p.speed or 150, vy = 0, falls = true,
                        jumpSpeed = math.sqrt(2 * GRAVITY * jump), every = p.every or 45,
                        startX = o.x - 6, startY = o.y - 12 }, o.x - 6, o.y - 12, 12, 12)
      elseif o.type == 'walker' then
        local vx = (p.speed or 150) * (p.direction == 'left' and -1 or 1)
        body({ kind = 'walker', name = o.name, vx = vx, vy = 0, falls = true }, o.x, o.y,
             o.width, o.height)
      elseif o.type == 'spawner' or o.type == 'bullet' then
        local count, size = o.type == 'spawner' and p.count or 1, p.size or 4
        local angle = math.rad(p.angle or 0)
        for k = 1, count do
          -- a spawner lines its bullets up along its longer side
          local x, y = o.x, o.y
          if o.type == 'spawner' then
            if o.height >= o.width then y = o.y + (k - 0.5) * o.height / count - size / 2
            else x = o.x + (k - 0.5) * o.width / count - size / 2 end
          end
          body({ kind = 'bullet', name = ('%s %d'):format(o.name, k), falls = false,
                 vx = (p.speed or 960) * math.cos(angle), vy = (p.speed or 960) * math.sin(angle) },
               x, y, size, size)
        end
      end
    end
  end
end

local function filter(item, other)
  if isSolid(other) then return item.kind == 'bullet' and 'touch' or 'slide' end
  return nil  -- bodies pass each other
end

local function step(b, dt)
  if b.stopped then return end
  if b.falls then b.vy = b.vy + GRAVITY * dt end
  local x, y = world:getRect(b)
  local ax, ay, cols, len = world:move(b, x + b.vx * dt, y + b.vy * dt, filter)
  b.onGround = false
  for i = 1, len do
    local n = cols[i].normal
    if b.kind == 'bullet' then b.stopped, b.hit = true, cols[i].other end
    if n.y < 0 then b.onGround, b.vy = true, 0 elseif n.y > 0 then b.vy = 0 end
    if n.x ~= 0 and b.kind ~= 'player' then b.vx = -b.vx end
  end
  -- the segment from where it was to where it is crosses no solid: nothing passed through one
  local cx, cy = x + 0.5, y + 0.5
  local through = world:querySegment(cx, cy, ax + 0.5, ay + 0.5, isSolid)
  if #through > 0 and maxFrames then
    failures[#failures + 1] = ('frame %d: %s passed through %s'):format(frame, b.name, through[1].name)
  end
  if ay > map.height * map.tileheight + 64 and b == player then  -- fell out: back to the start
    world:update(b, b.startX, b.startY)
    b.vy = 0
  end
end

function love.load(args)
  for i = 1, #args do
    if args[i] == '--frames' then maxFrames = tonumber(args[i + 1]) end
    if args[i] == '--expect-solids' then expectSolids = tonumber(args[i + 1]) end
  end
  if maxFrames then
    function love.errorhandler(msg)  -- playing itself (CI): an error is exit status 1
      print('ERROR ' .. debug.traceback(tostring(msg), 2))
      os.exit(1)
    end
  end
  world = bump.newWorld(4 * map.tilewidth)
  solids = addCollidables(world)
  addActors()
end

function love.update(dt)
  frame = frame + 1
  dt = maxFrames and 1 / 60 or math.min(dt, 1 / 30)  -- a fixed step when playing itself
  if maxFrames then
    if player.onGround and frame % player.every == 0 then player.vy = -player.jumpSpeed end
  else
    local dirX = (love.keyboard.isDown('right', 'd') and 1 or 0) - (love.keyboard.isDown('left', 'a') and 1 or 0)
    player.vx = dirX * 130
    if player.onGround and love.keyboard.isDown('space', 'up', 'w') then player.vy = -player.jumpSpeed end
  end
  for _, b in ipairs(bodies) do step(b, dt) end
  if maxFrames then
    for _, b in ipairs(bodies) do  -- nothing ends a frame inside a solid
      local x, y, w, h = world:getRect(b)
      local inside = world:queryRect(x, y, w, h, isSolid)
      if #inside > 0 then failures[#failures + 1] = ('frame %d: %s inside %s'):format(frame, b.name, inside[1].name) end
    end
    if frame >= maxFrames then
      local stopped = 0
      for _, b in ipairs(bodies) do if b.kind == 'bullet' and b.stopped then stopped = stopped + 1 end end
      local x = world:getRect(player)
      if expectSolids and #solids ~= expectSolids then
        failures[#failures + 1] = ('%d collidable items, expected %d'):format(#solids, expectSolids)
      end
      if x - player.startX < 100 then failures[#failures + 1] = ('the player only got %.1f px far'):format(x - player.startX) end
      for _, f in ipairs(failures) do print('FAIL ' .. f) end
      print(('%d frames, %d collidable items, %d bullets stopped on a solid, player at x=%.2f, %s')
        :format(frame, #solids, stopped, x, #failures == 0 and 'ok' or 'FAILED'))
      love.event.quit(#failures == 0 and 0 or 1)
    end
  end
end

function love.keypressed(key)
  if key == 'escape' then love.event.quit() end
end

function love.draw()
  local px = world:getRect(player)
  love.graphics.push()
  love.graphics.translate(math.floor(math.min(0, 320 - px)), 0)
  local colours = { tile = { 0.35, 0.4, 0.5 }, platform = { 0.8, 0.8, 0.9 }, player = { 0.3, 0.9, 0.5 },
                    walker = { 0.9, 0.3, 0.3 }, bullet = { 1, 0.85, 0.2 } }
  for _, item in ipairs(world:getItems()) do
    local x, y, w, h = world:getRect(item)
    love.graphics.setColor(colours[item.kind] or { 1, 1, 1 })
    love.graphics.rectangle('fill', x, y, w, h)
  end
  love.graphics.pop()
  love.graphics.setColor(1, 1, 1)
  love.graphics.print(('%d collidable items from the map   frame %d'):format(#solids, frame), 8, 8)
end
