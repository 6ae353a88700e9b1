// A mutation fuzzer over the reader: valid recordings with bytes flipped, set, inserted, deleted
// or cut — with the chunk checksum fixed up most of the time, so the mutation reaches the decoder
// and the replay instead of stopping at the CRC. Every file must either replay or be refused with
// a tv::Error: no crash, no other exception, no unbounded allocation (the suite runs it under
// ASan + UBSan too). TV_FUZZ_ITERATIONS=N runs N files per shard instead of the default.

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>
#include <vector>

#include "recording_kit.hpp"
#include "tv/corner.hpp"
#include "tv/error.hpp"
#include "tv/record/recorder.hpp"
#include "tv/record/replay.hpp"
#include "tv/sim/rng.hpp"

namespace {

using Bytes = std::vector<std::uint8_t>;

std::uint64_t iterations() {
  if (const char* v = std::getenv("TV_FUZZ_ITERATIONS")) return std::strtoull(v, nullptr, 10);
  return 25000;  // × 4 shards = 10^5 files
}

const std::vector<Bytes>& seeds() {
  static const std::vector<Bytes> s = [] {
    std::vector<Bytes> out;
    tvtest::Script a;
    a.framesToPlay = 3;
    a.keyframeEvery = 2;
    out.push_back(a.record());
    // A tiny one: every byte of it matters.
    tv::World w(8);
    tv::Recorder rec;
    w.add({0, 16, 64, 8});
    w.attach(rec);
    const tv::ItemId p = w.add({0, 0, 4, 4});
    rec.label(p, "p", "c");
    for (int i = 0; i < 4; ++i) {
      rec.frame();
      w.move(p, w.rect(p).position() + tv::Vec2{3.25, 5.5});
      (void)w.queryPoint({1, 17});
    }
    w.detach();
    out.push_back(rec.bytes());
    // A corner nudge: its moves and its cornerNudge call.
    tv::World c(16);
    tv::Recorder nudged;
    (void)c.add({16, 0, 32, 8});
    c.attach(nudged);
    const tv::ItemId jumper = c.add({10, 40, 8, 12});
    nudged.frame();
    (void)tv::moveCornered(c, jumper, {10, 0});
    c.detach();
    out.push_back(nudged.bytes());
    return out;
  }();
  return s;
}

Bytes mutate(const Bytes& seed, tv::sim::Rng& rng) {
  Bytes b = seed;
  const int edits = 1 + static_cast<int>(rng.below(4));
  std::size_t last = 0;
  for (int e = 0; e < edits && !b.empty(); ++e) {
    const std::size_t at = rng.below(b.size());
    last = at;
    switch (rng.below(7)) {
      case 0:
        b[at] ^= static_cast<std::uint8_t>(1u << rng.below(8));
        break;
      case 1:
        b[at] = static_cast<std::uint8_t>(rng.below(256));
        break;
      case 2: {  // an interesting value: 0, 0xFF, 0x7F, 0x80
        const std::uint8_t v[] = {0, 0xFF, 0x7F, 0x80, 1};
        b[at] = v[rng.below(5)];
        break;
      }
      case 3:
        b.insert(b.begin() + static_cast<std::ptrdiff_t>(at),
                 static_cast<std::uint8_t>(rng.below(256)));
        break;
      case 4:
        b.erase(b.begin() + static_cast<std::ptrdiff_t>(at));
        break;
      case 5:
        b.resize(at);
        break;
      default: {  // a run of 0xFF: huge varints and counts
        for (std::size_t i = at; i < std::min(b.size(), at + 1 + rng.below(10)); ++i) b[i] = 0xFF;
      }
    }
  }
  if (rng.below(10) < 8 && last < b.size()) tvtest::fixChecksum(b, last);
  return b;
}

void fuzz(std::uint64_t seed) {
  tv::sim::Rng rng(seed);
  tv::ReplayOptions small;
  small.maxCells = 1 << 16;  // keeps each file's world small, so many files fit in the run
  std::uint64_t refused = 0, replayed = 0;
  const std::uint64_t n = iterations();
  for (std::uint64_t i = 0; i < n; ++i) {
    const Bytes& s = seeds()[rng.below(seeds().size())];
    const Bytes b = mutate(s, rng);
    try {
      tv::Replay r = tv::Replay::fromBytes(b, small);
      (void)r.validate();
      for (const tv::CallInfo& c : r.calls(r.frames() - 1)) (void)c;
      r.seek(r.frames() / 2);
      ++replayed;
    } catch (const tv::Error&) {
      ++refused;
    }
    // Anything else (bad_alloc, length_error, a crash) fails the test.
  }
  EXPECT_EQ(refused + replayed, n);
  EXPECT_GT(refused, n / 10);    // the mutations do reach the checks...
  EXPECT_GT(replayed, n / 100);  // ...and some files still replay (harmless edits, cut tails)
}

TEST(MutationFuzz, Shard1NoMutatedFileCrashesOrThrowsAnythingButError) {
  fuzz(1);
}
TEST(MutationFuzz, Shard2NoMutatedFileCrashesOrThrowsAnythingButError) {
  fuzz(2);
}
TEST(MutationFuzz, Shard3NoMutatedFileCrashesOrThrowsAnythingButError) {
  fuzz(3);
}
TEST(MutationFuzz, Shard4NoMutatedFileCrashesOrThrowsAnythingButError) {
  fuzz(4);
}

}  // namespace
