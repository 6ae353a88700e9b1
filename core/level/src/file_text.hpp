#pragma once
// Reading a whole file, bounded: a level file is untrusted. Internal to tv::level.

#include <cstddef>
#include <filesystem>
#include <string>

namespace tv::level::detail {

inline constexpr std::size_t kMaxFileBytes = std::size_t{64} << 20;

/// The file's bytes; throws tv::Error naming the file when it cannot be read or is larger than
/// kMaxFileBytes.
std::string readFileText(const std::filesystem::path& path);

}  // namespace tv::level::detail
