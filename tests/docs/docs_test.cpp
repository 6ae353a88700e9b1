// The documents a newcomer reads: the README opens with the two commands and stays short, and
// every relative link in every Markdown file of the repository leads to a file that exists and,
// where it names a section, to a heading that exists. A moved section breaks a link somewhere;
// this is where it shows.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "docs/markdown_links.hpp"

namespace fs = std::filesystem;

namespace {

const fs::path kRoot = TV_SOURCE_DIR;

std::string readFile(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  EXPECT_TRUE(in.good()) << "cannot read " << p;
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<std::string> splitLines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// Every Markdown file of the source tree, not of a build or output folder inside it.
std::vector<fs::path> markdownFiles() {
  std::vector<fs::path> files;
  for (auto it = fs::recursive_directory_iterator(kRoot); it != fs::recursive_directory_iterator();
       ++it) {
    const std::string name = it->path().filename().string();
    if (it->is_directory() && (name.rfind("build", 0) == 0 || name == "out" || name[0] == '.')) {
      it.disable_recursion_pending();
      continue;
    }
    if (it->is_regular_file() && it->path().extension() == ".md") files.push_back(it->path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace

TEST(Readme, OpensWithExactlyTheTwoCommandsRunAndTest) {
  const auto lines = splitLines(readFile(kRoot / "README.md"));
  ASSERT_GE(lines.size(), 6u);
  EXPECT_EQ(lines[0], "# Tunnelvision");
  EXPECT_EQ(lines[2], "```sh");
  EXPECT_EQ(lines[3].rfind("scripts/run.sh ", 0), 0u) << lines[3];
  EXPECT_EQ(lines[4].rfind("scripts/test.sh ", 0), 0u) << lines[4];
  EXPECT_EQ(lines[5], "```");
}

TEST(Readme, IsReadInFiveMinutesAtMostThreeHundredLines) {
  EXPECT_LE(splitLines(readFile(kRoot / "README.md")).size(), 300u);
}

TEST(Readme, FirstScreenLeadsToTheApiYourGameAndDebugging) {
  // The first 40 lines (a screen) link to the sections a newcomer came for.
  const auto lines = splitLines(readFile(kRoot / "README.md"));
  std::string screen;
  for (std::size_t i = 0; i < std::min<std::size_t>(40, lines.size()); ++i) screen += lines[i];
  for (const char* anchor : {"(#the-api-at-a-glance)", "(#use-it-in-your-game)",
                             "(#debug-your-own-game)", "(#the-programs)"})
    EXPECT_NE(screen.find(anchor), std::string::npos) << anchor;
}

TEST(Readme, TheStudiesLiveInTheResultsDocumentEachWithItsCommand) {
  const std::string results = readFile(kRoot / "app/bench/RESULTS.md");
  for (const char* study : {"## tunnel:", "## pareto:", "## jitter:", "## scale:", "## stress:",
                            "## record:", "## The targets"})
    EXPECT_NE(results.find(study), std::string::npos) << study;
  EXPECT_NE(results.find("tv-bench $s --full --out app/bench/results/$s"), std::string::npos);
}

TEST(MarkdownLinks, SlugsFollowGithubHeadings) {
  using tv::docs::slug;
  EXPECT_EQ(slug("The API at a glance"), "the-api-at-a-glance");
  EXPECT_EQ(slug("Reading it from C++, and untrusted files"), "reading-it-from-c-and-untrusted-files");
  EXPECT_EQ(slug("substep-discrete with its default pieces, at a wall's end"),
            "substep-discrete-with-its-default-pieces-at-a-walls-end");
  EXPECT_EQ(slug("From LÖVE"), "from-löve");  // letters stay, lowercased as GitHub does (ASCII)
  EXPECT_EQ(slug("2×2 projectiles, diagonal (45°)"), "22-projectiles-diagonal-45");
  EXPECT_EQ(slug("Scene files (`.json`)"), "scene-files-json");
}

TEST(MarkdownLinks, TheCheckerFindsAMissingFileAndAMissingSection) {
  // Negative control: a checker that cannot fail checks nothing.
  const fs::path dir = fs::temp_directory_path() / "tv_docs_negative_control";
  fs::create_directories(dir);
  std::ofstream(dir / "a.md") << "# A\n\n## Real section\n\n[ok](#real-section) [ok](b.md#b)\n"
                                 "[gone](missing.md) [gone](#no-such-section) [gone](b.md#nope)\n"
                                 "```\n[not a link](inside-code.md)\n```\n"
                                 "`[not a link](inline-code.md)` [web](https://example.org/x)\n";
  std::ofstream(dir / "b.md") << "# B\n";
  const auto problems = tv::docs::brokenLinks(dir / "a.md");
  ASSERT_EQ(problems.size(), 3u);
  EXPECT_NE(problems[0].find("missing.md"), std::string::npos) << problems[0];
  EXPECT_NE(problems[1].find("#no-such-section"), std::string::npos) << problems[1];
  EXPECT_NE(problems[2].find("b.md#nope"), std::string::npos) << problems[2];
  fs::remove_all(dir);
}

TEST(MarkdownLinks, EveryRelativeLinkInTheRepositoryLeadsSomewhere) {
  const auto files = markdownFiles();
  ASSERT_GE(files.size(), 6u);  // README, RESULTS, the FORMATs, the Lua README, screenshots...
  for (const fs::path& f : files)
    for (const std::string& problem : tv::docs::brokenLinks(f))
      ADD_FAILURE() << fs::relative(f, kRoot).string() << ": " << problem;
}

namespace {

// The labels of tv-debugger's File menu, read from its source: every string between
// BeginMenu("File") and the menu's EndMenu(), without a trailing "...".
std::vector<std::string> fileMenuLabels() {
  const std::string ui = readFile(kRoot / "app/debugger/debugger_ui.cpp");
  const std::size_t begin = ui.find("BeginMenu(\"File\")");
  const std::size_t end = ui.find("EndMenu()", begin);
  std::vector<std::string> labels;
  if (begin == std::string::npos || end == std::string::npos) return labels;
  for (std::size_t q = ui.find('"', begin + 18); q < end; q = ui.find('"', q + 1)) {
    const std::size_t close = ui.find('"', q + 1);
    std::string label = ui.substr(q + 1, close - q - 1);
    if (label.size() > 3 && label.ends_with("...")) label.resize(label.size() - 3);
    if (!label.empty()) labels.push_back(label);
    q = close;
  }
  return labels;
}

}  // namespace

// The documents name the File menu's items as the menu does: the README sent people to
// "File > Open file...", which the menu did not have.
TEST(Menus, EveryFileMenuItemTheDocumentsNameIsInTheMenu) {
  const std::vector<std::string> labels = fileMenuLabels();
  ASSERT_GE(labels.size(), 4u) << "the File menu was not found in app/debugger/debugger_ui.cpp";
  ASSERT_NE(std::find(labels.begin(), labels.end(), "Open recording"), labels.end());
  // The control: the label the README used is not one of them.
  EXPECT_EQ(std::find(labels.begin(), labels.end(), "Open file"), labels.end());
  int named = 0;
  for (const fs::path& f : markdownFiles()) {
    if (f.filename() == "CHANGELOG.md") continue;  // the history names menus as they were
    const std::string text = readFile(f);
    for (std::size_t at = text.find("File > "); at != std::string::npos;
         at = text.find("File > ", at + 1)) {
      const std::string said = text.substr(at + 7, 80);
      const bool found = std::any_of(labels.begin(), labels.end(), [&](const std::string& l) {
        return said.rfind(l, 0) == 0;
      });
      ++named;
      EXPECT_TRUE(found) << fs::relative(f, kRoot).string() << ": 'File > "
                         << said.substr(0, said.find('\n')) << "' is not in the File menu";
    }
  }
  EXPECT_GE(named, 3);
}
