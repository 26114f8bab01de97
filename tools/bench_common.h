// bench's pieces shared by its sections (bench.cpp, bench_wad.cpp, bench_doom.cpp,
// bench_capture.cpp): the settings from the command line, child processes timed whole,
// cameras (from a list, or random) and the frame timed on one thread beside every core.
#pragma once

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "engine/level/level.h"
#include "engine/render/camera.h"
#include "engine/render/camera_file.h"
#include "tools/cli.h"

namespace p3d::bench {

using Clock = std::chrono::steady_clock;

struct Settings {
  cli::LevelArgs wads;         // the wad section: --iwad, --file, --map
  int skill = level::kDefaultSkill;
  int cameras = 30;            // the wad section: random cameras per map
  int runs = 5;                // the wad section: compiles per map and tool (median)
  int peer_reps = 3;           // the doom section: Crispy Doom timings per demo (median); 0: ours only
  int threads = 0;             // the doom, wad and capture sections' "every core": this many threads (0: every core)
  int width = 640, height = 400;
  int repeat = 3;              // renders per camera; the median of all frames is reported
  double budget_seconds = 2;   // per renderer and map: slow renderers render a prefix of the path
  std::string source_dir = cli::bundled_maps_dir().parent_path().string();
  std::vector<size_t> sizes = {1000, 10000, 100000, 1000000};
  std::vector<std::string> renderers;
  std::string beside_mapc;     // the hostile section: another pseudo3d-mapc timed beside this one
};

// The thread count of "every core": --threads, or the machine's cores.
int every_core(const Settings& s);

// Runs a program with its output discarded: its wall time, peak memory and exit status.
struct Measured {
  double seconds = 0;
  double cpu_seconds = 0;  // user + system
  double peak_mb = 0;
  int status = 0;
};
Measured run_measured(const std::vector<std::string>& args);
// A child's wall time; it must succeed.
double run_process(const std::vector<std::string>& args);
// The directory of this program (the other tools are built beside it).
std::filesystem::path own_directory();
bool on_path(const std::string& program);

// The cameras of a list (a camera file's lines) standing in the level.
std::vector<render::Camera> cameras_from(const level::Level& level, const std::vector<render::CameraSpec>& specs);
// Cameras at random points inside sectors, looking anywhere, eye 41 above the floor.
std::vector<render::Camera> random_cameras(const level::Level& level, int count, uint64_t seed);

// The bsp renderer's ms/frame on the cameras at w x h, on one thread and on `cores`
// (medians; see bench_common.cpp). keep_indices: a paletted level's frames stay 8-bit
// (Doom's screen before its blit), else they are resolved to colours.
std::pair<double, double> time_threads(const level::Level& level, const level::State& state,
                                       const std::vector<render::Camera>& cameras, int w, int h, int cores, int repeat,
                                       bool keep_indices = false);

// Sections in files of their own.
void bench_wad(const Settings& s);   // every map of WADs compiled beside ZDBSP, and rendered
void bench_doom(const Settings& s);  // beside Crispy Doom
void bench_capture(const Settings& s);  // a frame's render beside its PNG at each level; whole captures

}  // namespace p3d::bench
