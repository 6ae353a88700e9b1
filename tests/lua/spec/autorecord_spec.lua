-- Recording a game without changing it: TV_RECORD=game.tvrec, or one line of code,
-- tunnelvision.record('game.tvrec'). Every world gets a file (game.tvrec, game.2.tvrec, ...);
-- under LÖVE a frame is marked after each step of love.run, and the files are closed when the
-- game quits or its error handler runs.
local tv = require 'tunnelvision'
local bump = tv.bump

local dir = assert(os.getenv('TV_LUA_MODULE_DIR'))
local vm = jit and 'luajit' or 'lua5.1'

local function exists(path)
  local f = io.open(path)
  if f then f:close() end
  return f ~= nil
end

local function summary(path)
  local ok, report = tv.validateRecording(path)
  assert.is_true(ok, report)
  return tonumber(report:match('^(%d+) frames')), report
end

-- Runs `code` in a fresh interpreter with TV_RECORD set; returns its stdout and stderr.
local function run(record, code)
  local script = os.tmpname()
  local f = assert(io.open(script, 'w'))
  f:write(('package.cpath = %q .. "/?.so;" .. package.cpath\n'):format(dir))
  f:write(('package.path = %q .. "/?.lua;" .. package.path\n'):format(dir))
  f:write(code)
  f:close()
  local err = os.tmpname()
  local p = io.popen(('TV_RECORD=%q %s %q 2>%q'):format(record, vm, script, err))
  local out = p:read('*a')
  p:close()
  local e = io.open(err):read('*a')
  os.remove(script)
  os.remove(err)
  return out, e
end

describe('tunnelvision.record(path)', function()
  it('records every world into its own file, numbered, with frames from tunnelvision.frame', function()
    local base = os.tmpname()
    local path = base .. '.tvrec'
    local before = bump.newWorld()          -- alive at record(): recorded too
    before:add({ name = 'early' }, 0, 0, 1, 1)
    tv.record(path)
    local w = bump.newWorld()
    w:add({ name = 'player' }, 0, 0, 10, 10)
    for i = 1, 5 do
      w:move(w:getItems()[1], i, 0)
      tv.frame()
    end
    tv.stopRecording()
    -- Every world alive got a file (other specs' worlds may be alive too): find ours.
    local files, byLabel = {}, {}
    for n = 1, 100 do
      local f = n == 1 and path or (base .. '.' .. n .. '.tvrec')
      if not exists(f) then break end
      files[#files + 1] = f
      for _, item in ipairs(tv.recordingItems(f)) do byLabel[item.label] = f end
    end
    assert.is_true(#files >= 2)
    assert.is_not_nil(byLabel.early)
    assert.equal(6, (summary(byLabel.player)))
    -- after stopRecording, new worlds are not recorded
    bump.newWorld():add('x', 0, 0, 1, 1)
    assert.is_false(exists(base .. '.' .. (#files + 1) .. '.tvrec'))
    for _, f in ipairs(files) do os.remove(f) end
    os.remove(base)
  end)

  it('refuses a path it cannot write, naming it, and records nothing', function()
    assert.has_error(function() tv.record('/nonexistent-dir/game.tvrec') end,
      "tunnelvision.record: cannot write '/nonexistent-dir/game.tvrec': No such file or directory")
    local w = bump.newWorld()
    assert.is_false(w:isRecording())
  end)
end)

describe('TV_RECORD', function()
  it('records a plain Lua program that never mentions recording', function()
    local path = os.tmpname() .. '.tvrec'
    local out = run(path, [[
      local bump = require 'tunnelvision.bump'
      local world = bump.newWorld()
      world:add('floor', 0, 10, 100, 10)
      world:add('p', 0, 0, 5, 5)
      for i = 1, 10 do world:move('p', i, i) end
      print('played')
    ]])
    assert.equal('played\n', out)
    local frames, report = summary(path)
    assert.equal(1, frames)   -- no love.run: one frame
    assert.truthy(report:find('10 moves'))
    os.remove(path)
  end)

  it('with a path it cannot write says so once, and the program runs on', function()
    local out, err = run('/nonexistent-dir/game.tvrec', [[
      local bump = require 'tunnelvision.bump'
      local world = bump.newWorld()
      world:add('p', 0, 0, 5, 5)
      world:move('p', 3, 3)
      print('played')
    ]])
    assert.equal('played\n', out)
    assert.equal("tunnelvision: TV_RECORD=/nonexistent-dir/game.tvrec: cannot write " ..
                 "'/nonexistent-dir/game.tvrec': No such file or directory; the game runs without recording\n", err)
  end)

  -- LÖVE's boot, as love 11 does it: love.run() returns the main loop's step, called until it
  -- returns an exit code; on an error, love.errorhandler (or love.errhand) runs.
  local fakeLove = [[
    love = {}
    function love.errhand(msg) print('handled: ' .. msg) end
    local bump = require 'tunnelvision.bump'     -- the game's require, at the top of main.lua
    local world = bump.newWorld()
    world:add('p', 0, 0, 5, 5)
    function love.update(dt) world:move('p', select(1, world:getRect('p')) + 1, 0) end
    function love.run()                          -- defined after the require, as games do
      local n = 0
      return function()
        n = n + 1
        if FAIL and n == 3 then error('boom') end
        love.update(1 / 60)
        if n == 5 then return 0 end
      end
    end
    local main = love.run()                      -- what boot.lua does
    local ok, err = pcall(function() while true do if main() then break end end end)
    if not ok then love.errhand(err) end
    print('frames played')
  ]]

  it('under LÖVE marks a frame per step of love.run and closes the file when the game quits', function()
    local path = os.tmpname() .. '.tvrec'
    local out = run(path, fakeLove)
    assert.equal('frames played\n', out)
    local frames, report = summary(path)
    assert.equal(6, frames)    -- frame 0 (love.load's), then one per step
    assert.truthy(report:find('5 moves'))
    os.remove(path)
  end)

  it('under LÖVE closes the file when the game fails, before its error handler runs', function()
    local path = os.tmpname() .. '.tvrec'
    local out = run(path, 'FAIL = true\n' .. fakeLove)
    assert.truthy(out:find('handled: .*boom'))
    local frames, report = summary(path)
    assert.equal(3, frames)
    assert.truthy(report:find('2 moves'))
    os.remove(path)
  end)
end)
