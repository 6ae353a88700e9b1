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

-- Runs `code` in a fresh interpreter with `env` ("NAME=value ...", quoted) before it; returns
-- its stdout and stderr.
local function runWith(env, code)
  local script = os.tmpname()
  local f = assert(io.open(script, 'w'))
  f:write(('package.cpath = %q .. "/?.so;" .. package.cpath\n'):format(dir))
  f:write(('package.path = %q .. "/?.lua;" .. package.path\n'):format(dir))
  f:write(code)
  f:close()
  local err = os.tmpname()
  local p = io.popen(('%s %s %q 2>%q'):format(env, vm, script, err))
  local out = p:read('*a')
  p:close()
  local e = io.open(err):read('*a')
  os.remove(script)
  os.remove(err)
  return out, e
end

-- The same with TV_RECORD set.
local function run(record, code)
  return runWith(('TV_RECORD=%q'):format(record), code)
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

-- Watching a program live with no code: TV_LIVE=HOST:PORT streams the newest world to a
-- receiver (tv-debugger --listen, tv-replay --listen). The streams themselves are tested with
-- a receiver in tests/lua/love_live.sh; here, what a program sees when the value is wrong or
-- nobody listens: one line, and it runs on.
describe('TV_LIVE', function()
  local program = [[
    local tv = require 'tunnelvision'
    local bump = require 'tunnelvision.bump'
    local world = bump.newWorld()
    world:add('p', 0, 0, 5, 5)
    for i = 1, 10 do world:move('p', i, 0); tv.frame() end
    print('played', world:isRecording())
  ]]

  it('that is not an address says so, naming the value, and the program runs unstreamed', function()
    for value, why in pairs({
      ['localhost'] = 'has no port number',
      ['127.0.0.1:99999'] = 'has a port outside 1..65535',
      [':7720'] = "has no host before ':'",
    }) do
      local out, err = runWith(('TV_LIVE=%q'):format(value), program)
      assert.equal('played\tfalse\n', out)
      assert.equal("tunnelvision: TV_LIVE: '" .. value .. "' " .. why ..
                   " (expected HOST:PORT or PORT, e.g. 127.0.0.1:7720); the game runs without streaming\n", err)
    end
  end)

  it('with nobody listening says so once, and the program runs on without waiting', function()
    -- Port 1: nobody listens there, and a connect is refused at once.
    -- The connect is tried on the recorder's own thread, which a loaded machine may not run
    -- before a ten-frame program ends: this one plays frames for a second or two.
    local started = os.time()
    local out, err = runWith('TV_LIVE=127.0.0.1:1', [[
      local tv = require 'tunnelvision'
      local bump = require 'tunnelvision.bump'
      local world = bump.newWorld()
      world:add('p', 0, 0, 5, 5)
      local t0, i = os.time(), 0
      while os.time() - t0 < 2 do i = i + 1; world:move('p', i % 100, 0); tv.frame() end
      print('played', world:isRecording())
    ]])
    assert.equal('played\ttrue\n', out)
    local _, said = err:gsub('no receiver at 127%.0%.0%.1:1 %(connection refused%)', '')
    assert.equal(1, said, err)
    assert.is_true(os.time() - started < 10)
  end)

  it('with TV_RECORD too writes the file as well; a newer world takes the stream over and ends the older one', function()
    local base = os.tmpname()
    local path = base .. '.tvrec'
    local out = runWith(('TV_RECORD=%q TV_LIVE=127.0.0.1:1'):format(path), [[
      local tv = require 'tunnelvision'
      local bump = require 'tunnelvision.bump'
      local level1 = bump.newWorld()              -- streams, and records into game.tvrec
      level1:add('p', 0, 0, 5, 5)
      for i = 1, 4 do level1:move('p', i, 0); tv.frame() end
      local level2 = bump.newWorld()              -- a level reloaded: it streams now
      level2:add('q', 0, 0, 5, 5)
      for i = 1, 6 do level2:move('q', i, 0); tv.frame() end
      print(level1:isRecording(), level2:isRecording())
    ]])
    assert.equal('false\ttrue\n', out)
    -- level 1's file ended when level 2 was made: frame 0 and four more, closed.
    local frames1, report1 = summary(path)
    assert.equal(5, frames1)
    assert.truthy(report1:find('4 moves'), report1)
    local frames2, report2 = summary(base .. '.2.tvrec')
    assert.equal(7, frames2)
    assert.truthy(report2:find('6 moves'), report2)
    os.remove(path)
    os.remove(base .. '.2.tvrec')
    os.remove(base)
  end)
end)
