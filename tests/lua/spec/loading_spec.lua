-- What a game ships: tunnelvision.so and tunnelvision/bump.lua, side by side. With both on the
-- loaders' paths, `require 'tunnelvision.bump'` works first or after `require 'tunnelvision'`,
-- from any working directory, and both give one module. (LÖVE: tests/lua/love/require_anywhere.)
local dir = assert(os.getenv('TV_LUA_MODULE_DIR'))
local vm = jit and 'luajit' or 'lua5.1'

local function run(code)
  local script = os.tmpname()
  local f = assert(io.open(script, 'w'))
  f:write(code)
  f:close()
  local p = io.popen(('cd / && %s %q 2>&1'):format(vm, script))
  local out = p:read('*a')
  p:close()
  os.remove(script)
  return out
end

describe('require', function()
  it('finds tunnelvision.bump through the file beside the module, first or second', function()
    local paths = ('package.cpath = %q .. "/?.so"; package.path = %q .. "/?.lua"\n'):format(dir, dir)
    assert.equal('bump v3.1.7 (tunnelvision)\ttrue\n', run(paths .. [[
      local bump = require 'tunnelvision.bump'
      print(bump._VERSION, require('tunnelvision').bump == bump)
    ]]))
    assert.equal('true\n', run(paths .. [[
      local tv = require 'tunnelvision'
      print(require('tunnelvision.bump') == tv.bump)
    ]]))
  end)

  it('finds it by the module alone where package.cpath is all there is (Lua\'s all-in-one loader)', function()
    assert.equal('bump v3.1.7 (tunnelvision)\n', run(('package.cpath = %q .. "/?.so"; package.path = ""\n'):format(dir) .. [[
      print(require('tunnelvision.bump')._VERSION)
    ]]))
  end)

  it('says where it looked when neither is there', function()
    local out = run('package.cpath = ""; package.path = ""; require "tunnelvision.bump"')
    assert.truthy(out:find("module 'tunnelvision.bump' not found", 1, true))
  end)
end)
