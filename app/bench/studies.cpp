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
       {{"moves", "moves in the workload (default 20000)"},
        {"from-csv", "re-draw the table and plot from a pareto.csv written before (its numbers, "
                     "not measured again; --moves as when it was measured)"}},
       runPareto},
      {"jitter",
       "rendered-pixel changes at rest, double updates and skipped renders",
       {{"frames", "rendered frames per configuration (default 3000)"}},
       runJitter},
      {"stress", "numerical stability: a table of cases; exits 1 if any fails", {}, runStress},
      {"scale",
       "bump-crowd and crowd ms per tick against N, tv::Batch, move cost against length, adaptive "
       "vs discrete",
       {{"counts", "comma-separated crowd sizes (default 100,1000,10000,100000)"},
        {"movers", "comma-separated movers for the crowd (default sweep,continuous,adaptive)"},
        {"ticks", "ticks timed per crowd run and per slow scene (default by size, by mode)"},
        {"crowd-only", "only the crowd table (used to compare tracing builds)", false},
        {"bump-counts", "comma-separated bump-crowd sizes (default 1000,10000,100000)"},
        {"cells", "comma-separated bump-crowd cell sizes (default 16,32,64)"},
        {"filters", "bump-crowd filters: tiles, all (default both)"},
        {"batch-counts", "comma-separated sizes of the bump-crowd through tv::Batch"},
        {"bump-only", "only the bump-crowd tables", false},
        {"slow-only", "only adaptive against discrete (the slow scenes)", false},
        {"slow-scenes", "slow scenes: crowd-1px, crowd-2px, rest-floor, seam-walk (default all)"},
        {"slow-movers", "slow-scene movers: discrete, adaptive, continuous (default all)"},
        {"slow-count", "bodies in each slow scene (default 500, 5000, 10000 by mode)"}},
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
