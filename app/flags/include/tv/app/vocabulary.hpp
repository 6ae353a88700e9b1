#pragma once
/// One vocabulary for every tool: a scene parameter is spelled the same as a flag of tv-run,
/// tv-render, tv-debugger and tv-bench, as a label in the debugger's panel and as a CSV column
/// (--speed, --size, --tile, --dt, --substep, --cell, --count ...); the traced body is --body
/// and a picture's pixel size --window. The spellings the tools used to accept are refused
/// with the one to write instead, rather than silently meaning something else.

#include <string>
#include <string_view>

namespace tv::app {

struct RetiredFlag {
  std::string_view old;  ///< without the leading --
  std::string_view now;  ///< what to write instead
};

inline constexpr RetiredFlag kRetiredFlags[] = {
    {"body-size", "--size S (the body size, in px, in every tool)"},
    {"velocity", "--speed V (the bodies' speed, in px/s, in every tool)"},
    {"trace", "--body I (the traced body, in every tool)"},
};

/// Throws `UsageError{message}` when `name` (without --) is a retired spelling.
template <class UsageError>
void refuseRetiredFlag(std::string_view name) {
  for (const RetiredFlag& r : kRetiredFlags) {
    if (name == r.old) {
      throw UsageError{"--" + std::string(name) + ": no longer a flag; write " +
                       std::string(r.now)};
    }
  }
}

/// `--size WxH` was the picture's size in tv-render and tv-debugger: say where it went.
template <class UsageError>
void refuseWindowSizeAsSize(std::string_view value) {
  if (value.find('x') != std::string_view::npos) {
    throw UsageError{"--size " + std::string(value) +
                     ": --size is the body size (px) in every tool; the picture's size is "
                     "--window WxH"};
  }
}

}  // namespace tv::app
