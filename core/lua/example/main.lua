-- A small platformer written against bump.lua's API. Besides the require, the only
-- Tunnelvision-specific calls are world:frame() and the recording (--record): remove those and
-- swap the require for `require 'bump'`, and the game runs on bump.lua 3.1.7.
--
--   love .                        play: arrows or A/D to run, Space/Up/W to jump
--   love . --frames 300           play itself for 300 frames, check what it saw, exit 0 or 1
--   love . --frames 300 --record game.tvrec   ... and record it for tv-debugger / tv-replay
--
-- Without tunnelvision.so in this directory (or the save directory), the module is looked for
-- in $TV_LUA_MODULE_DIR and then in package.cpath.
local dir = os.getenv('TV_LUA_MODULE_DIR')
if dir then
  package.cpath = dir .. '/?.so;' .. package.cpath
  package.path = dir .. '/?.lua;' .. package.path
end

local bump = require 'tunnelvision.bump'

local TILE = 16
local MAP = {
  '                                                                                ',
  '                                                                                ',
  '                                   c  c  c                                      ',
  '                                  =========                c c c                ',
  '               c c                                        #######               ',
  '              =====                  e                                    c     ',
  '                          #####################                         =====   ',
  '         c                                                                      ',
  '  p     ===                                          e            c             ',
  '################   ####################################  ########################',
  '################   ####################################  ########################',
}

local world, player, enemies, coins, solids, firstCoinX
local frame, maxFrames, recordPath, failures = 0, nil, nil, {}
local input = { left = false, right = false, jump = false }
local score = 0

