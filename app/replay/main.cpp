// tv-replay: what is in a recording (.tvrec), whether it replays bit for bit, per-item stats, and
// what another mover would have done with the same calls.
//
//   tv-replay FILE                      summary, with a full replay and its rate
//   tv-replay FILE --validate [--traced] [--allow-truncated]
//                                       exit 1 with the divergence report if it does not replay,
//                                       or if the file was cut short (a game that crashed);
//                                       --traced: every call traced and from every keyframe, as
//                                       the debugger re-runs them
//   tv-replay FILE --stats              per item: moves, hits, max speed, moves ending in a solid
//   tv-replay FILE --what-if NAME [--substep L] [--updates-as-moves] [--far D]
//                 [--fail-on tunnel,overlap,differ]
//                                       re-run the moves with another mover and compare; exit 1
//                                       when the re-run does what --fail-on names (a game's CI)
//   tv-replay --listen [HOST:]PORT --out FILE [--frames N] [--wait S]
//                                       receive a game's live stream into FILE (listen.cpp)

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <optional>
#include <string>
#include <string_view>

#include "listen.hpp"
#include "tv/app/flags.hpp"
#include "tv/app/user_message.hpp"
#include "tv/error.hpp"
#include "tv/record/replay.hpp"

namespace {

struct UsageError {
  std::string message;
};

// What a what-if run may not do, for --fail-on.
struct FailOn {
  bool tunnel = false, overlap = false, differ = false;
  [[nodiscard]] bool any() const { return tunnel || overlap || differ; }
};

struct Options {
  std::string file;
  bool validate = false, traced = false, stats = false, updatesAsMoves = false, tolerant = false;
  bool allowTruncated = false;
  std::optional<std::string> mover;
  std::optional<double> substep;
  double far = 64.0;
  FailOn failOn;
  std::optional<tv::replay::ListenOptions> listen;
};

FailOn parseFailOn(std::string_view list) {
  FailOn f;
  while (true) {
    const std::size_t comma = list.find(',');
    const std::string_view word = list.substr(0, comma);
    if (word == "tunnel") {
      f.tunnel = true;
    } else if (word == "overlap") {
      f.overlap = true;
    } else if (word == "differ") {
      f.differ = true;
    } else {
      throw UsageError{"--fail-on: expected tunnel, overlap or differ (comma-separated), but "
                       "got '" + std::string(word) + "'"};
    }
    if (comma == std::string_view::npos) break;
    list.remove_prefix(comma + 1);
  }
  return f;
}

constexpr const char* kUsage =
    "usage: tv-replay FILE [--validate [--traced] [--allow-truncated] | --stats |\n"
    "                       --what-if NAME [--substep L] [--updates-as-moves] [--far D]\n"
    "                                      [--fail-on tunnel,overlap,differ]] [--tolerant]\n"
    "       tv-replay --listen [HOST:]PORT --out FILE [--frames N] [--wait S]\n"
    "  (no flag)           summary: frames, calls, moves, collisions, items, size, bytes per move, "
    "replay rate\n"
    "  --validate          replay every call and compare it with the recording; exit 1 on a "
    "divergence,\n"
    "                      and on a recording cut short (no end mark, or a frame cut: a game that "
    "crashed)\n"
    "  --traced            with --validate: every call traced, and from each keyframe on a world "
    "rebuilt from it,\n"
    "                      as the debugger re-runs them: what it shows is what the game got\n"
    "  --allow-truncated   with --validate: a recording cut short passes if its whole frames "
    "replay\n"
    "  --stats             per moving item: moves, hits, longest move, moves that ended inside a "
    "solid\n"
    "  --what-if NAME      make every recorded move with this mover instead, and compare (also "
    "--mover)\n"
    "                      (discrete, sweep, substep-discrete, substep-sweep, continuous, pixel, "
    "adaptive)\n"
    "  --substep L         what-if: substep piece length in world units (substep-* movers)\n"
    "  --updates-as-moves  what-if: also make each position-only update a move (games that move "
    "bodies themselves)\n"
    "  --far D             what-if: distance from the recording beyond which its goals stop making "
    "sense (default 64)\n"
    "  --fail-on LIST      what-if: exit 1 if the re-run has a move that tunnelled (tunnel), ended "
    "inside\n"
    "                      a solid (overlap) or ended elsewhere than recorded (differ)\n"
    "  --tolerant          open what can be opened of a damaged file (a bad chunk ends it)\n"
    "  --listen [HOST:]PORT  receive one game's live stream (a game run with --live, or TV_LIVE)\n"
    "                      on 127.0.0.1 unless HOST is given; port 0 takes a free one\n"
    "  --out FILE          with --listen: where the stream is saved, whole frames as they come\n"
    "  --frames N          with --listen: stop after N frames (default: when the game leaves)\n"
    "  --wait S            with --listen: give up if no game connects within S seconds\n"
    "Exit status: 0 ok, 1 a divergence, a recording cut short or a --fail-on condition, 2 bad "
    "command line or a file that cannot be read or is not a recording.\n";

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string_view a = argv[i];
    const auto value = [&]() -> std::string_view {
      if (i + 1 >= argc) throw UsageError{std::string(a) + " needs a value"};
      return argv[++i];
    };
    if (a == "--help" || a == "-h") {
      std::cout << kUsage;
      std::exit(0);
    } else if (a == "--validate") {
      o.validate = true;
    } else if (a == "--traced") {
      o.traced = true;
    } else if (a == "--stats") {
      o.stats = true;
    } else if (a == "--tolerant") {
      o.tolerant = true;
    } else if (a == "--allow-truncated") {
      o.allowTruncated = true;
    } else if (a == "--fail-on") {
      o.failOn = parseFailOn(value());
    } else if (a == "--updates-as-moves") {
      o.updatesAsMoves = true;
    } else if (a == "--what-if" || a == "--mover") {
      o.mover = std::string(value());
    } else if (a == "--substep") {
      o.substep = tv::app::parseFinite<UsageError>("substep", value());
      if (*o.substep <= 0) throw UsageError{"--substep: expected a length > 0"};
    } else if (a == "--listen") {
      if (!o.listen) o.listen.emplace();
      o.listen->address = std::string(value());
    } else if (a == "--out") {
      if (!o.listen) o.listen.emplace();
      o.listen->out = std::string(value());
    } else if (a == "--frames") {
      if (!o.listen) o.listen.emplace();
      o.listen->frames = tv::app::parseWhole<UsageError>("frames", value());
      if (o.listen->frames == 0) throw UsageError{"--frames: expected at least 1"};
    } else if (a == "--wait") {
      if (!o.listen) o.listen.emplace();
      o.listen->waitSeconds = tv::app::parseFinite<UsageError>("wait", value());
      if (o.listen->waitSeconds <= 0) throw UsageError{"--wait: expected seconds > 0"};
    } else if (a == "--far") {
      o.far = tv::app::parseFinite<UsageError>("far", value());
      if (o.far < 0) throw UsageError{"--far: expected a distance >= 0"};
    } else if (!a.empty() && a[0] == '-') {
      throw UsageError{"unknown flag '" + std::string(a) + "'"};
    } else if (o.file.empty()) {
      o.file = a;
    } else {
      throw UsageError{"one recording at a time (got '" + o.file + "' and '" + std::string(a) +
                       "')"};
    }
  }
  if (o.listen) {
    if (o.listen->address.empty()) throw UsageError{"--out, --frames and --wait go with --listen"};
    if (o.listen->out.empty()) throw UsageError{"--listen needs --out FILE (where to save it)"};
    if (!o.file.empty() || o.validate || o.traced || o.stats || o.mover || o.tolerant ||
        o.allowTruncated || o.failOn.any()) {
      throw UsageError{"--listen receives a recording: validate it afterwards with tv-replay FILE"};
    }
    return o;
  }
  if (o.file.empty()) throw UsageError{"no recording given"};
  if ((o.validate + o.stats + o.mover.has_value()) > 1) {
    throw UsageError{"--validate, --stats and --what-if are separate reports: pick one"};
  }
  if (o.traced && !o.validate) throw UsageError{"--traced goes with --validate"};
  if ((o.substep || o.updatesAsMoves) && !o.mover) {
    throw UsageError{"--substep and --updates-as-moves go with --what-if"};
  }
  if (o.failOn.any() && !o.mover) throw UsageError{"--fail-on goes with --what-if MOVER"};
  if (o.allowTruncated && !o.validate) throw UsageError{"--allow-truncated goes with --validate"};
  return o;
}

