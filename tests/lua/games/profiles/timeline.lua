-- Scripted input from a timeline of held keys: { key, from, to } holds `key` from frame `from`
-- up to frame `to` (exclusive). Returns input(frame) -> { {'press'|'release', key}, ... }.
return function(timeline)
  local events = {}
  local function at(f, e)
    events[f] = events[f] or {}
    table.insert(events[f], e)
  end
  for _, h in ipairs(timeline) do
    at(h[2], { 'press', h[1] })
    at(h[3], { 'release', h[1] })
  end
  return function(frame) return events[frame] end
end
