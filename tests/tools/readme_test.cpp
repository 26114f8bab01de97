// Every command in the fenced `sh` blocks of the README and docs/ runs as written and
// succeeds (a test per document), so the documents cannot drift from the programs; every relative link in
// them leads to a file that exists. Each block runs as one bash script in a
// fresh directory where build/, maps/, tools/ and tests/ lead to the real ones, so
// every output lands in that directory's out/. The game runs through SDL's dummy
// video driver for a few tics. Skipped, and checked to be the only ones skipped: the
// two quick-start commands (they install packages and build; CI runs the second) and
// the whole benchmark (`bench` alone, minutes; its sections run here).
// Release only: the sanitizer build checks the same code through the other tests.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <regex>
#include <sstream>

#include "engine/util/file.h"
#include "tests/support/support.h"

namespace p3d {
namespace {

struct Block {
  int line;  // of the opening fence
  std::vector<std::string> lines;
};

// The fenced blocks of one language ("sh", "console") in a Markdown text.
std::vector<Block> fenced_blocks(const std::string& text, const std::string& language) {
  std::vector<Block> blocks;
  std::istringstream in(text);
  std::string line;
  bool inside = false;
  for (int number = 1; std::getline(in, line); ++number) {
    if (!inside && line == "```" + language) {
      inside = true;
      blocks.push_back({number, {}});
    } else if (inside && line.rfind("```", 0) == 0) {
      inside = false;
    } else if (inside) {
      blocks.back().lines.push_back(line);
    }
  }
  return blocks;
}

// The command without its trailing "# comment".
std::string strip_comment(const std::string& line) {
  const size_t hash = line.find(" #");
  std::string command = hash == std::string::npos ? line : line.substr(0, hash);
  while (!command.empty() && command.back() == ' ') command.pop_back();
  return command;
}

bool skipped(const std::string& command) {
  return command == "tools/quickstart.sh" || command == "tests/run.sh" || command == "build/tools/pseudo3d-bench";
}

// The game in a window: through the dummy video driver, for a few tics.
std::string adapt(const std::string& command) {
  if (command.rfind("build/game/pseudo3d", 0) != 0 || command.find("--headless") != std::string::npos) return command;
  return "SDL_VIDEODRIVER=dummy SDL_AUDIODRIVER=dummy " + command + " --quit-after-tics 5 --no-vsync";
}

// The README, then docs/*.md in name order.
std::vector<std::filesystem::path> documents() {
  std::vector<std::filesystem::path> files = {test::source_dir() / "README.md"};
  std::vector<std::filesystem::path> docs;
  for (const auto& entry : std::filesystem::directory_iterator(test::source_dir() / "docs"))
    if (entry.path().extension() == ".md") docs.push_back(entry.path());
  std::sort(docs.begin(), docs.end());
  files.insert(files.end(), docs.begin(), docs.end());
  return files;
}

// A fresh directory where build/, maps/, tools/ and tests/ lead to the real ones, with
// out/outpost.bsp compiled as the quick start leaves it.
std::filesystem::path scratch(const std::string& name) {
  const auto dir = test::temp_dir(name);
  std::filesystem::create_directory_symlink(test::tools_dir().parent_path(), dir / "build");
  for (const char* shared : {"maps", "tools", "tests"})
    std::filesystem::create_directory_symlink(test::source_dir() / shared, dir / shared);
  std::string output;
  EXPECT_EQ(test::run("cd " + dir.string() + " && build/tools/pseudo3d-mapc maps/outpost.map -o out/outpost.bsp", output), 0)
      << output;
  return dir;
}

// The commands of a document's `sh` blocks, each block as one script (a line is
// skipped when `skipped`; `skips` counts them).
std::vector<std::pair<int, std::string>> block_scripts(const std::filesystem::path& document, size_t& commands,
                                                       size_t& skips) {
  std::vector<std::pair<int, std::string>> scripts;
  for (const Block& block : fenced_blocks(read_file_text(document), "sh")) {
    std::string script;
    for (const std::string& line : block.lines) {
      const std::string command = strip_comment(line);
      if (command.empty()) continue;
      if (skipped(command)) {
        ++skips;
        continue;
      }
      script += adapt(command) + "\n";
      ++commands;
    }
    scripts.push_back({block.line, script});
  }
  return scripts;
}

TEST(Readme, OnlyTheQuickStartAndTheWholeBenchmarkAreSkipped) {
  size_t commands = 0, skips = 0;
  for (const std::filesystem::path& document : documents()) block_scripts(document, commands, skips);
  EXPECT_EQ(skips, 3u) << "only the quick start and the whole benchmark are skipped";
  EXPECT_GT(commands, 40u);
}

// One test per document, so that ctest runs them side by side.
class DocumentCommands : public testing::TestWithParam<std::filesystem::path> {};

TEST_P(DocumentCommands, RunAsWritten) {
#ifdef P3D_SANITIZE
  GTEST_SKIP() << "the Release build runs the documents' commands";
#endif
  const std::filesystem::path& document = GetParam();
  const std::string name = std::filesystem::relative(document, test::source_dir()).string();
  const auto dir = scratch("readme_" + document.stem().string());
  size_t commands = 0, skips = 0;
  for (const auto& [line, commands_of_block] : block_scripts(document, commands, skips)) {
    write_file_atomically(dir / "block.sh", "set -euo pipefail\ncd " + dir.string() + "\n" + commands_of_block);
    std::string output;
    EXPECT_EQ(test::run("bash " + (dir / "block.sh").string(), output), 0)
        << name << ":" << line << ": a command failed:\n" << commands_of_block << "\n" << output;
  }
  std::printf("[ stats    ] %s: %zu commands run, %zu skipped\n", name.c_str(), commands, skips);
  std::filesystem::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(Readme, DocumentCommands, testing::ValuesIn(documents()),
                         [](const testing::TestParamInfo<std::filesystem::path>& document) {
                           std::string name = document.param.stem().string();  // README, docs_front_end, ...
                           std::replace_if(name.begin(), name.end(), [](unsigned char c) { return !std::isalnum(c); }, '_');
                           return name == "README" ? name : "docs_" + name;
                         });

// An example in a fenced `console` block: "$ command" lines, each followed by what it
// prints.
struct Example {
  int line;
  std::string command;
  std::vector<std::string> expected;
};

std::vector<Example> console_examples(const std::string& text) {
  std::vector<Example> examples;
  for (const Block& block : fenced_blocks(text, "console"))
    for (size_t i = 0; i < block.lines.size(); ++i) {
      const std::string& line = block.lines[i];
      if (line.rfind("$ ", 0) == 0)
        examples.push_back({block.line + 1 + int(i), line.substr(2), {}});
      else if (!examples.empty())
        examples.back().expected.push_back(line);
    }
  return examples;
}

// A printed line as the documents show it: "..." stands for what changes from run to
// run (times), everything else is literal.
std::regex line_pattern(const std::string& shown) {
  std::string pattern;
  for (size_t i = 0; i < shown.size(); ++i) {
    if (shown.compare(i, 3, "...") == 0) {  // a time: its column's padding shrinks as it grows (58.4, 103.7)
      while (!pattern.empty() && pattern.back() == ' ') pattern.pop_back();
      pattern += " *.*";
      i += 2;
    } else {
      if (std::string("\\^$.|?*+()[]{}").find(shown[i]) != std::string::npos) pattern += '\\';
      pattern += shown[i];
    }
  }
  return std::regex(pattern);
}

// The documents' example outputs are what the programs print: each shown line, in
// order, among the lines the command prints (numbers exact; "..." for times).
TEST(Readme, ExampleOutputsAreWhatTheProgramsPrint) {
#ifdef P3D_SANITIZE
  GTEST_SKIP() << "the Release build runs the documents' examples";
#endif
  const auto dir = scratch("examples");
  size_t checked = 0;
  for (const std::filesystem::path& document : documents()) {
    const std::string name = std::filesystem::relative(document, test::source_dir()).string();
    for (const Example& example : console_examples(read_file_text(document))) {
      std::string output;
      ASSERT_EQ(test::run("cd " + dir.string() + " && " + example.command, output), 0)
          << name << ":" << example.line << ": " << example.command << "\n" << output;
      std::istringstream printed(output);
      std::string line;
      size_t next = 0;
      while (next < example.expected.size() && std::getline(printed, line))
        if (std::regex_match(line, line_pattern(example.expected[next]))) ++next;
      EXPECT_EQ(next, example.expected.size())
          << name << ":" << example.line << ": " << example.command << "\n  shows: "
          << (next < example.expected.size() ? example.expected[next] : "") << "\n  printed:\n" << output;
      ++checked;
    }
  }
  EXPECT_GE(checked, 3u);
  std::filesystem::remove_all(dir);
}

// Links and pictures in the documents lead somewhere: each relative target exists.
TEST(Readme, RelativeLinksLeadToFiles) {
  const std::regex link(R"(\]\(([^)#\s]+)(#[^)]*)?\))");
  size_t checked = 0;
  for (const std::filesystem::path& document : documents()) {
    const std::string text = read_file_text(document);
    for (auto m = std::sregex_iterator(text.begin(), text.end(), link); m != std::sregex_iterator(); ++m) {
      const std::string target = (*m)[1];
      if (target.find("://") != std::string::npos) continue;
      EXPECT_TRUE(std::filesystem::exists(document.parent_path() / target)) << document << " links to " << target;
      ++checked;
    }
  }
  EXPECT_GT(checked, 10u);
}

}  // namespace
}  // namespace p3d
