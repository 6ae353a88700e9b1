#pragma once
// The stress study's cases: each states what the documented model expects and reports what the
// library did. A case passes when the two agree; timings are printed, never part of a verdict.

#include <functional>
#include <string>
#include <vector>

#include "cli.hpp"

namespace tv::bench {

struct CaseResult {
  std::string got;
  bool pass = false;
};

struct StressCase {
  std::string name;
  std::string expected;
  std::function<CaseResult()> run;
};

/// Every case; `mode` scales the long ones (add/remove cycles).
[[nodiscard]] std::vector<StressCase> stressCases(Mode mode);

}  // namespace tv::bench
