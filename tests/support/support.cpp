#include "tests/support/support.h"

#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <filesystem>
#include <cstdio>
#include <system_error>
#include <vector>

namespace p3d::test {

namespace {
map::GenerateOptions options(size_t walls, uint64_t seed) { return {walls, seed, map::builtin_textures()}; }

// The directories this test process made, removed when it exits (ctest runs each test
// in a process of its own), so that runs do not pile them up in the temp directory.
class ScratchDirs {
 public:
  ~ScratchDirs() {
    std::error_code ignored;  // a directory a test removed itself, or cannot be removed: nothing to do
    for (const std::filesystem::path& dir : dirs_) std::filesystem::remove_all(dir, ignored);
  }
  const std::filesystem::path& add(std::filesystem::path dir) { return dirs_.emplace_back(std::move(dir)); }

 private:
  std::vector<std::filesystem::path> dirs_;
};
ScratchDirs& scratch_dirs() {
  static ScratchDirs dirs;
  return dirs;
}
}  // namespace

map::Source random_soup(size_t walls, uint64_t seed) { return map::generate_soup(options(walls, seed)); }
map::Source random_rooms(size_t walls, uint64_t seed) { return map::generate_rooms(options(walls, seed)); }

level::Level compile(const map::Source& source, bsp::Strategy strategy, uint64_t seed) {
  map::validate(source);
  bsp::Options options;
  options.strategy = strategy;
  options.seed = seed;
  return bsp::build(source, options);
}

render::Camera random_camera(const level::Level& level, Rng& rng) {
  const bool has_sectors = std::any_of(level.walls.begin(), level.walls.end(), [](const level::Wall& w) { return !w.segment(); });
  for (int attempt = 0;; ++attempt) {
    const geom::Vec2 p{rng.uniform(level.bounds.min.x, level.bounds.max.x), rng.uniform(level.bounds.min.y, level.bounds.max.y)};
    const int sector = level::sector_at_brute_force(level, p);  // inside a sector (Doom's rule gives one to any point)
    if (has_sectors && sector == level::kNone && attempt < 1000) continue;
    render::Camera c = render::camera_at(level, p, rng.uniform(0, 360), rng.uniform(8, 72), rng.uniform(60, 120));
    return c;
  }
}

std::filesystem::path freedoom_path(const std::string& file) {
  const std::filesystem::path path = std::filesystem::path("/usr/share/games/doom") / file;
  if (!std::filesystem::exists(path))
    throw std::runtime_error(path.string() + " is missing: install Debian's freedoom package (tools/install-deps.sh does)");
  return path;
}

std::filesystem::path temp_dir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("p3d-test-" + name + "-" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return scratch_dirs().add(dir);
}

int run(const std::string& command, std::string& output) {
  output.clear();
  // The programs keep settings and saves under the XDG directories: the tests' own.
  static const std::string xdg =
      scratch_dirs().add(std::filesystem::temp_directory_path() / ("p3d-test-xdg-" + std::to_string(::getpid()))).string();
  const std::string isolated = "export XDG_CONFIG_HOME='" + xdg + "/config' XDG_DATA_HOME='" + xdg + "/data'; " + command;
  FILE* pipe = ::popen((isolated + " 2>&1").c_str(), "r");
  if (!pipe) return -1;
  std::array<char, 4096> buffer;
  size_t n;
  while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0) output.append(buffer.data(), n);
  const int status = ::pclose(pipe);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace p3d::test
