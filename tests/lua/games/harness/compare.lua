-- Compares two harness logs (main.lua writes one line per frame: every world's item count and
-- state hash).
--   compare.lua A B            frames compared, identical, first difference; exit 0 iff equal
--   compare.lua --items A B F  the items whose rects differ at frame F (logs with dumps)

local function frames(path)
  local out = {}
  for line in io.lines(path) do
    local f = line:match('^frame (%d+) ')
    if f then out[tonumber(f)] = line end
  end
  return out
end

if arg[1] == '--items' then
  local function items(path, frame)
    local out = {}
    for line in io.lines(path) do
      local f, w, serial, rest = line:match('^dump (%d+) world (%d+) item (%d+) (.*)$')
      if f and tonumber(f) == frame then out[w .. ':' .. serial] = rest end
    end
    return out
  end
  local frame = tonumber(arg[4])
  local a, b = items(arg[2], frame), items(arg[3], frame)
  local keys, n = {}, 0
  for k in pairs(a) do keys[#keys + 1] = k end
  for k in pairs(b) do if a[k] == nil then keys[#keys + 1] = k end end
  table.sort(keys)
  print(('items that differ at frame %d (world:item  kind x y w h):'):format(frame))
  for _, k in ipairs(keys) do
    if a[k] ~= b[k] then
      n = n + 1
      if n <= 20 then
        print(('  %s\n    bump.lua          %s\n    tunnelvision.bump %s'):format(k, a[k] or '(none)', b[k] or '(none)'))
      end
    end
  end
  print(('%d items differ'):format(n))
  os.exit(0)
end

local a, b = frames(arg[1]), frames(arg[2])
-- A line without its exact hashes: what is left must match when the runs differ by rounding.
local function rounded(line) return line and (line:gsub(' %x+ ~', ' ~')) end
local n, same, close, first, firstFar = 0, 0, 0, nil, nil
for f = 1, math.huge do
  if a[f] == nil and b[f] == nil then break end
  n = n + 1
  if a[f] == b[f] then
    same = same + 1
  else
    first = first or f
    if rounded(a[f]) == rounded(b[f]) then
      close = close + 1
    else
      firstFar = firstFar or f
    end
  end
end
print(('frames compared %d: identical bit for bit %d, within 1e-6 (rounding) %d, different %d'):format(
  n, same, close, n - same - close))
if first then
  print(('first difference at frame %d'):format(first))
  print('  ' .. tostring(a[first]))
  print('  ' .. tostring(b[first]))
end
if firstFar then
  print(('first difference beyond rounding at frame %d'):format(firstFar))
  print('  ' .. tostring(a[firstFar]))
  print('  ' .. tostring(b[firstFar]))
  os.exit(1)
end
if first then os.exit(2) end
print('every frame identical')
os.exit(0)
