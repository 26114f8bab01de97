// bench capture: a frame's render beside its PNG at each level (and stb_image_write,
// the encoder this project began with), then whole `pseudo3d-capture --cameras`
// processes on one thread and on every core.
#include <unistd.h>

#include <array>
#include <cstdio>
#include <iterator>

#include <stb_image_write.h>

#include "engine/bsp/build.h"
#include "engine/bsp/load.h"
#include "engine/image/frame.h"
#include "engine/map/source.h"
#include "engine/render/camera_file.h"
#include "engine/render/renderer.h"
#include "engine/util/file.h"
#include "tools/bench_common.h"
#include "tools/bench_report.h"

namespace p3d::bench {

namespace {

std::vector<uint8_t> stb_png(const image::Image& img) {  // the encoder we replaced, for comparison
  std::vector<uint8_t> out;
  auto sink = [](void* context, void* data, int size) {
    auto* v = static_cast<std::vector<uint8_t>*>(context);
    v->insert(v->end(), static_cast<uint8_t*>(data), static_cast<uint8_t*>(data) + size);
  };
  stbi_write_png_to_func(sink, &out, img.width, img.height, 4, img.pixels.data(), img.width * 4);
  return out;
}

// The PNG encodings the capture table times: each level of ours on every `every`th
// frame (the slow ones on a sample), then stb_image_write (level -1). Each is timed
// just after a render of its frame, as a capture encodes it (a second encoding of the
// same bytes is faster: they are in the cache, and the processor has learnt their
// branches).
struct PngStep {
  int level;
  const char* name;
  size_t every;
};
constexpr PngStep kPngSteps[] = {{image::kPngRuns, "PNG level 1: runs (the default)", 1},
                                 {image::kPngStored, "PNG level 0: stored", 1},
                                 {2, "PNG level 2: libdeflate", 4},
                                 {6, "PNG level 6: libdeflate", 4},
                                 {9, "PNG level 9: libdeflate", 4},
                                 {image::kPngMaxLevel, "PNG level 12: libdeflate", 20},
                                 {-1, "PNG, stb_image_write", 4}};

constexpr int kProcessViews = 300;  // MAP01's views in a timed capture process

// Whole `pseudo3d-capture --cameras` processes on one thread and on every core, in
// turns (the host's noise falls on both alike), medians of five: the outpost path
// (compiled on the way) and, given their cameras, random views of freedoom2 MAP01
// (compiled beforehand).
// Frames go into memory where there is a tmpfs (/dev/shm): the program's time, not the
// disk's.
void time_capture_processes(const Settings& s, const std::vector<render::Camera>* map01_cameras,
                            const std::filesystem::path& dir) {
  const std::string capture = (own_directory() / "pseudo3d-capture").string();
  const auto maps = std::filesystem::path(s.source_dir) / "maps";
  const std::string size = std::to_string(s.width) + "x" + std::to_string(s.height), cores = std::to_string(every_core(s));
  const std::filesystem::path shm = "/dev/shm", frames_dir =
      (std::filesystem::is_directory(shm) ? shm : dir) / ("p3d-bench-frames-" + std::to_string(::getpid()));
  struct Job {
    std::string name;
    std::vector<std::string> level_args;
    size_t frames;
  };
  std::vector<Job> jobs = {{"outpost path (RGB)",
                            {(maps / "outpost.map").string(), "--cameras", (maps / "outpost.path").string()},
                            render::read_camera_list(maps / "outpost.path").size()}};
  if (map01_cameras) {
    std::string list;
    char line[200];
    for (size_t i = 0; i < map01_cameras->size(); ++i) {
      const render::Camera& c = (*map01_cameras)[i];  // at the default eye height, as random_cameras stands them
      std::snprintf(line, sizeof line, "v%zu %.17g %.17g %.17g\n", i, c.pos.x, c.pos.y, c.angle);
      list += line;
    }
    write_file_atomically(dir / "map01.cameras", list);
    run_process({(own_directory() / "pseudo3d-mapc").string(), "--iwad", "/usr/share/games/doom/freedoom2.wad", "--map",
                 "MAP01", "-o", (dir / "map01.bsp").string()});
    jobs.push_back({"freedoom2 MAP01 (8-bit)",
                    {(dir / "map01.bsp").string(), "--cameras", (dir / "map01.cameras").string()},
                    map01_cameras->size()});
  }
  report.print("\n| `pseudo3d-capture --cameras`, %s (whole process) | frames | 1 thread, s | %s threads, s | "
               "speed-up | frames/s | MB |\n|---|---:|---:|---:|---:|---:|---:|\n",
               size.c_str(), cores.c_str());
  for (const Job& job : jobs) {
    std::vector<double> one, all;
    for (int turn = 0; turn < 5; ++turn)
      for (auto [threads, times] : {std::pair{std::string("1"), &one}, std::pair{cores, &all}}) {
        std::filesystem::remove_all(frames_dir);  // each run writes new files, as a first capture does
        std::vector<std::string> args = {capture};
        args.insert(args.end(), job.level_args.begin(), job.level_args.end());
        args.insert(args.end(), {"--size", size, "--threads", threads, "-o", frames_dir.string()});
        times->push_back(run_process(args));
      }
    double bytes = 0;
    for (const auto& entry : std::filesystem::directory_iterator(frames_dir)) bytes += double(entry.file_size());
    const double t1 = median(one), tn = median(all);
    report.print("| %s | %zu | %s | %s | %s | %s | %s |\n", job.name.c_str(), job.frames, fixed(t1, 3).c_str(),
                 fixed(tn, 3).c_str(), fixed(t1 / tn, 2).c_str(), fixed(double(job.frames) / tn, 0).c_str(),
                 fixed(bytes / 1e6, 1).c_str());
  }
  std::filesystem::remove_all(frames_dir);
}

}  // namespace

// The outpost path's frames (RGB) and random views of freedoom2 MAP01 (8-bit, when
// Freedoom is installed): render, then each PNG encoding in one run, its time beside
// the render's and its bytes beside level 1's on the same frames; then the whole
// captures of both (time_capture_processes).
void bench_capture(const Settings& s) {
  const auto dir = std::filesystem::temp_directory_path() / ("p3d-bench-capture-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const auto maps = std::filesystem::path(s.source_dir) / "maps";
  struct Scene {
    std::string name;
    level::Level level;
    std::vector<render::Camera> cameras;
    bool indexed;
  };
  std::vector<Scene> scenes;
  {
    level::Level outpost = bsp::build(map::load_map(maps / "outpost.map"), {});
    auto path = cameras_from(outpost, render::read_camera_list(maps / "outpost.path"));
    scenes.push_back({"outpost path (RGB)", std::move(outpost), std::move(path), false});
  }
  const std::filesystem::path freedoom = "/usr/share/games/doom/freedoom2.wad";
  if (std::filesystem::exists(freedoom)) {
    level::Level level = bsp::build_wad_map(bsp::read_wads({freedoom}), "MAP01", {}, nullptr);
    auto cameras = random_cameras(level, 100, 1);
    scenes.push_back({"freedoom2 MAP01 (8-bit)", std::move(level), std::move(cameras), true});
  }
  report.print("\n### Capture: a frame's render and its PNG at each level, %dx%d, one thread\n\n", s.width, s.height);
  report.print("| frames | step | ms/frame | KB/frame | ÷ render (time) | ÷ level 1 (bytes) |\n"
               "|---|---|---:|---:|---:|---:|\n");
  for (const Scene& scene : scenes) {
    auto renderer = render::make_renderer("bsp");
    renderer->prepare(scene.level);
    const level::State state = level::start_state(scene.level, s.skill);
    render::Frame frame(s.width, s.height);
    frame.keep_indices = scene.indexed;
    struct Sums {
      double frames = 0, ms = 0, bytes = 0, render_ms = 0, level1_bytes = 0;
    };
    std::array<Sums, std::size(kPngSteps)> sums{};
    double render_ms = 0;
    for (size_t c = 0; c < scene.cameras.size(); ++c) {
      auto t = Clock::now();
      renderer->render(scene.level, state, scene.cameras[c], frame);
      const double frame_ms = cli::seconds_since(t) * 1000;
      render_ms += frame_ms;
      double level1_bytes = 0;
      for (size_t k = 0; k < std::size(kPngSteps); ++k) {
        const PngStep& step = kPngSteps[k];
        if (c % step.every != 0 || (step.level < 0 && frame.indexed())) continue;  // stb writes no palette
        if (k > 0) renderer->render(scene.level, state, scene.cameras[c], frame);
        t = Clock::now();
        const double bytes = double(step.level < 0 ? stb_png(frame).size() : frame.png(step.level).size());
        sums[k].ms += cli::seconds_since(t) * 1000;
        if (step.level == image::kPngRuns) level1_bytes = bytes;
        sums[k].frames += 1, sums[k].bytes += bytes, sums[k].render_ms += frame_ms, sums[k].level1_bytes += level1_bytes;
      }
    }
    report.print("| %s | render (bsp) | %s |  | 1.00 |  |\n", scene.name.c_str(),
                 fixed(render_ms / double(scene.cameras.size()), 2).c_str());
    for (size_t k = 0; k < std::size(kPngSteps); ++k) {
      const Sums& sum = sums[k];
      if (sum.frames == 0) continue;
      const std::string name = kPngSteps[k].name + (kPngSteps[k].every > 1
                                                        ? " (every " + std::to_string(kPngSteps[k].every) + "th frame)"
                                                        : std::string());
      report.print("| %s | %s | %s | %s | %s | %s |\n", scene.name.c_str(), name.c_str(),
                   fixed(sum.ms / sum.frames, 2).c_str(), fixed(sum.bytes / sum.frames / 1024, 0).c_str(),
                   fixed(sum.ms / sum.render_ms, 2).c_str(), fixed(sum.bytes / sum.level1_bytes, 2).c_str());
    }
  }
  // Whole captures of 300 views: each process's start (the level read, each worker's
  // first touch of its buffers) a small part of its time, as in a capture for CI.
  std::vector<render::Camera> many_views;
  if (scenes.size() > 1) many_views = random_cameras(scenes[1].level, kProcessViews, 1);
  time_capture_processes(s, scenes.size() > 1 ? &many_views : nullptr, dir);
  std::filesystem::remove_all(dir);
}

}  // namespace p3d::bench