double seconds(std::chrono::steady_clock::duration d) {
  return std::chrono::duration<double>(d).count();
}

void printWarnings(const tv::Replay& r) {
  for (const std::string& w : r.warnings()) std::cerr << "warning: " << w << "\n";
}

// What a check of a damaged file did not cover: "" for a whole file.
std::string damage(const tv::ReplaySummary& s) {
  if (!s.damagedAt) return "";
  return "; only frames 0.." + std::to_string(s.frames - 1) + " were checked: the file is cut or " +
         "damaged at byte " + std::to_string(*s.damagedAt);
}

int summary(tv::Replay& r) {
  const tv::ReplaySummary& s = r.summary();
  const auto t0 = std::chrono::steady_clock::now();
  const std::optional<tv::Divergence> d = r.validate();
  const double t = seconds(std::chrono::steady_clock::now() - t0);
  std::printf("frames      %llu (%llu keyframes)\n", static_cast<unsigned long long>(s.frames),
              static_cast<unsigned long long>(s.keyframes));
  std::printf("calls       %llu (%llu queries)\n", static_cast<unsigned long long>(s.calls),
              static_cast<unsigned long long>(s.queries));
  std::printf("moves       %llu\n", static_cast<unsigned long long>(s.moves));
  std::printf("collisions  %llu\n", static_cast<unsigned long long>(s.collisions));
  std::printf("items       %zu\n", r.items().size());
  std::printf("file size   %llu bytes\n", static_cast<unsigned long long>(s.bytes));
  // Of a damaged file only the frames read count: their bytes over their moves.
  const std::uint64_t bytes = s.damagedAt ? s.bytesRead : s.bytes;
  if (s.moves)
    std::printf("bytes/move  %.1f%s\n", static_cast<double>(bytes) / static_cast<double>(s.moves),
                s.damagedAt ? " (of the frames read)" : "");
  std::printf("replay      %.3f s: %.0f moves/s, %.0f calls/s, %.0f frames/s\n", t,
              static_cast<double>(s.moves) / t, static_cast<double>(s.calls) / t,
              static_cast<double>(s.frames) / t);
  std::printf("validation  %s%s\n",
              d ? "DIVERGED (tv-replay --validate for the report)" : "ok, bit for bit",
              damage(s).c_str());
  return 0;
}

