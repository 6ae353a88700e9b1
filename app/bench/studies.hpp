#pragma once
// The studies tv-bench runs, one per subcommand. Each prints markdown on stdout, writes CSV
// (and plots) into `Options::out`, and returns the process exit code.

#include <span>
#include <string_view>
#include <vector>

#include "cli.hpp"

namespace tv::bench {

struct Study {
  std::string_view name;
  std::string_view summary;
  std::vector<FlagSpec> flags;  ///< beyond --quick, --full, --out, --seed
  int (*run)(const Options&);
};

[[nodiscard]] std::span<const Study> studies();

int runTunnel(const Options& o);
/// tunnel with --map or --scene-file: the same table on a level from a file.
int runLevelTunnel(const Options& o);
int runPareto(const Options& o);
int runJitter(const Options& o);
int runStress(const Options& o);
int runScale(const Options& o);
int runRecord(const Options& o);

}  // namespace tv::bench