local function build()
  world = bump.newWorld(TILE * 2)
  enemies, coins, solids = {}, {}, 0
  for row, line in ipairs(MAP) do
    for col = 1, #line do
      local ch = line:sub(col, col)
      local x, y = (col - 1) * TILE, (row - 1) * TILE
      if ch == '#' then
        world:add({ name = ('tile %d,%d'):format(col, row), kind = 'solid' }, x, y, TILE, TILE)
        solids = solids + 1
      elseif ch == '=' then
        world:add({ name = ('cloud %d,%d'):format(col, row), kind = 'cloud' }, x, y, TILE, 4)
      elseif ch == 'c' then
        local coin = { name = ('coin %d'):format(#coins + 1), kind = 'coin' }
        coins[#coins + 1] = coin
        if not firstCoinX or x < firstCoinX then firstCoinX = x end
        world:add(coin, x + 4, y + 4, 8, 8)
      elseif ch == 'e' then
        local e = { name = ('enemy %d'):format(#enemies + 1), kind = 'enemy', vx = 40 }
        enemies[#enemies + 1] = e
        world:add(e, x, y + 4, 12, 12)
      elseif ch == 'p' then
        -- a height that is not a power-of-two fraction: bump.lua snags such bodies on seams
        player = { name = 'player', kind = 'player', vx = 0, vy = 0, onGround = false, startX = x }
        world:add(player, x, y + TILE - 13.7, 10, 13.7)
      end
    end
  end
end

-- Solids block; clouds only from above; coins and enemies are walked through and reported.
local function playerFilter(item, other)
  if other.kind == 'coin' or other.kind == 'enemy' then return 'cross' end
  if other.kind == 'cloud' then
    local _, y, _, h = world:getRect(item)
    local _, oy = world:getRect(other)
    if item.vy >= 0 and y + h <= oy then return 'slide' end
    return nil
  end
  return 'slide'
end

local function enemyFilter(_, other)
  if other.kind == 'solid' or other.kind == 'enemy' then return 'slide' end
  return nil
end

local GRAVITY, RUN, JUMP = 900, 110, 330

local function updatePlayer(dt)
  local p = player
  p.vx = (input.right and RUN or 0) - (input.left and RUN or 0)
  p.vy = math.min(p.vy + GRAVITY * dt, 600)
  if input.jump and p.onGround then p.vy = -JUMP end
  local x, y = world:getRect(p)
  local ax, ay, cols, len = world:move(p, x + p.vx * dt, y + p.vy * dt, playerFilter)
  p.onGround = false
  for i = 1, len do
    local col = cols[i]
    if col.other.kind == 'coin' and world:hasItem(col.other) then
      world:remove(col.other)
      score = score + 1
    elseif col.type == 'slide' then
      if col.normal.y < 0 then p.onGround, p.vy = true, 0 end
      if col.normal.y > 0 then p.vy = 0 end
    end
  end
  if ay > #MAP * TILE + 64 then  -- fell into the pit: back to the start
    world:update(p, p.startX, 0)
    p.vy = 0
  end
  return ax, ay
end

local function updateEnemies(dt)
  for _, e in ipairs(enemies) do
    local x, y = world:getRect(e)
    local _, _, cols, len = world:move(e, x + e.vx * dt, y + 60 * dt, enemyFilter)
    for i = 1, len do
      if cols[i].normal.x ~= 0 then e.vx = -e.vx end
    end
  end
end

-- What the self-playing run checks every frame: the player is never inside a solid.
local function check()
  local x, y, w, h = world:getRect(player)
  local inside = world:queryRect(x, y, w, h, function(other) return other.kind == 'solid' end)
  if #inside > 0 then failures[#failures + 1] = ('frame %d: player inside %s'):format(frame, inside[1].name) end
end

function love.load(args)
  for i = 1, #args do
    if args[i] == '--frames' then maxFrames = tonumber(args[i + 1]) end
    if args[i] == '--record' then recordPath = args[i + 1] end
  end
  if maxFrames then
    -- playing itself (CI): an error ends the run with status 1, not on LÖVE's error screen
    function love.errorhandler(msg)
      print('ERROR ' .. debug.traceback(tostring(msg), 2))
      os.exit(1)
    end
  end
  build()
  if recordPath then world:startRecording(recordPath) end
end

local function autoplay()
  -- run right; jump every 50 frames and at the pit's edge
  input.right = true
  local x = world:getRect(player)
  input.jump = frame % 50 == 10 or (x > 220 and x < 250)
end

function love.update(dt)
  frame = frame + 1
  if maxFrames then
    autoplay()
    dt = 1 / 60  -- a fixed step: the same run every time
  else
    input.left = love.keyboard.isDown('left', 'a')
    input.right = love.keyboard.isDown('right', 'd')
    input.jump = love.keyboard.isDown('space', 'up', 'w')
    dt = math.min(dt, 1 / 30)
  end
  updatePlayer(dt)
  updateEnemies(dt)
  world:frame()  -- one rendered frame ends (for a recording; nothing otherwise)
  if maxFrames then
    check()
    if frame >= maxFrames then
      local x = world:getRect(player)
      if recordPath then
        local frames, calls = world:stopRecording()
        if not frames then failures[#failures + 1] = 'recording failed: ' .. tostring(calls) end
        -- the recording must replay bit for bit (what tv-replay --validate checks)
        local ok, report = require('tunnelvision').validateRecording(recordPath)
        print(('recorded %s frames, %s calls into %s: %s'):format(frames, calls, recordPath, report))
        if not ok then failures[#failures + 1] = 'recording diverges: ' .. report end
      end
      -- Running right the whole time, the player covers RUN px a second unless something stops
      -- it (bump.lua snags a 13.7 px body on a seam for good): at least half that, for any
      -- --frames. The script's jumps take the first coin once the player has run past it.
      local expected = RUN * frame / 60
      if x - player.startX < expected / 2 then
        failures[#failures + 1] = ('player only got %.1f px far in %d frames (free running: %.1f)'):format(
          x - player.startX, frame, expected)
      end
      if x > firstCoinX + TILE and score == 0 then failures[#failures + 1] = 'ran past a coin without taking it' end
      for _, f in ipairs(failures) do print('FAIL ' .. f) end
      print(('%d frames, player at x=%.2f, %d coins, %d solids, %s'):format(frame, x, score, solids,
        #failures == 0 and 'ok' or 'FAILED'))
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
  love.graphics.translate(math.floor(math.min(0, 320 - px)), 80)
  local items = world:getItems()
  for _, item in ipairs(items) do
    local x, y, w, h = world:getRect(item)
    if item.kind == 'solid' then love.graphics.setColor(0.35, 0.4, 0.5)
    elseif item.kind == 'cloud' then love.graphics.setColor(0.8, 0.8, 0.9)
    elseif item.kind == 'coin' then love.graphics.setColor(1, 0.85, 0.2)
    elseif item.kind == 'enemy' then love.graphics.setColor(0.9, 0.3, 0.3)
    else love.graphics.setColor(0.3, 0.9, 0.5) end
    love.graphics.rectangle('fill', x, y, w, h)
  end
  love.graphics.pop()
  love.graphics.setColor(1, 1, 1)
  love.graphics.print(('coins %d   cells %d   frame %d'):format(score, world:countCells(), frame), 8, 8)
end