// How a recording was cut short, or "" when the game closed it: a file cut inside a frame, or
// whole frames with no end mark (the game crashed or was killed between two frames).
std::string cutShort(const tv::ReplaySummary& s) {
  if (s.damagedAt)
    return "the file is cut or damaged at byte " + std::to_string(*s.damagedAt) +
           ", so the frames after " + std::to_string(s.frames - 1) + " are lost";
  if (!s.closed) return "the file has no end mark: the game stopped without closing the recording";
  return "";
}

int validate(tv::Replay& r, const Options& o) {
  const bool traced = o.traced;
  const std::optional<tv::Divergence> d =
      r.validate({}, traced ? tv::Replay::Tracing::on : tv::Replay::Tracing::off);
  if (d) {
    if (traced) std::cout << "traced (as the debugger re-runs it): ";
    std::cout << d->report();
    return 1;
  }
  const tv::ReplaySummary& s = r.summary();
  const std::string cut = cutShort(s);
  if (!cut.empty() && !o.allowTruncated) {
    // What was read replays, but a recording cut short is what a crash leaves: a CI check that
    // passed it would hide the crash.
    std::printf("CUT SHORT: frames 0..%llu (%llu calls) replay bit for bit, but %s\n",
                static_cast<unsigned long long>(s.frames - 1),
                static_cast<unsigned long long>(s.calls), cut.c_str());
    std::cerr << "tv-replay: " << o.file << " was cut short (a game that crashed?); "
              << "--allow-truncated accepts a recording cut short\n";
    return 1;
  }
  std::printf("ok: %llu frames, %llu calls replayed bit for bit%s%s%s\n",
              static_cast<unsigned long long>(s.frames),
              static_cast<unsigned long long>(s.calls),
              traced ? ", traced and from every keyframe" : "", damage(s).c_str(),
              !s.damagedAt && !s.closed ? "; the file has no end mark (allowed)" : "");
  return 0;
}

