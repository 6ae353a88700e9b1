// tv-replay: what is in a recording (.tvrec), whether it replays bit for bit, per-item stats, and
// what another mover would have done with the same calls.
//
//   tv-replay FILE                      summary, with a full replay and its rate
//   tv-replay FILE --validate           exit 1 with the divergence report if it does not replay
//   tv-replay FILE --stats              per item: moves, hits, max speed, moves ending in a solid
//   tv-replay FILE --mover NAME [--substep L] [--updates-as-moves] [--far D]
//                                       re-run the moves with another mover and compare
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

struct Options {
  std::string file;
  bool validate = false, stats = false, updatesAsMoves = false, tolerant = false;
  std::optional<std::string> mover;
  std::optional<double> substep;
  double far = 64.0;
  std::optional<tv::replay::ListenOptions> listen;
};

constexpr const char* kUsage =
    "usage: tv-replay FILE [--validate | --stats | --mover NAME [--substep L] [--updates-as-moves] "
    "[--far D]] [--tolerant]\n"
    "       tv-replay --listen [HOST:]PORT --out FILE [--frames N] [--wait S]\n"
    "  (no flag)           summary: frames, calls, moves, collisions, items, size, bytes per move, "
    "replay rate\n"
    "  --validate          replay every call and compare it with the recording; exit 1 on a "
    "divergence\n"
    "  --stats             per moving item: moves, hits, longest move, moves that ended inside a "
    "solid\n"
    "  --mover NAME        what-if: make every recorded move with this mover instead\n"
    "                      (discrete, sweep, substep-discrete, substep-sweep, continuous, pixel, "
    "adaptive)\n"
    "  --substep L         what-if: substep piece length in world units (substep-* movers)\n"
    "  --updates-as-moves  what-if: also make each position-only update a move (games that move "
    "bodies themselves)\n"
    "  --far D             what-if: distance from the recording beyond which its goals stop making "
    "sense (default 64)\n"
    "  --tolerant          open what can be opened of a damaged file (a bad chunk ends it)\n"
    "  --listen [HOST:]PORT  receive one game's live stream (a game run with --live, or TV_LIVE)\n"
    "                      on 127.0.0.1 unless HOST is given; port 0 takes a free one\n"
    "  --out FILE          with --listen: where the stream is saved, whole frames as they come\n"
    "  --frames N          with --listen: stop after N frames (default: when the game leaves)\n"
    "  --wait S            with --listen: give up if no game connects within S seconds\n";

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
    } else if (a == "--stats") {
      o.stats = true;
    } else if (a == "--tolerant") {
      o.tolerant = true;
    } else if (a == "--updates-as-moves") {
      o.updatesAsMoves = true;
    } else if (a == "--mover") {
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
    if (!o.file.empty() || o.validate || o.stats || o.mover || o.tolerant) {
      throw UsageError{"--listen receives a recording: validate it afterwards with tv-replay FILE"};
    }
    return o;
  }
  if (o.file.empty()) throw UsageError{"no recording given"};
  if ((o.validate + o.stats + o.mover.has_value()) > 1) {
    throw UsageError{"--validate, --stats and --mover are separate reports: pick one"};
  }
  if ((o.substep || o.updatesAsMoves) && !o.mover) {
    throw UsageError{"--substep and --updates-as-moves go with --mover"};
  }
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

int validate(tv::Replay& r) {
  const std::optional<tv::Divergence> d = r.validate();
  if (d) {
    std::cout << d->report();
    return 1;
  }
  std::printf("ok: %llu frames, %llu calls replayed bit for bit%s\n",
              static_cast<unsigned long long>(r.summary().frames),
              static_cast<unsigned long long>(r.summary().calls), damage(r.summary()).c_str());
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
  std::printf("\nmoves re-run: %llu; ended elsewhere: %zu",
              static_cast<unsigned long long>(w.moves),
              static_cast<std::size_t>(
                  std::count_if(w.differences.begin(), w.differences.end(),
                                [](const tv::MoveDifference& m) { return m.distance > 0; })));
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
    if (o.validate) return validate(r);
    if (o.stats) return stats(r);
    if (o.mover) return whatIf(r, o);
    return summary(r);
  } catch (const tv::Error& e) {
    std::cerr << "tv-replay: " << tv::app::userMessage(e) << "\n";
    return 2;
  }
}
