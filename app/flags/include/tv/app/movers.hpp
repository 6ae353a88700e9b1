#pragma once
/// A mover named where a person typed it (a flag, a settings file) becomes a MoverSpec here,
/// once, from core's mover table; every tool passes the spec on and never parses the name again.

#include <string>
#include <string_view>

#include "tv/app/user_message.hpp"
#include "tv/error.hpp"
#include "tv/mover.hpp"

namespace tv::app {

/// The mover `text` names, for flag `--flag`; `UsageError{message}` naming the flag and listing
/// the valid names otherwise ("--mover: unknown mover 'warp' (known: discrete, ...)").
template <class UsageError>
[[nodiscard]] MoverSpec parseMoverFlag(std::string_view flag, std::string_view text) {
  try {
    return parseMover(text);
  } catch (const Error& e) {
    throw UsageError{"--" + std::string(flag) + ": " + userMessage(e)};
  }
}

}  // namespace tv::app