int stats(tv::Replay& r) {
  const std::optional<tv::Divergence> d = r.validate();
  if (d) std::cerr << "warning: the recording does not replay exactly; stats after " << d->report();
  std::printf("| item | category | moves | hits | longest move | ended in a solid |\n");
  std::printf("|---|---|---:|---:|---:|---:|\n");
  std::size_t still = 0;
  for (const tv::RecordedItem& it : r.items()) {
    if (it.moves == 0) {
      ++still;
      continue;
    }
    std::printf("| %s | %s | %llu | %llu | %.3f | %llu |\n", it.label.c_str(), it.category.c_str(),
                static_cast<unsigned long long>(it.moves), static_cast<unsigned long long>(it.hits),
                it.maxSpeed, static_cast<unsigned long long>(it.endedOverlapping));
  }
  std::printf("\n%zu items never moved (tiles, walls...).\n", still);
  return 0;
}

// What kind of thing an item is, for the breakdowns: its category ("bullet"), else its label.
std::string kindOf(const tv::Replay& r, tv::ItemId id) {
  if (!id.valid()) return "?";
  const std::string c = r.category(id);
  return c.empty() ? r.label(id) : c;
}

// "43 bullet through wall, 5 bullet through tile": the moves behind a count, by what moved and
// what it passed through (or ended inside), largest first.
std::string breakdown(const tv::Replay& r, const std::vector<tv::MoveDifference>& moves,
                      bool tunnel) {
  std::vector<std::pair<std::string, std::uint64_t>> counts;
  for (const tv::MoveDifference& m : moves) {
    if (tunnel ? !m.tunnelled : !m.overlapping) continue;
    const std::string key =
        kindOf(r, m.item) + (tunnel ? " through " : " inside ") + kindOf(r, m.solid);
    auto it = std::find_if(counts.begin(), counts.end(),
                           [&](const auto& c) { return c.first == key; });
    if (it == counts.end()) {
      counts.emplace_back(key, 1);
    } else {
      ++it->second;
    }
  }
  std::stable_sort(counts.begin(), counts.end(),
                   [](const auto& a, const auto& b) { return a.second > b.second; });
  std::string text;
  for (const auto& [key, n] : counts)
    text += (text.empty() ? "" : ", ") + std::to_string(n) + " " + key;
  return text;
}

