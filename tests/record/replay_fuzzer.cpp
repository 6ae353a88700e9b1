// libFuzzer target over the recording reader (clang only; see tests/CMakeLists.txt): any input
// must open and replay, or be refused with tv::Error.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "tv/error.hpp"
#include "tv/record/replay.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  tv::ReplayOptions o;
  o.maxCells = 1 << 16;
  try {
    tv::Replay r = tv::Replay::fromBytes(std::vector<std::uint8_t>(data, data + size), o);
    (void)r.validate();
    (void)r.calls(r.frames() - 1);
    r.seek(r.frames() / 2);
  } catch (const tv::Error&) {
  }
  return 0;
}
