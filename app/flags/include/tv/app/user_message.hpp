#pragma once
/// The library names where an error came from for its programmer ("tv::sim::Params: dt must
/// be ..."); a person at a tool knows the flag or the field, not the class. The tools show an
/// error's message without that leading name; the value and the reason stay.

#include <cctype>
#include <exception>
#include <new>
#include <string>
#include <string_view>

namespace tv::app {

/// `message` without a leading "tv::Name::name: " (or "tv::sim::Scene 'x': ", which becomes
/// "scene 'x': ").
[[nodiscard]] inline std::string userMessage(std::string_view message) {
  if (message.substr(0, 15) == "tv::sim::Scene ") return "scene " + std::string(message.substr(15));
  const std::size_t colon = message.find(": ");
  if (message.substr(0, 4) != "tv::" || colon == std::string_view::npos) {
    return std::string(message);
  }
  for (const char c : message.substr(0, colon)) {
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != ':') {
      return std::string(message);
    }
  }
  return std::string(message.substr(colon + 2));
}

/// The same for any exception; an allocation that failed reads "out of memory", not
/// "std::bad_alloc".
[[nodiscard]] inline std::string userMessage(const std::exception& e) {
  if (dynamic_cast<const std::bad_alloc*>(&e)) return "out of memory";
  return userMessage(std::string_view(e.what()));
}

}  // namespace tv::app
