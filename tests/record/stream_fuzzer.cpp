// libFuzzer target over the live stream reader (clang only; see tests/CMakeLists.txt): any bytes,
// fed in pieces whose sizes the first byte chooses, must be read or refused with tv::Error; what
// was accepted must then open as a recording or be refused.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "stream_reader.hpp"
#include "tv/error.hpp"
#include "tv/record/replay.hpp"

namespace {
struct Collect final : tv::rec::StreamReader::Sink {
  std::vector<std::uint8_t> file;
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
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::size_t piece = 1 + data[0] % 64;
  tv::rec::StreamReader reader({1u << 20, 1u << 16});
  Collect got;
  try {
    for (std::size_t at = 1; at < size; at += piece) {
      reader.feed(data + at, std::min(piece, size - at), got);
    }
  } catch (const tv::Error&) {
  }
  if (got.file.size() > 32) {
    try {
      tv::ReplayOptions o;
      o.maxCells = 1 << 16;
      tv::Replay r = tv::Replay::fromBytes(got.file, o);
      (void)r.validate();
    } catch (const tv::Error&) {
    }
  }
  return 0;
}
