-- world:startRecording / stopRecording: a game's calls into a .tvrec file that replays bit for
-- bit (tunnelvision.validateRecording is tv-replay --validate from Lua).
local tv = require 'tunnelvision'

local function tmpfile()
  local path = os.tmpname()
  return path
end

describe('recording', function()
  it('records a play-through, filters and Lua responses included, that replays bit for bit', function()
    local path = tmpfile()
    local world = tv.newWorld(16)
    for i = 0, 20 do world:add({ name = 'tile ' .. i, kind = 'tile' }, i * 16, 100, 16, 16) end
    world:add({ name = 'cloud', kind = 'cloud' }, 40, 60, 32, 4)
    local player = { name = 'player', kind = 'player' }
    world:add(player, 0, 40, 10, 13.7)
    world:addResponse('stick', function(_, col) return col.touch.x, col.touch.y end)
    world:add(7, 200, 0, 8, 8)                 -- labelled by tostring
    world:startRecording(path)
    assert.is_true(world:isRecording())
    world:add('coin', 80, 80, 8, 8)            -- added while recording
    local filter = function(_, other)
      if other == 'coin' then return 'cross' end
      if type(other) == 'table' and other.kind == 'cloud' then return 'stick' end
      return 'slide'
    end
    local x, y = 0, 40
    for _ = 1, 120 do
      x, y = world:move(player, x + 2, y + 3, filter)
      world:queryRect(x - 8, y - 8, 26, 30)
      world:frame()
    end
    local frames, calls, bytes = world:stopRecording()
    assert.is_false(world:isRecording())
    assert.is_true(frames >= 120)
    assert.is_true(calls >= 240)
    assert.is_true(bytes > 0)
    local ok, report = tv.validateRecording(path)
    assert.is_true(ok, report)
    os.remove(path)
  end)

  it('a body that lands, walks and crosses a coin added while recording replays', function()
    local path = tmpfile()
    local world = tv.newWorld(16)
    for i = 0, 20 do world:add('tile' .. i, i * 16, 100, 16, 16) end
    world:add('player', 0, 40, 10, 13.7)
    world:startRecording(path)
    world:add('coin', 80, 80, 8, 8)
    local x, y = 0, 40
    for _ = 1, 40 do
      x, y = world:move('player', x + 2, y + 3, function(_, o) return o == 'coin' and 'cross' or 'slide' end)
      world:frame()
    end
    world:stopRecording()
    local ok, report = tv.validateRecording(path)
    os.remove(path)
    assert.is_true(ok, report)
  end)

  it('refuses a path it cannot write, naming it, and records nothing', function()
    local world = tv.newWorld()
    local ok, err = pcall(world.startRecording, world, '/nonexistent-dir/x.tvrec')
    assert.is_false(ok)
    assert.matches('nonexistent%-dir', err)
    assert.is_false(world:isRecording())
    assert.has_error(function() world:stopRecording() end, 'world:stopRecording: this world is not recording')
  end)

  it('validateRecording refuses a file that is not a recording, with a clear error', function()
    local path = tmpfile()
    local f = assert(io.open(path, 'wb'))
    f:write('definitely not a recording')
    f:close()
    local ok, err = pcall(tv.validateRecording, path)
    assert.is_false(ok)
    assert.matches('byte %d+', err)
    os.remove(path)
  end)

  --          +------------------------------+
  --          |  ceiling {16, 0, 32, 8}         |
  --       +--+-----------------------------+
  --       |b |   jumper {10, 40, 8, 12}: jumps straight up, 2 px under the ceiling's left end;
  --       +--+   world:moveCornered nudges it -2 round the corner. The recording says so.
  it('records a corner nudge as one, and the replay finds it: which body, which ceiling, dx', function()
    for _, make in ipairs({ tv.newWorld, tv.bump.newWorld }) do
      local path = tmpfile()
      local world = make(16)
      local ceiling, jumper = { name = 'ceiling' }, { name = 'jumper' }
      world:add(ceiling, 16, 0, 32, 8)
      world:add(jumper, 10, 40, 8, 12)
      world:startRecording(path)
      world:frame()
      local x, y, _, _, dx = world:moveCornered(jumper, 10, 0)
      assert.same({ 8, 0, -2 }, { x, y, dx })
      world:frame()
      world:stopRecording()
      local ok, report = tv.validateRecording(path)
      assert.is_true(ok, report)
      local nudges = tv.recordingNudges(path)
      assert.equal(1, #nudges)
      assert.same({ item = 'jumper', ceiling = 'ceiling', x = 10, y = 8, dx = -2 },
                  { item = nudges[1].item, ceiling = nudges[1].ceiling, x = nudges[1].x,
                    y = nudges[1].y, dx = nudges[1].dx })
      for _, item in ipairs(tv.recordingItems(path)) do
        assert.equal(item.label == 'jumper' and 1 or 0, item.nudges)
      end
      os.remove(path)
      -- Negative control: the same jump by world:move is recorded with no nudge (it stops dead).
      path = tmpfile()
      world = make(16)
      world:add(ceiling, 16, 0, 32, 8)
      world:add(jumper, 10, 40, 8, 12)
      world:startRecording(path)
      world:frame()
      local mx, my = world:move(jumper, 10, 0)
      assert.same({ 10, 8 }, { mx, my })
      world:stopRecording()
      assert.same({}, tv.recordingNudges(path))
      os.remove(path)
    end
  end)

  it('validateRecording and recordingItems refuse a folder, naming it (not "std::bad_alloc")', function()
    local dir = os.tmpname()
    os.remove(dir)
    assert(os.execute('mkdir "' .. dir .. '"'))
    for _, f in ipairs({ tv.validateRecording, tv.recordingItems }) do
      local ok, err = pcall(f, dir)
      assert.is_false(ok)
      assert.is_truthy(err:find("cannot open '" .. dir .. "': is a directory, not a recording", 1, true), err)
    end
    os.remove(dir)
  end)
end)
