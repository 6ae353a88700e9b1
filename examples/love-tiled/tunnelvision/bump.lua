-- LÖVE's C loader finds tunnelvision.so in the game (or save) directory by its own name only:
-- this makes `require 'tunnelvision.bump'` load it there too.
return require('tunnelvision').bump