int whatIf(tv::Replay& r, const Options& o) {
  const tv::WhatIfReport w = r.whatIf(o.far);
  const std::string name = r.options().mover->name();
  std::printf("What-if: the recorded moves%s made by %s%s.\n",
              o.updatesAsMoves ? " (and position updates)" : "", name.c_str(),
              o.substep ? (" (pieces of " + tv::formatNumber(*o.substep) + ")").c_str() : "");
  std::printf(
      "Open loop: the game's reactions to a different outcome are not in the file; each "
      "recorded goal is replayed as it was.\n\n");
  std::printf("| | recorded run | %s |\n|---|---:|---:|\n", name.c_str());
  std::printf("| moves that tunnelled | %llu | %llu |\n",
              static_cast<unsigned long long>(w.recordedTunnelled),
              static_cast<unsigned long long>(w.tunnelled));
  std::printf("| moves that ended inside a solid | %llu | %llu |\n",
              static_cast<unsigned long long>(w.recordedOverlapping),
              static_cast<unsigned long long>(w.overlapping));
  // The counts are of moves: say which moves, so they can be set against what the game saw.
  const auto explain = [&](const char* run, const std::vector<tv::MoveDifference>& moves,
                           std::uint64_t tunnelled, std::uint64_t overlapping) {
    if (tunnelled) std::printf("%s, tunnelled: %s\n", run, breakdown(r, moves, true).c_str());
    if (overlapping)
      std::printf("%s, ended inside: %s\n", run, breakdown(r, moves, false).c_str());
  };
  std::printf("\n");
  explain("recorded run", w.recordedFailures, w.recordedTunnelled, w.recordedOverlapping);
  explain(name.c_str(), w.differences, w.tunnelled, w.overlapping);
  std::printf(
      "Counted in moves, not bodies: a body that passes two solids in two moves counts twice.\n");
  if (o.updatesAsMoves) {
    std::printf(
        "With --updates-as-moves every position update is a move: a game that pushes its bodies "
        "out itself\nfirst updates them into what they hit (a move that ended inside a solid), "
        "then out of it.\n");
  }
  const auto elsewhere = static_cast<std::size_t>(
      std::count_if(w.differences.begin(), w.differences.end(),
                    [](const tv::MoveDifference& m) { return m.distance > 0; }));
  std::printf("\nmoves re-run: %llu; ended elsewhere: %zu",
              static_cast<unsigned long long>(w.moves), elsewhere);
  if (w.failedCalls)
    std::printf("; refused by the world: %llu", static_cast<unsigned long long>(w.failedCalls));
  std::printf("\n");
  if (w.firstDifferentFrame)
    std::printf("first frame that differs: %llu\n",
                static_cast<unsigned long long>(*w.firstDifferentFrame));
  if (w.firstImplausibleFrame) {
    std::printf(
        "first frame where a body is more than %s away from the recording (its goals stop "
        "making sense from there): %llu\n",
        tv::formatNumber(o.far).c_str(), static_cast<unsigned long long>(*w.firstImplausibleFrame));
  }
  std::size_t shown = 0;
  for (const tv::MoveDifference& m : w.differences) {
    if (shown == 0)
      std::printf(
          "\n| frame | call | item | recorded | %s | distance | "
          "|\n|---:|---:|---|---|---|---:|---|\n",
          name.c_str());
    if (++shown > 12) {
      std::printf("| … %zu more | | | | | | |\n", w.differences.size() - 12);
      break;
    }
    std::printf("| %llu | %u | %s | (%s, %s) | (%s, %s) | %s | %s |\n",
                static_cast<unsigned long long>(m.frame), m.call, r.label(m.item).c_str(),
                tv::formatNumber(m.recorded.x).c_str(), tv::formatNumber(m.recorded.y).c_str(),
                tv::formatNumber(m.got.x).c_str(), tv::formatNumber(m.got.y).c_str(),
                tv::formatNumber(m.distance).c_str(),
                m.tunnelled ? "tunnelled" : (m.overlapping ? "ends inside a solid" : ""));
  }
  if (!o.failOn.any()) return 0;
  // A game's CI: "under discrete this recording tunnels 15 times" is a failure with its report.
  std::string failed;
  const auto add = [&failed](std::uint64_t n, const char* what) {
    failed += (failed.empty() ? "" : ", ") + std::to_string(n) + (n == 1 ? " move " : " moves ") +
              what;
  };
  if (o.failOn.tunnel && w.tunnelled) add(w.tunnelled, "tunnelled");
  if (o.failOn.overlap && w.overlapping) add(w.overlapping, "ended inside a solid");
  if (o.failOn.differ && elsewhere) add(elsewhere, "ended elsewhere");
  if (!failed.empty()) {
    std::printf("\nFAILED under %s: %s (--fail-on)\n", name.c_str(), failed.c_str());
    return 1;
  }
  std::printf("\npassed under %s: nothing --fail-on names happened\n", name.c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  try {
    o = parse(argc, argv);
  } catch (const UsageError& e) {
    std::cerr << "tv-replay: " << e.message << "\n" << kUsage;
    return 2;
  }
  if (o.listen) return tv::replay::listen(*o.listen);
  try {
    tv::ReplayOptions ro;
    ro.tolerant = o.tolerant;
    ro.itemStats = o.stats;
    ro.updatesAsMoves = o.updatesAsMoves;
    if (o.mover) {
      tv::MoverSpec spec = tv::parseMover(*o.mover);
      if (o.substep) {
        if (spec.kind != tv::MoverKind::substep) {
          throw tv::Error("--substep applies to the substep-* movers, not '" + *o.mover + "'");
        }
        spec.maxStep = *o.substep;
      }
      ro.mover = spec;
    }
    tv::Replay r = tv::Replay::open(o.file, ro);
    printWarnings(r);
    if (o.validate) return validate(r, o);
    if (o.stats) return stats(r);
    if (o.mover) return whatIf(r, o);
    return summary(r);
  } catch (const std::exception& e) {
    // tv::Error for a file that cannot be read or is not a recording; anything else (memory)
    // is said in words too, never left to abort the program.
    std::cerr << "tv-replay: " << tv::app::userMessage(e) << "\n";
    return 2;
  }
}
