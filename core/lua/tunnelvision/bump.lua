-- `require 'tunnelvision.bump'`: bump.lua 3.1.7's API. The code is tunnelvision.so, beside
-- this folder; this file lets every loader that looks for Lua files find it by this name —
-- LÖVE's (in the game or save directory, whatever the working directory), and package.path's —
-- where a C loader would look for a tunnelvision/bump.so that does not exist.
return require('tunnelvision').bump
