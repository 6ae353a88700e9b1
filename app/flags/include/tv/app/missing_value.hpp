#pragma once
/// A flag at the end of the command line, or followed by another flag, has no value. When the
/// tool does not know the flag at all, that is what to say: "--bogus needs a value" sent a new
/// user looking for a value to give a flag that does not exist.

#include <initializer_list>
#include <string>
#include <string_view>

#include "tv/sim/scene.hpp"

namespace tv::app {

/// Whether `name` (without the --) is a parameter of some built-in scene (--speed, --count, ...).
[[nodiscard]] inline bool isSceneParameter(std::string_view name) {
  for (const sim::SceneDef& s : sim::builtinScenes().all()) {
    if (s.defaults().has(name)) return true;
  }
  return false;
}

/// Throws "--NAME needs a value" for a flag the tool takes (one of `toolFlags`, or a scene
/// parameter), else "unknown flag '--NAME'".
template <class E>
[[noreturn]] void refuseMissingValue(std::string_view name,
                                     std::initializer_list<std::string_view> toolFlags) {
  bool known = isSceneParameter(name);
  for (const std::string_view f : toolFlags) known = known || f == name;
  if (known) throw E{"--" + std::string(name) + " needs a value"};
  throw E{"unknown flag '--" + std::string(name) + "'"};
}

}  // namespace tv::app
