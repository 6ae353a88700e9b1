// stress: numerical stability, as a table `case | expected | got | pass`; exits 1 if any fails.
#include <exception>
#include <iostream>

#include "report.hpp"
#include "stress_cases.hpp"
#include "studies.hpp"

namespace tv::bench {

int runStress(const Options& o) {
  std::ostream& os = std::cout;
  printHeading(os, "stress: numerical stability", modeName(o.mode), o.seed, o.out);
  os << "Each case states what the documented model (tv/geometry.hpp, tv/world.hpp) expects and "
        "what the library did. The seed is unused: every case is a fixed input.\n\n";
  const std::vector<StressCase> cases = stressCases(o.mode);
  Table table({"case", "expected", "got", "pass"});
  Progress progress("stress", cases.size());
  int failed = 0;
  for (const StressCase& c : cases) {
    CaseResult r;
    try {
      r = c.run();
    } catch (const std::exception& e) {
      r = {std::string("unexpected exception: ") + e.what(), false};
    }
    if (!r.pass) ++failed;
    table.add({c.name, c.expected, r.got, r.pass ? "pass" : "FAIL"});
    progress.step(c.name);
  }
  table.printMarkdown(os);
  table.writeCsv(o.out, "stress.csv");
  os << cases.size() - static_cast<std::size_t>(failed) << " of " << cases.size()
     << " cases pass.\n";
  return failed == 0 ? 0 : 1;
}

}  // namespace tv::bench
