// A mutation fuzzer over the live stream reader, as mutation_fuzz_test is over the file reader:
// valid streams (a game's hello and a recording) with bytes flipped, set, inserted, deleted or
// cut — the chunk checksum fixed up most of the time, so that the mutation reaches the decoder —
// fed in pieces of random sizes, as a socket delivers them. Every stream must be read to its end
// or refused with a tv::Error: no crash, no other exception; what it accepted opens as a
// recording or is refused. TV_FUZZ_ITERATIONS=N runs N streams per shard.

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>
#include <vector>

#include "live_kit.hpp"
#include "recording_kit.hpp"
#include "stream_reader.hpp"
#include "tv/error.hpp"
#include "tv/record/replay.hpp"
#include "tv/sim/rng.hpp"

namespace {

using Bytes = std::vector<std::uint8_t>;

std::uint64_t iterations() {
  if (const char* v = std::getenv("TV_FUZZ_ITERATIONS")) return std::strtoull(v, nullptr, 10);
  return 10000;  // × 2 shards
}

const std::vector<Bytes>& seeds() {
  static const std::vector<Bytes> s = [] {
    std::vector<Bytes> out;
    tvtest::Script a;
    a.framesToPlay = 3;
    a.keyframeEvery = 2;
    out.push_back(a.record());
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
    for (Bytes& b : out) {
      Bytes hello = tvtest::gameHello(true);
      b.insert(b.begin(), hello.begin(), hello.end());
    }
    return out;
  }();
  return s;
}

// The recording's part starts after the 16-byte hello: fixChecksum works on it there.
Bytes mutate(const Bytes& seed, tv::sim::Rng& rng) {
  Bytes b = seed;
  const int edits = 1 + static_cast<int>(rng.below(4));
  std::size_t last = 0;
  for (int e = 0; e < edits && !b.empty(); ++e) {
    const std::size_t at = rng.below(b.size());
    last = at;
    switch (rng.below(6)) {
      case 0:
        b[at] ^= static_cast<std::uint8_t>(1u << rng.below(8));
        break;
      case 1:
        b[at] = static_cast<std::uint8_t>(rng.below(256));
        break;
      case 2:
        b.insert(b.begin() + static_cast<std::ptrdiff_t>(at),
                 static_cast<std::uint8_t>(rng.below(256)));
        break;
      case 3:
        b.erase(b.begin() + static_cast<std::ptrdiff_t>(at));
        break;
      case 4:
        b.resize(at);
        break;
      default:
        for (std::size_t i = at; i < std::min(b.size(), at + 1 + rng.below(10)); ++i) b[i] = 0xFF;
    }
  }
  if (rng.below(10) < 8 && last >= 16 && last < b.size()) {
    Bytes file(b.begin() + 16, b.end());
    tvtest::fixChecksum(file, last - 16);
    std::copy(file.begin(), file.end(), b.begin() + 16);
  }
  return b;
}

// Keeps what the reader accepted, as a file.
struct Collect final : tv::rec::StreamReader::Sink {
  Bytes file;
  void hello(std::uint32_t) override {}
  void header(const std::array<std::uint8_t, tv::rec::kHeaderSize>& h,
              const tv::rec::HeaderInfo&) override {
    file.assign(h.begin(), h.end());
  }
  void frame(tv::LiveFrame&& f) override {
    file.insert(file.end(), f.chunk.begin(), f.chunk.end());
  }
  void end() override {}
};

void fuzz(std::uint64_t seed) {
  tv::sim::Rng rng(seed);
  std::uint64_t refused = 0, read = 0;
  const std::uint64_t n = iterations();
  for (std::uint64_t i = 0; i < n; ++i) {
    const Bytes b = mutate(seeds()[rng.below(seeds().size())], rng);
    tv::rec::StreamReader reader({1u << 20, 1u << 16});
    Collect got;
    try {
      for (std::size_t at = 0; at < b.size();) {
        const std::size_t piece = std::min(b.size() - at, 1 + rng.below(64));
        reader.feed(b.data() + at, piece, got);
        at += piece;
      }
      ++read;
    } catch (const tv::Error&) {
      ++refused;
    }
    if (got.file.size() > 32) {
      try {
        tv::ReplayOptions small;
        small.maxCells = 1 << 16;
        tv::Replay r = tv::Replay::fromBytes(got.file, small);
        (void)r.validate();
      } catch (const tv::Error&) {
      }
    }
    // Anything else (bad_alloc, length_error, a crash) fails the test.
  }
  EXPECT_EQ(refused + read, n);
  EXPECT_GT(refused, n / 10);  // the mutations reach the checks...
  EXPECT_GT(read, n / 100);    // ...and some streams still read whole (harmless edits)
}

TEST(StreamFuzz, Shard1NoMutatedStreamCrashesOrThrowsAnythingButError) {
  fuzz(11);
}
TEST(StreamFuzz, Shard2NoMutatedStreamCrashesOrThrowsAnythingButError) {
  fuzz(12);
}

TEST(StreamFuzz, AValidStreamFedAByteAtATimeGivesTheRecordingBack) {
  const Bytes& s = seeds()[0];
  tv::rec::StreamReader reader({1u << 20, 1u << 16});
  Collect got;
  for (const std::uint8_t byte : s) reader.feed(&byte, 1, got);
  EXPECT_TRUE(reader.ended());
  const Bytes file(s.begin() + 16, s.end() - 8);  // without the hello and the end mark
  EXPECT_EQ(got.file, file);
}

}  // namespace
