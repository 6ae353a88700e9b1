#include "studies.hpp"

namespace tv::bench {

std::span<const Study> studies() {
  static const std::vector<Study> all = {
      {"tunnel",
       "tunnelling rates: every mover, 240 px/s to 1e5 px/s, six shot layouts",
       {{"speeds", "comma-separated px/s (default 240,480,720,960,1920,3840,7680,1e5)"},
        {"count", "projectiles per cell (default 1000; --quick 100)"},
        {"map", "a Tiled map: shots at its solids at the same speeds, every mover"},
        {"solid-layer", "with --map: a layer all of whose tiles and objects are solid"},
        {"scene-file", "a scene file: shots at its solids"}},
       runTunnel},
      {"pareto",
       "run time against position error against an exact rational reference",
       {{"moves", "moves in the workload (default 20000)"}},
       runPareto},
      {"jitter",
       "rendered-pixel changes at rest, double updates and skipped renders",
       {{"frames", "rendered frames per configuration (default 3000)"}},
       runJitter},
      {"stress", "numerical stability: a table of cases; exits 1 if any fails", {}, runStress},
      {"scale",
       "crowd ms per tick against N, move cost against length, adaptive vs discrete",
       {{"counts", "comma-separated crowd sizes (default 100,1000,10000,100000)"},
        {"movers", "comma-separated movers for the crowd (default sweep,continuous,adaptive)"},
        {"ticks", "ticks timed per crowd run (default by size)"},
        {"crowd-only", "only the crowd table (used to compare tracing builds)", false}},
       runScale},
      {"record",
       "recording on vs detached on the crowd, bytes per move, replay and seek times",
       {{"count", "crowd size (default 10000)"},
        {"ticks", "crowd ticks per timed run"},
        {"variant", "only the crowd, detached, memory or validate (for callgrind)"}},
       runRecord},
  };
  return all;
}

}  // namespace tv::bench
