// tv-bench: the evidence behind Tunnelvision's claims, one study per subcommand.
//
//   tv-bench tunnel|pareto|jitter|stress|scale [--quick|--full] [--out DIR] [--seed N] [...]
//   tv-bench --help | --list
//
// Bad flags and unknown subcommands print a message naming the flag and the value on stderr
// and exit with code 2; `stress` exits with 1 when a case fails.
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>


#include "cli.hpp"
#include "studies.hpp"
#include "tv/app/vocabulary.hpp"
#include "tv/error.hpp"

namespace {

using tv::bench::Options;
using tv::bench::UsageError;

constexpr int kUsageError = 2;

std::string usage() {
  std::string u =
      "usage: tv-bench STUDY [--quick | --full] [--out DIR] [--seed N] [study flags]\n"
      "  --quick     seconds (the CI smoke test)   --full   the published numbers\n"
      "              (default: under a minute)\n"
      "  --out DIR   where CSV and plots go (default: bench-results/ beside tv-bench)\n"
      "  --seed N    the fixed seed (default " +
      std::to_string(tv::bench::kDefaultSeed) + ")\nstudies:\n";
  for (const tv::bench::Study& s : tv::bench::studies()) {
    u += "  " + std::string(s.name) + std::string(8 - s.name.size(), ' ') + std::string(s.summary) +
         "\n";
    for (const tv::bench::FlagSpec& f : s.flags) {
      u += "      --" + f.name + (f.takesValue ? " V" : "") + "  " + f.help + "\n";
    }
  }
  return u;
}

const tv::bench::Study& findStudy(std::string_view name) {
  std::string valid;
  for (const tv::bench::Study& s : tv::bench::studies()) {
    if (s.name == name) return s;
    valid += (valid.empty() ? "" : ", ") + std::string(s.name);
  }
  throw UsageError{"unknown study '" + std::string(name) + "' (valid: " + valid + ")"};
}

std::filesystem::path defaultOut(const char* argv0, std::string_view study) {
  std::error_code ec;
  std::filesystem::path exe = std::filesystem::canonical("/proc/self/exe", ec);
  if (ec) exe = std::filesystem::absolute(argv0, ec);
  return exe.parent_path() / "bench-results" / study;
}

Options parseArgs(int argc, char** argv, const tv::bench::Study*& study) {
  Options o;
  if (argc < 2) throw UsageError{"missing the study to run"};
  study = &findStudy(argv[1]);
  o.study = std::string(study->name);
  bool quick = false, full = false, outGiven = false;
  for (int i = 2; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (arg.size() < 3 || arg.substr(0, 2) != "--") {
      throw UsageError{"unexpected argument '" + std::string(arg) + "' (flags start with --)"};
    }
    std::string name(arg.substr(2));
    std::optional<std::string> inlineValue;
    if (const auto eq = name.find('='); eq != std::string::npos) {
      inlineValue = name.substr(eq + 1);
      name.resize(eq);
    }
    const auto value = [&]() -> std::string {
      if (inlineValue) return *inlineValue;
      if (i + 1 >= argc) throw UsageError{"--" + name + " needs a value"};
      return argv[++i];
    };
    const auto noValue = [&] {
      if (inlineValue)
        throw UsageError{"--" + name + " takes no value, but got '" + *inlineValue + "'"};
    };
    if (name == "quick") {
      noValue();
      quick = true;
    } else if (name == "full") {
      noValue();
      full = true;
    } else if (name == "out") {
      o.out = value();
      if (o.out.empty()) throw UsageError{"--out: expected a folder, but got ''"};
      outGiven = true;
    } else if (name == "seed") {
      o.seed = tv::bench::parseCount(name, value());
    } else {
      const tv::bench::FlagSpec* spec = nullptr;
      std::string valid = "--quick, --full, --out, --seed";
      for (const tv::bench::FlagSpec& f : study->flags) {
        if (f.name == name) spec = &f;
        valid += ", --" + f.name;
      }
      if (!spec) {
        tv::app::refuseRetiredFlag<UsageError>(name);
        throw UsageError{"--" + name + ": unknown flag for '" + o.study + "' (valid: " + valid +
                         ")"};
      }
      if (spec->takesValue) {
        o.extra[name] = value();
      } else {
        noValue();
        o.extra[name] = "";
      }
    }
  }
  if (quick && full) throw UsageError{"--quick and --full: pick one"};
  o.mode =
      quick ? tv::bench::Mode::quick : (full ? tv::bench::Mode::full : tv::bench::Mode::normal);
  if (!outGiven) o.out = defaultOut(argv[0], o.study);
  std::error_code ec;
  std::filesystem::create_directories(o.out, ec);
  if (ec) throw UsageError{"--out " + o.out.string() + ": cannot create it (" + ec.message() + ")"};
  return o;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    if (argc >= 2 && (std::string_view(argv[1]) == "--help" || std::string_view(argv[1]) == "-h")) {
      std::cout << usage();
      return 0;
    }
    if (argc >= 2 && std::string_view(argv[1]) == "--list") {
      for (const tv::bench::Study& s : tv::bench::studies()) std::cout << s.name << "\n";
      return 0;
    }
    const tv::bench::Study* study = nullptr;
    const Options o = parseArgs(argc, argv, study);
    return study->run(o);
  } catch (const UsageError& e) {
    std::cerr << "tv-bench: " << e.message << "\n" << usage();
    return kUsageError;
  } catch (const std::exception& e) {
    std::cerr << "tv-bench: " << e.what() << "\n";
    return 1;
  }
}
