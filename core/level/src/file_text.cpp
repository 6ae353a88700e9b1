#include "file_text.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <system_error>

#include "tv/error.hpp"

namespace tv::level::detail {

std::string readFileText(const std::filesystem::path& path) {
  const std::string name = path.string();
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) fail(name, "is a directory, not a file");
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(name, std::string("cannot open: ") + std::strerror(errno));
  // Read in pieces rather than trusting a size: a pipe or a growing file has none.
  std::string text;
  char buf[1 << 16];
  while (in.read(buf, sizeof buf) || in.gcount() > 0) {
    text.append(buf, static_cast<std::size_t>(in.gcount()));
    if (text.size() > kMaxFileBytes) {
      fail(name, "larger than " + std::to_string(kMaxFileBytes >> 20) + " MiB: not a level file");
    }
  }
  if (in.bad()) fail(name, "read error");
  return text;
}

}  // namespace tv::level::detail
