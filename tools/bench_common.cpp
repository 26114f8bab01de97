// bench_common.h's pieces.
#include "tools/bench_common.h"

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <thread>

#include "engine/render/renderer.h"
#include "engine/util/error.h"
#include "engine/util/rng.h"
#include "tools/bench_report.h"

namespace p3d::bench {

int every_core(const Settings& s) { return s.threads > 0 ? s.threads : int(std::max(1u, std::thread::hardware_concurrency())); }

Measured run_measured(const std::vector<std::string>& args) {
  std::vector<char*> argv;
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  const auto start = Clock::now();
  const pid_t pid = ::fork();
  if (pid == 0) {
    const int null = ::open("/dev/null", O_WRONLY);
    ::dup2(null, 1);
    ::dup2(null, 2);
    ::execvp(argv[0], argv.data());
    ::_exit(127);
  }
  // A child's peak RSS counts the forked copy of this process before its exec (Linux
  // keeps the high-water mark across exec): main runs the hostile section first, while
  // bench is still small.
  int status = 0;
  rusage usage{};
  if (pid < 0 || ::wait4(pid, &status, 0, &usage) < 0 || !WIFEXITED(status)) throw Error(args[0] + " did not finish");
  const auto seconds = [](const timeval& t) { return double(t.tv_sec) + double(t.tv_usec) / 1e6; };
  return {cli::seconds_since(start), seconds(usage.ru_utime) + seconds(usage.ru_stime), double(usage.ru_maxrss) / 1024,
          WEXITSTATUS(status)};
}

double run_process(const std::vector<std::string>& args) {
  const Measured m = run_measured(args);
  if (m.status != 0) throw Error(args[0] + " failed (" + args.back() + ")");
  return m.seconds;
}

std::filesystem::path own_directory() { return std::filesystem::read_symlink("/proc/self/exe").parent_path(); }

bool on_path(const std::string& program) {
  for (const char* dir : {"/usr/bin", "/usr/local/bin", "/usr/games"})
    if (std::filesystem::exists(std::filesystem::path(dir) / program)) return true;
  return false;
}

std::vector<render::Camera> cameras_from(const level::Level& level, const std::vector<render::CameraSpec>& specs) {
  std::vector<render::Camera> path;
  for (const auto& c : specs) path.push_back(render::camera_at(level, c.pos, c.angle, c.eye, c.fov));
  return path;
}

std::vector<render::Camera> random_cameras(const level::Level& level, int count, uint64_t seed) {
  Rng rng(seed);
  std::vector<render::Camera> out;
  for (int attempt = 0; int(out.size()) < count && attempt < count * 1000; ++attempt) {
    const geom::Vec2 p{rng.uniform(level.bounds.min.x, level.bounds.max.x), rng.uniform(level.bounds.min.y, level.bounds.max.y)};
    const int sector = level::sector_at_brute_force(level, p);  // inside a sector (Doom's rule gives one to any point)
    if (sector == level::kNone) continue;
    const level::Sector& s = level.sectors[size_t(sector)];
    if (s.ceiling - s.floor < 56) continue;  // not inside a closed door or a crusher
    out.push_back(render::camera_at(level, p, rng.uniform(0, 360)));
  }
  return out;
}

// The bsp renderer's ms/frame on the cameras at w x h, on one thread and on `cores`, interleaved camera
// by camera so that the machine's noise falls on both alike; medians. Each timed frame follows an
// untimed one of the same camera and renderer, as frames follow each other in a game or a timedemo:
// a pool worker asleep since the other renderer's frame (a wake-up costs tens of microseconds
// here) is woken by the untimed frame. keep_indices: a paletted level's frames stay
// 8-bit (Doom's screen before its blit), else they are resolved to colours.
std::pair<double, double> time_threads(const level::Level& level, const level::State& state,
                                       const std::vector<render::Camera>& cameras, int w, int h, int cores, int repeat,
                                       bool keep_indices) {
  auto one = render::make_renderer("bsp", {.threads = 1});
  auto all = render::make_renderer("bsp", {.threads = cores});
  render::Frame frame(w, h);
  frame.keep_indices = keep_indices;
  std::vector<double> ms1, msn;
  for (int pass = 0; pass < 1 + repeat; ++pass)
    for (const render::Camera& camera : cameras)
      for (auto [r, out] : {std::pair{one.get(), &ms1}, std::pair{all.get(), &msn}}) {
        r->render(level, state, camera, frame);
        const auto t0 = Clock::now();
        r->render(level, state, camera, frame);
        if (pass > 0) out->push_back(cli::seconds_since(t0) * 1000);  // pass 0 warms up
      }
  return {median(ms1), median(msn)};
}

}  // namespace p3d::bench
