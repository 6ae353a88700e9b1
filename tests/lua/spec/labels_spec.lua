-- What a recording calls a game's items: the debugger's list must read like the game, never
-- like memory addresses.
local tv = require 'tunnelvision'
local bump = tv.bump

local function tmp(name) return os.tmpname() .. '-' .. name .. '.tvrec' end

-- A middleclass-like class: instances find `class` (with its `name`) through their metatable.
local function class(name)
  local c = { name = name, static = {} }
  c.__instanceDict = { class = c }
  c.__instanceDict.__index = c.__instanceDict
  c.new = function() return setmetatable({}, c.__instanceDict) end
  return c
end

local function labels(path)
  local out = {}
  for _, i in ipairs(tv.recordingItems(path)) do out[#out + 1] = i.label .. ' [' .. i.category .. ']' end
  return out
end

describe('an item\'s label', function()
  it('is its name, its class and a serial, a type/kind/class field and a serial, or its type', function()
    local path = tmp('labels')
    local world = bump.newWorld()
    world:startRecording(path)
    local Guardian, Block = class('Guardian'), class('Block')
    world:add({ name = 'player' }, 0, 0, 1, 1)
    world:add(Guardian.new(), 2, 0, 1, 1)
    world:add(Guardian.new(), 4, 0, 1, 1)
    world:add(Block.new(), 6, 0, 1, 1)
    world:add(setmetatable({ name = 'boss' }, Guardian.__instanceDict), 8, 0, 1, 1)
    world:add({ kind = 'coin' }, 10, 0, 1, 1)
    world:add({ type = 'spike' }, 12, 0, 1, 1)
    world:add({ class = 'door' }, 14, 0, 1, 1)
    world:add({}, 16, 0, 1, 1)
    world:add({}, 18, 0, 1, 1)
    world:add('a string', 20, 0, 1, 1)
    world:add(7, 22, 0, 1, 1)
    world:add(print, 24, 0, 1, 1)
    world:add({ name = 'Stone' }, 26, 0, 1, 1)
    world:add({ name = 'Stone' }, 28, 0, 1, 1)
    world:stopRecording()
    assert.same({
      'player [player]', 'Guardian 1 [Guardian]', 'Guardian 2 [Guardian]', 'Block 1 [Block]',
      'boss [Guardian]', 'coin 1 [coin]', 'spike 1 [spike]', 'door 1 [door]', 'table 1 []',
      'table 2 []', 'a string []', '7 []', 'function 1 []', 'Stone [Stone]', 'Stone 2 [Stone]',
    }, labels(path))
    for _, l in ipairs(labels(path)) do assert.is_nil(l:find('0x')) end
    os.remove(path)
  end)

  it('is never what a __tostring says (middleclass: "instance of class Debris" for all)', function()
    local path = tmp('tostring')
    local world = bump.newWorld()
    world:startRecording(path)
    local Debris = class('Debris')
    Debris.__instanceDict.__tostring = function() return 'instance of class Debris' end
    world:add(Debris.new(), 0, 0, 1, 1)
    world:add(Debris.new(), 2, 0, 1, 1)
    world:stopRecording()
    assert.same({ 'Debris 1 [Debris]', 'Debris 2 [Debris]' }, labels(path))
    os.remove(path)
  end)

  it('can be given by world:label, which wins', function()
    local path = tmp('label')
    local world = bump.newWorld()
    world:startRecording(path)
    local e = { kind = 'enemy' }
    world:add(e, 0, 0, 1, 1)
    world:label(e, 'the boss', 'boss')
    world:stopRecording()
    assert.same({ 'the boss [boss]' }, labels(path))
    os.remove(path)
  end)

  it('of an item whose fields raise is left out, and the game goes on', function()
    local path = tmp('raise')
    local world = bump.newWorld()
    world:startRecording(path)
    world:add(setmetatable({}, { __index = function() error('no fields here') end }), 0, 0, 1, 1)
    world:add({ name = 'next' }, 2, 0, 1, 1)
    world:stopRecording()
    local all = labels(path)
    assert.equal('next [next]', all[#all])
    os.remove(path)
  end)
end)
