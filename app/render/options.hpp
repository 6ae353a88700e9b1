#pragma once
// tv-render's command line: the picture's flags (shared with tv-debugger, see
// tv/ui/picture_options.hpp) plus --out, --ticks, --timing and --list, which only tv-render uses.

#include "tv/ui/picture_options.hpp"

namespace tv::headless {

using UsageError = ui::UsageError;
using ViewKind = ui::ViewKind;
using Options = ui::PictureOptions;

[[nodiscard]] inline Options parseOptions(int argc, char** argv) {
  return ui::parsePictureOptions(argc, argv);
}
extern const char* const kUsage;

}  // namespace tv::headless
