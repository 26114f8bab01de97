// Test helpers: random maps compiled in memory, random cameras, paths.
#pragma once

#include <filesystem>
#include <string>

#include "engine/bsp/build.h"
#include "engine/map/generate.h"
#include "engine/render/camera.h"
#include "engine/util/rng.h"

namespace p3d::test {

// The sanitizer build (ten times slower): the heaviest checks take a sample there.
#ifdef P3D_SANITIZE
inline constexpr bool kSanitized = true;
#else
inline constexpr bool kSanitized = false;
#endif

// The source tree (for maps/ and tests/golden/) and the tools' build directory.
inline std::filesystem::path source_dir() { return P3D_SOURCE_DIR; }
inline std::filesystem::path tools_dir() { return P3D_TOOLS_DIR; }

map::Source random_soup(size_t walls, uint64_t seed);
map::Source random_rooms(size_t walls, uint64_t seed);

level::Level compile(const map::Source& source, bsp::Strategy strategy = bsp::Strategy::kGreedy, uint64_t seed = 1);

// A camera somewhere in the level's bounds (inside a sector when the level has any
// walls with sectors), looking anywhere, at a plausible eye height.
render::Camera random_camera(const level::Level& level, Rng& rng);

// A Freedoom WAD (Debian's freedoom package, which tools/install-deps.sh installs);
// fails the test with a clear message when it is not there.
std::filesystem::path freedoom_path(const std::string& file);

// A fresh empty directory under the system temp directory, removed when the test's
// process exits.
std::filesystem::path temp_dir(const std::string& name);

// Runs a shell command, returning its exit status; output goes to `output`.
int run(const std::string& command, std::string& output);

}  // namespace p3d::test
