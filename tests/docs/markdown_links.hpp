#pragma once
// Relative links in Markdown, checked the way GitHub renders them: a link's file must exist
// beside the document, and its `#section` must be the anchor of one of that file's headings.
// Links inside code (fenced blocks, `spans`) are text, not links; web links are not checked.

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace tv::docs {

namespace detail {

inline std::uint32_t nextCodePoint(const std::string& s, std::size_t& i) {
  const auto b = static_cast<unsigned char>(s[i++]);
  int extra = b >= 0xF0 ? 3 : b >= 0xE0 ? 2 : b >= 0xC0 ? 1 : 0;
  std::uint32_t cp = extra == 3 ? b & 0x07u : extra == 2 ? b & 0x0Fu : extra == 1 ? b & 0x1Fu : b;
  while (extra-- > 0 && i < s.size()) cp = (cp << 6) | (static_cast<unsigned char>(s[i++]) & 0x3Fu);
  return cp;
}

inline void appendUtf8(std::string& out, std::uint32_t cp) {
  if (cp < 0x80) {
    out += static_cast<char>(cp);
  } else if (cp < 0x800) {
    out += static_cast<char>(0xC0 | (cp >> 6));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  } else if (cp < 0x10000) {
    out += static_cast<char>(0xE0 | (cp >> 12));
    out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  } else {
    out += static_cast<char>(0xF0 | (cp >> 18));
    out += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
    out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  }
}

// Symbols and punctuation outside ASCII that GitHub drops from anchors (×, °, –, →, ...); letters
// and digits of any script stay.
inline bool isDroppedSymbol(std::uint32_t cp) {
  return (cp >= 0x00A0 && cp <= 0x00BF) || cp == 0x00D7 || cp == 0x00F7 ||
         (cp >= 0x2000 && cp <= 0x2BFF) || (cp >= 0x3000 && cp <= 0x303F);
}

// The document's lines with code removed: fenced blocks become empty lines, `spans` vanish.
inline std::vector<std::string> proseLines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  bool fenced = false;
  for (std::string line; std::getline(in, line);) {
    const auto first = line.find_first_not_of(' ');
    if (first != std::string::npos && line.compare(first, 3, "```") == 0) {
      fenced = !fenced;
      lines.emplace_back();
      continue;
    }
    if (fenced) {
      lines.emplace_back();
      continue;
    }
    std::string prose;
    bool inSpan = false;
    for (char c : line) {
      if (c == '`') {
        inSpan = !inSpan;
      } else if (!inSpan) {
        prose += c;
      }
    }
    lines.push_back(prose);
  }
  return lines;
}

inline std::string readAll(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace detail

/// The anchor GitHub gives a heading: lowercased, punctuation and symbols dropped, spaces as '-'.
inline std::string slug(const std::string& heading) {
  std::string out;
  for (std::size_t i = 0; i < heading.size();) {
    std::uint32_t cp = detail::nextCodePoint(heading, i);
    if (cp < 0x80) {
      const char c = static_cast<char>(cp);
      if (c >= 'A' && c <= 'Z') {
        out += static_cast<char>(c - 'A' + 'a');
      } else if ((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-' || c == '_') {
        out += c;
      } else if (c == ' ') {
        out += '-';
      }
      continue;
    }
    if (detail::isDroppedSymbol(cp)) continue;
    if (cp >= 0xC0 && cp <= 0xDE) cp += 0x20;  // Latin-1 capitals (× was dropped above)
    detail::appendUtf8(out, cp);
  }
  return out;
}

/// The anchors of a Markdown file's headings, with GitHub's -1, -2 suffixes for repeats.
inline std::set<std::string> anchors(const std::string& text) {
  std::set<std::string> result;
  std::map<std::string, int> seen;
  for (const std::string& line : detail::proseLines(text)) {
    std::size_t level = 0;
    while (level < line.size() && line[level] == '#') ++level;
    if (level == 0 || level > 6 || level >= line.size() || line[level] != ' ') continue;
    std::string title = line.substr(level + 1);
    while (!title.empty() && (title.back() == '#' || title.back() == ' ')) title.pop_back();
    const std::string base = slug(title);
    const int n = seen[base]++;
    result.insert(n == 0 ? base : base + "-" + std::to_string(n));
  }
  return result;
}

/// Every relative link of `doc` that leads nowhere, as "link to TARGET: why".
inline std::vector<std::string> brokenLinks(const std::filesystem::path& doc) {
  namespace fs = std::filesystem;
  std::vector<std::string> problems;
  const std::string text = detail::readAll(doc);
  // The code was removed from the prose before it was searched, so code may hold any text.
  // A link's target follows "](" up to the first ')' or blank (a title may follow the blank).
  for (const std::string& line : detail::proseLines(text)) {
    for (std::size_t at = line.find("]("); at != std::string::npos; at = line.find("](", at + 2)) {
      const std::size_t begin = at + 2;
      const std::size_t end = line.find_first_of(") \t(", begin);
      if (end == std::string::npos || end == begin || line[end] == '(') continue;
      const std::string target = line.substr(begin, end - begin);
      if (target.find("://") != std::string::npos || target.rfind("mailto:", 0) == 0) continue;
      const auto hash = target.find('#');
      const std::string file = target.substr(0, hash);
      const std::string anchor = hash == std::string::npos ? "" : target.substr(hash + 1);
      const fs::path path = file.empty() ? doc : doc.parent_path() / file;
      if (!fs::exists(path)) {
        problems.push_back("link to " + target + ": no such file");
        continue;
      }
      if (anchor.empty() || path.extension() != ".md") continue;
      if (!anchors(detail::readAll(path)).count(anchor))
        problems.push_back("link to " + target + ": no heading with that anchor");
    }
  }
  return problems;
}

}  // namespace tv::docs
