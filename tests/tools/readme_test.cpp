// Every command in the fenced `sh` blocks of the README and docs/ runs as written and
// succeeds, so the documents cannot drift from the programs; every relative link in
// them leads to a file that exists. Each block runs as one bash script in a
// fresh directory where build/, maps/, tools/ and tests/ lead to the real ones, so
// every output lands in that directory's out/. The game runs through SDL's dummy
// video driver for a few tics. Skipped, and checked to be the only ones skipped: the
// two quick-start commands (they install packages and build; CI runs the second) and
// the whole benchmark (`bench` alone, minutes; its sections run here).
// Release only: the sanitizer build checks the same code through the other tests.
#include <gtest/gtest.h>

#include <algorithm>
#include <regex>

#include "engine/util/file.h"
#include "tests/support/support.h"

namespace p3d {
namespace {

struct Block {
  int line;  // of the opening fence
  std::vector<std::string> commands;
};

std::vector<Block> sh_blocks(const std::string& readme) {
  std::vector<Block> blocks;
  std::istringstream in(readme);
  std::string line;
  bool inside = false;
  for (int number = 1; std::getline(in, line); ++number) {
    if (!inside && line == "```sh") {
      inside = true;
      blocks.push_back({number, {}});
    } else if (inside && line.rfind("```", 0) == 0) {
      inside = false;
    } else if (inside) {
      blocks.back().commands.push_back(line);
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
  return command == "tools/quickstart.sh" || command == "tests/run.sh" || command == "build/tools/bench";
}

// The game in a window: through the dummy video driver, for a few tics.
std::string adapt(const std::string& command) {
  if (command.rfind("build/game/game", 0) != 0 || command.find("--headless") != std::string::npos) return command;
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

TEST(Readme, EveryCommandRunsAsWritten) {
#ifdef P3D_SANITIZE
  GTEST_SKIP() << "the Release build runs the documents' commands";
#endif
  const auto dir = test::temp_dir("readme");
  std::filesystem::create_directory_symlink(test::tools_dir().parent_path(), dir / "build");
  for (const char* shared : {"maps", "tools", "tests"})
    std::filesystem::create_directory_symlink(test::source_dir() / shared, dir / shared);
  // The README's commands compile maps/outpost.map first in the quick start.
  std::string output;
  ASSERT_EQ(test::run("cd " + dir.string() + " && build/tools/mapc maps/outpost.map -o out/outpost.bsp", output), 0) << output;

  size_t ran = 0, skips = 0, blocks_seen = 0;
  for (const std::filesystem::path& document : documents()) {
    const std::string name = std::filesystem::relative(document, test::source_dir()).string();
    for (const Block& block : sh_blocks(read_file_text(document))) {
      ++blocks_seen;
      std::string script = "set -euo pipefail\ncd " + dir.string() + "\n";
      for (const std::string& line : block.commands) {
        const std::string command = strip_comment(line);
        if (command.empty()) continue;
        if (skipped(command)) {
          ++skips;
          continue;
        }
        script += adapt(command) + "\n";
        ++ran;
      }
      write_file_atomically(dir / "block.sh", script);
      EXPECT_EQ(test::run("bash " + (dir / "block.sh").string(), output), 0)
          << name << ":" << block.line << ": a command failed:\n" << script << "\n" << output;
    }
  }
  EXPECT_EQ(skips, 3u) << "only the quick start and the whole benchmark are skipped";
  EXPECT_GT(ran, 40u);
  std::printf("[ stats    ] %zu blocks, %zu commands run, %zu skipped\n", blocks_seen, ran, skips);
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
