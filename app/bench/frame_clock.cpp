#include "frame_clock.hpp"

#include "report.hpp"

namespace tv::bench {

std::string FrameModel::describe() const {
  return "frame time = (1/" + fixed(rate, 0) + " s)·(1 + U(−" + fixed(jitter * 100, 0) + "%, +" +
         fixed(jitter * 100, 0) + "%)); with probability " + fixed(hitchChance * 100, 0) +
         "% a hitch of " + fixed(hitchMin, 0) + "–" + fixed(hitchMax, 0) + " frame periods (" +
         fixed(1000 * hitchMin / rate, 0) + "–" + fixed(1000 * hitchMax / rate, 0) + " ms)";
}

}  // namespace tv::bench
