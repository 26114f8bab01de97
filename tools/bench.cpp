// bench: the project's benchmark (Release builds). Prints markdown tables:
//   render      median ms/frame and fps per renderer along a fixed camera path
//   scaling     compile time and frame time as generated maps grow from 1k to 1M walls
//   grids       grid ray casting against open distance: mazes and open arenas
//   strategies  tree size, depth, build time and frame time per BSP strategy
//   hostile, capture, threads, wad, doom: see main's help and the README
//   play        Doom's rules: every monster awake on every Freedoom map, Doom's demos (bench_play.cpp)
// Timings are wall-clock medians; compare ratios within one run. --json writes the
// tables as JSON, --plots draws the scaling, threads and doom tables as SVG charts.
#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <functional>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdarg>
#include <cstdlib>
#include <fstream>
#include <map>
#include <thread>

#include "engine/bsp/build.h"
#include "engine/bsp/load.h"
#include "engine/play/demo.h"
#include "engine/play/world.h"
#include "engine/util/rng.h"
#include "engine/util/thread_pool.h"
#include <stb_image_write.h>
#include "engine/wad/write.h"
#include "engine/level/io.h"
#include "engine/map/generate.h"
#include "engine/render/camera_file.h"
#include "engine/render/renderer.h"
#include "engine/util/file.h"
#include "tools/cli.h"
#include "tools/bench_play.h"
#include "tools/bench_report.h"
#include "tools/plot_svg.h"

using namespace p3d;
using namespace p3d::bench;
using tools::BarChart;
using tools::LineChart;
using tools::LineSeries;
using Clock = std::chrono::steady_clock;

namespace {


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
int every_core(const Settings& s) { return s.threads > 0 ? s.threads : int(std::max(1u, std::thread::hardware_concurrency())); }

struct Timing {
  double median_ms = 0;
  size_t frames = 0;
  double nodes_visited = 0;  // mean per frame
  double pixels = 0;         // mean per frame
  double steps_per_ray = 0;  // mean (ray-based renderers)
};


Timing time_renderer(render::Renderer& r, const level::Level& level, const std::vector<render::Camera>& path,
                     const Settings& s) {
  render::Frame frame(s.width, s.height);
  std::vector<double> times;
  Timing t;
  r.prepare(level);  // acceleration structures are built outside the timing
  const auto start = Clock::now();
  const render::RenderStats first = r.render(level, path.front(), frame);  // warms up caches and scratch buffers
  if (cli::seconds_since(start) > s.budget_seconds) {  // too slow to repeat: that one frame is the measure
    t.frames = 1;
    t.median_ms = cli::seconds_since(start) * 1000;
    t.nodes_visited = double(first.nodes_visited);
    t.pixels = double(first.pixels_written);
    t.steps_per_ray = first.rays ? double(first.steps) / double(first.rays) : 0;
    return t;
  }
  for (const render::Camera& c : path) {
    for (int i = 0; i < s.repeat; ++i) {
      const auto t0 = Clock::now();
      const render::RenderStats st = r.render(level, c, frame);
      times.push_back(cli::seconds_since(t0) * 1000);
      t.nodes_visited += double(st.nodes_visited);
      t.pixels += double(st.pixels_written);
      t.steps_per_ray += st.rays ? double(st.steps) / double(st.rays) : 0;
    }
    if (cli::seconds_since(start) > s.budget_seconds) break;  // slow renderers: a prefix of the path
  }
  t.frames = times.size();
  t.median_ms = median(times);
  t.nodes_visited /= double(t.frames);
  t.pixels /= double(t.frames);
  t.steps_per_ray /= double(t.frames);
  return t;
}

std::vector<render::Camera> cameras_from(const level::Level& level, const std::vector<render::CameraSpec>& specs) {
  std::vector<render::Camera> path;
  for (const auto& c : specs) path.push_back(render::camera_at(level, c.pos, c.angle, c.eye, c.fov));
  return path;
}

// Turning on the spot at the player start: the same view at every map size.
std::vector<render::Camera> turn_around(const level::Level& level, int steps = 36) {
  std::vector<render::Camera> path;
  for (int i = 0; i < steps; ++i) path.push_back(render::camera_at(level, level.player_start, i * 360.0 / steps));
  return path;
}

std::vector<map::Texture> bundled_textures(const Settings& s) {
  std::vector<map::Texture> textures;
  for (const char* name : {"brick", "stone", "metal", "wood", "tech", "rock"})
    textures.push_back({name, image::load_png(std::filesystem::path(s.source_dir) / "maps/textures" / (std::string(name) + ".png")), {}});
  return textures;
}


std::string count_text(size_t n) {
  if (n >= 1000000 && n % 1000000 == 0) return std::to_string(n / 1000000) + "M";
  if (n >= 1000 && n % 1000 == 0) return std::to_string(n / 1000) + "k";
  return std::to_string(n);
}

std::vector<std::string> renderer_list(const Settings& s) {
  return s.renderers.empty() ? render::renderer_names() : s.renderers;
}

// ---- render ------------------------------------------------------------------

void bench_render(const Settings& s) {
  report.print("\n### Renderers, %dx%d, one thread\n\n", s.width, s.height);
  report.print("| map | walls | renderer | median ms/frame | fps | frames | nodes visited | pixels written / screen | "
              "steps / ray |\n");
  report.print("|---|---:|---|---:|---:|---:|---:|---:|---:|\n");
  struct Case {
    std::string name;
    level::Level level;
    std::vector<render::Camera> path;
  };
  std::vector<Case> cases;
  {
    const auto src = map::load_map(std::filesystem::path(s.source_dir) / "maps/outpost.map");
    level::Level level = bsp::build(src, {});
    auto path = cameras_from(level, render::read_camera_list(std::filesystem::path(s.source_dir) / "maps/outpost.path"));
    cases.push_back({"outpost (default)", std::move(level), std::move(path)});
  }
  {
    level::Level level = bsp::build(map::load_grid(std::filesystem::path(s.source_dir) / "maps/labyrinth.grid"), {});
    auto path = turn_around(level);
    cases.push_back({"labyrinth (grid 256x256)", std::move(level), std::move(path)});
  }
  for (const char* kind : {"rooms", "soup"}) {
    map::GenerateOptions o;
    o.walls = 100000;
    o.textures = bundled_textures(s);
    const auto src = std::string(kind) == "rooms" ? map::generate_rooms(o) : map::generate_soup(o);
    level::Level level = bsp::build(src, {});
    auto path = turn_around(level);
    cases.push_back({std::string(kind) + " 100k", std::move(level), std::move(path)});
  }
  for (const Case& c : cases)
    for (const std::string& name : renderer_list(s)) {
      auto r = render::make_renderer(name);
      if (!r || !r->supports(c.level)) continue;
      const Timing t = time_renderer(*r, c.level, c.path, s);
      report.print("| %s | %zu | %s | %s | %s | %zu | %s | %s | %s |\n", c.name.c_str(), c.level.walls.size(), name.c_str(),
                  fixed(t.median_ms, 3).c_str(), fixed(1000 / t.median_ms, 1).c_str(), t.frames,
                  fixed(t.nodes_visited, 0).c_str(), fixed(t.pixels / (s.width * s.height), 2).c_str(),
                  t.steps_per_ray > 0 ? fixed(t.steps_per_ray, 1).c_str() : "");
    }
}

// ---- scaling -----------------------------------------------------------------

void bench_scaling(const Settings& s) {
  const auto dir = std::filesystem::temp_directory_path() / ("p3d-bench-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  report.print("\n### Scaling: compile (as mapc does: parse + validate, build, write) and render the same view\n\n");
  report.print("| map | walls | parse + validate s | build s | write s | total s | fragments | depth max/mean |");
  for (const std::string& name : renderer_list(s)) report.print(" %s ms/frame |", name.c_str());
  report.print("\n|---|---:|---:|---:|---:|---:|---:|---:|");
  for (size_t i = 0; i < renderer_list(s).size(); ++i) report.print("---:|");
  report.print("\n");
  const auto textures = bundled_textures(s);
  std::map<std::string, double> last_ms;  // renderer -> ms/frame at the previous size of this kind
  std::vector<std::string> files;
  for (const auto& t : textures)
    files.push_back(std::filesystem::absolute(std::filesystem::path(s.source_dir) / "maps/textures" / (t.name + ".png")).string());
  for (const char* kind : {"rooms", "soup"})
    for (size_t walls : s.sizes) {
      if (walls == s.sizes.front()) last_ms.clear();
      map::GenerateOptions o;
      o.walls = walls;
      o.textures = textures;
      const auto path = dir / (std::string(kind) + ".map");
      {
        const auto generated = std::string(kind) == "rooms" ? map::generate_rooms(o) : map::generate_soup(o);
        write_file_atomically(path, map::to_map_text(generated, files));
      }
      const auto t0 = Clock::now();
      const map::Source src = map::load_map(path, {.textures_anywhere = true});  // its own scratch map
      const double parse = cli::seconds_since(t0);
      const auto t1 = Clock::now();
      bsp::Stats stats;
      const level::Level level = bsp::build(src, {}, &stats);
      const double build = cli::seconds_since(t1);
      const auto out = dir / (std::string(kind) + std::to_string(walls) + ".bsp");  // a new file: no unlink in the timing
      const auto t2 = Clock::now();
      level::write(level, out);
      const double write = cli::seconds_since(t2);
      std::filesystem::remove(out);
      report.print("| %s | %s | %s | %s | %s | %s | %zu | %zu / %s |", kind, count_text(src.walls.size()).c_str(),
                  fixed(parse, 3).c_str(), fixed(build, 3).c_str(), fixed(write, 3).c_str(),
                  fixed(parse + build + write, 3).c_str(), stats.fragments, stats.max_depth,
                  fixed(stats.mean_depth, 1).c_str());
      const auto cameras = turn_around(level);
      for (const std::string& name : renderer_list(s)) {
        auto r = render::make_renderer(name);
        if (!r || !r->supports(level)) {
          report.print(" n/a |");
          continue;
        }
        if (last_ms.count(name) && last_ms[name] > 5000) {  // over 5 s a frame already: the next size is 10x that
          report.print(" skipped |");
          continue;
        }
        last_ms[name] = time_renderer(*r, level, cameras, s).median_ms;
        report.print(" %s |", fixed(last_ms[name], 3).c_str());
      }
      report.print("\n");
    }
  std::filesystem::remove_all(dir);
}

// ---- grids -------------------------------------------------------------------

void bench_grids(const Settings& s) {
  const auto dir = std::filesystem::temp_directory_path() / ("p3d-bench-grid-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  report.print("\n### Grid ray casting and open distance (turning on the spot at the player start)\n\n");
  report.print("| grid | tiles | walls | dda ms/frame | dda cells / ray | bsp ms/frame | bsp nodes visited | sphere ms/frame | "
              "sphere steps / ray |\n");
  report.print("|---|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  map::GridOptions o;
  for (const char* name : {"brick", "stone", "metal", "wood", "tech", "tiles", "ceiling"})
    o.texture_files.push_back(
        std::filesystem::absolute(std::filesystem::path(s.source_dir) / "maps/textures" / (std::string(name) + ".png")).string());
  for (const char* kind : {"maze", "arena"})
    for (int side : {64, 256, 1024}) {
      o.kind = kind;
      o.cols = o.rows = side;
      write_file_atomically(dir / "g.grid", map::generate_grid_text(o));
      const level::Level level = bsp::build(map::load_grid(dir / "g.grid", {.textures_anywhere = true}), {});
      const auto cameras = turn_around(level);
      const Timing dda = time_renderer(*render::make_renderer("dda"), level, cameras, s);
      const Timing bsp = time_renderer(*render::make_renderer("bsp"), level, cameras, s);
      const Timing sphere = time_renderer(*render::make_renderer("sphere"), level, cameras, s);
      report.print("| %s | %dx%d | %zu | %s | %s | %s | %s | %s | %s |\n", kind, side, side, level.walls.size(),
                  fixed(dda.median_ms, 3).c_str(), fixed(dda.steps_per_ray, 1).c_str(), fixed(bsp.median_ms, 3).c_str(),
                  fixed(bsp.nodes_visited, 0).c_str(), fixed(sphere.median_ms, 3).c_str(),
                  fixed(sphere.steps_per_ray, 1).c_str());
    }
  std::filesystem::remove_all(dir);
}

// ---- strategies --------------------------------------------------------------

void bench_strategies(const Settings& s) {
  report.print("\n### BSP strategies (seed 1; bsp renderer on each map's path)\n\n");
  report.print("| map | strategy | fragments | splits | fragments / (n + 2n ln n) | depth max/mean | build ms | "
              "bsp ms/frame | nodes visited |\n");
  report.print("|---|---|---:|---:|---:|---:|---:|---:|---:|\n");
  struct Case {
    std::string name;
    map::Source src;
    std::vector<render::CameraSpec> path;
  };
  std::vector<Case> cases;
  cases.push_back({"outpost", map::load_map(std::filesystem::path(s.source_dir) / "maps/outpost.map"),
                   render::read_camera_list(std::filesystem::path(s.source_dir) / "maps/outpost.path")});
  cases.push_back({"labyrinth", map::load_grid(std::filesystem::path(s.source_dir) / "maps/labyrinth.grid"), {}});
  for (const char* kind : {"rooms", "soup"}) {
    map::GenerateOptions o;
    o.walls = 10000;
    o.textures = bundled_textures(s);
    cases.push_back({std::string(kind) + " 10k", std::string(kind) == "rooms" ? map::generate_rooms(o) : map::generate_soup(o), {}});
  }
  for (const Case& c : cases)
    for (bsp::Strategy strategy : {bsp::Strategy::kFirst, bsp::Strategy::kRandom, bsp::Strategy::kFreeSplit, bsp::Strategy::kGreedy}) {
      bsp::Options o;
      o.strategy = strategy;
      bsp::Stats stats;
      const auto t0 = Clock::now();
      const level::Level level = bsp::build(c.src, o, &stats);
      const double build_ms = cli::seconds_since(t0) * 1000;
      const auto path = c.path.empty() ? turn_around(level) : cameras_from(level, c.path);
      auto r = render::make_renderer("bsp");
      const Timing t = time_renderer(*r, level, path, s);
      report.print("| %s | %s | %zu | %zu | %s | %zu / %s | %s | %s | %s |\n", c.name.c_str(), bsp::strategy_name(strategy),
                  stats.fragments, stats.splits, fixed(stats.fragments / stats.random_bound(), 3).c_str(), stats.max_depth,
                  fixed(stats.mean_depth, 1).c_str(), fixed(build_ms, 1).c_str(), fixed(t.median_ms, 3).c_str(),
                  fixed(t.nodes_visited, 0).c_str());
    }
}

// ---- wad: every map of WADs compiled beside ZDBSP, and rendered ---------------

// Runs a program with its output discarded: its wall time, peak memory and exit status.
struct Measured {
  double seconds = 0;
  double cpu_seconds = 0;  // user + system
  double peak_mb = 0;
  int status = 0;
};
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

// A child's wall time; it must succeed.
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

// ZDBSP's nodes for one map: segs, subsectors (as our leaves) and their mean depth.
struct PeerTree {
  size_t segs = 0, subsectors = 0;
  double mean_depth = 0;
};
PeerTree read_peer_tree(const std::filesystem::path& wad_path, const std::string& map) {
  const wad::Wad w(read_file_bytes(wad_path), wad_path.string());
  wad::Stack stack;
  stack.add(w);
  const auto lumps = stack.map(map);
  const wad::Lump *segs = lumps ? lumps->find("SEGS") : nullptr, *nodes = lumps ? lumps->find("NODES") : nullptr;
  if (!segs || !nodes || nodes->bytes.size() % 28) throw Error(wad_path.string() + ": no vanilla nodes for " + map);
  PeerTree t;
  t.segs = segs->bytes.size() / 12;
  const size_t n = nodes->bytes.size() / 28;
  auto child = [&](size_t node, int k) {
    const size_t at = node * 28 + 24 + 2 * size_t(k);
    return uint16_t(nodes->bytes[at] | nodes->bytes[at + 1] << 8);
  };
  size_t leaves = 0, depth_sum = 0;
  std::vector<std::pair<size_t, size_t>> stack_nodes{{n - 1, 1}};  // the root is the last node
  while (!stack_nodes.empty()) {
    const auto [node, depth] = stack_nodes.back();
    stack_nodes.pop_back();
    for (int k = 0; k < 2; ++k) {
      const uint16_t c = child(node, k);
      if (c & 0x8000) {
        ++leaves, depth_sum += depth;
      } else if (c < n) {
        stack_nodes.push_back({c, depth + 1});
      }
    }
  }
  t.subsectors = leaves;
  t.mean_depth = leaves ? double(depth_sum) / double(leaves) : 0;
  return t;
}

// The bsp renderer with every thing drawn and with none, camera by camera in turn
// (interleaved, so the machine's noise falls on both alike): the median with things,
// and the cost of things as a paired ratio: each camera's fastest render with things,
// summed, over the same without.
struct SpriteCost {
  double with_things_ms = 0, without_things_ms = 0, ratio = 0, sprites = 0;
};
SpriteCost time_sprites(const level::Level& level, const std::vector<render::Camera>& cameras, int skill,
                        const Settings& s) {
  const level::State with = level::start_state(level, skill);
  level::State without = with;
  without.things.clear();
  auto r = render::make_renderer("bsp");
  render::Frame frame(s.width, s.height);
  std::vector<double> a, b;
  SpriteCost cost;
  double fastest_with = 0, fastest_without = 0;
  r->render(level, with, cameras.front(), frame);  // warm-up
  for (const render::Camera& c : cameras) {
    double best_a = INFINITY, best_b = INFINITY;
    for (int i = 0; i < s.repeat; ++i) {
      auto t0 = Clock::now();
      cost.sprites += double(r->render(level, with, c, frame).sprites_drawn);
      a.push_back(cli::seconds_since(t0) * 1000);
      t0 = Clock::now();
      r->render(level, without, c, frame);
      b.push_back(cli::seconds_since(t0) * 1000);
      best_a = std::min(best_a, a.back()), best_b = std::min(best_b, b.back());
    }
    fastest_with += best_a, fastest_without += best_b;
  }
  cost.with_things_ms = median(a);
  cost.without_things_ms = median(b);
  cost.ratio = fastest_with / fastest_without;
  cost.sprites /= double(a.size());
  return cost;
}

// Cameras at random points inside sectors, looking anywhere, eye 41 above the floor.
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
                                       bool keep_indices = false) {
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

// Every map of a WAD at once: `pseudo3d-mapc --all` beside ZDBSP rebuilding the
// whole WAD's nodes, whole processes, interleaved, median of `runs`.
void bench_whole_wad(const std::filesystem::path& wad, const std::string& mapc, bool zdbsp,
                     const std::filesystem::path& dir, int runs) {
  const std::vector<std::string> ours = {mapc, "--iwad", wad.string(), "--all", "-o", (dir / "all").string()};
  const std::vector<std::string> peer = {"zdbsp", "-o", (dir / "all.wad").string(), wad.string()};
  std::vector<double> ours_s, ours_cpu, peer_s, peer_cpu;
  for (int r = 0; r < runs; ++r) {
    const Measured o = run_measured(ours);
    if (o.status != 0) throw Error(mapc + " --all failed (" + wad.string() + ")");
    ours_s.push_back(o.seconds), ours_cpu.push_back(o.cpu_seconds);
    if (!zdbsp) continue;
    const Measured p = run_measured(peer);
    if (p.status != 0) throw Error("zdbsp failed (" + wad.string() + ")");
    peer_s.push_back(p.seconds), peer_cpu.push_back(p.cpu_seconds);
  }
  const auto peer_cell = [&](double v, int digits) { return zdbsp ? fixed(v, digits) : std::string("n/a"); };
  report.print("\n#### %s: the whole WAD at once (`pseudo3d-mapc --all` beside ZDBSP rebuilding every map's nodes)\n\n",
               wad.filename().c_str());
  report.print("| WAD | mapc --all s | CPU s | zdbsp s | CPU s | mapc / zdbsp | CPU: mapc / zdbsp |\n|---|---:|---:|---:|---:|---:|---:|\n");
  const double os = median(ours_s), oc = median(ours_cpu), ps = zdbsp ? median(peer_s) : 0, pc = zdbsp ? median(peer_cpu) : 0;
  report.print("| %s | %s | %s | %s | %s | %s | %s |\n", wad.filename().c_str(), fixed(os, 2).c_str(), fixed(oc, 2).c_str(),
               peer_cell(ps, 2).c_str(), peer_cell(pc, 2).c_str(), peer_cell(os / ps, 2).c_str(), peer_cell(oc / pc, 2).c_str());
}

void bench_wad(const Settings& s) {
  const bsp::LevelSource source = cli::level_source(s.wads);
  const wad::Stack wads = bsp::read_wads(source.wads);
  const std::vector<std::string> maps = s.wads.map.empty() ? wads.map_names() : std::vector<std::string>{wad::normalize_name(s.wads.map)};
  const bool zdbsp = on_path("zdbsp");
  const auto dir = std::filesystem::temp_directory_path() / ("p3d-bench-wad-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string mapc = (own_directory() / "pseudo3d-mapc").string();
  report.print("\n### %s: every map compiled (whole process, median of %d) beside ZDBSP, and rendered\n\n",
              source.wads.back().filename().c_str(), s.runs);
  const int cores = every_core(s);
  report.print("| map | lines | mapc ms | zdbsp ms | mapc / zdbsp | segs (2-sided x2) | zdbsp segs | segs / zdbsp | "
              "leaves | zdbsp subsectors | leaves / zdbsp | mean depth | zdbsp mean depth | depth / zdbsp | "
              "bsp ms/frame %dx%d | fps | sprites / frame | without things ms | with / without | "
              "%d threads ms | 1920x1080, %d threads ms |\n",
              s.width, s.height, cores, cores);
  report.print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  std::vector<double> time_ratios, seg_ratios, leaf_ratios, depth_ratios, frame_ms, sprite_ratios, threads_ms, hd_ms;
  for (const std::string& map : maps) {
    bsp::Stats stats;
    const level::Level level = bsp::build_wad_map(wads, map, {}, nullptr, &stats);
    size_t segs = 0;
    for (const level::Fragment& f : level.fragments) segs += level.walls[f.wall].two_sided() ? 2 : 1;

    std::vector<std::string> ours = {mapc, "--iwad", source.wads.front().string()};
    for (size_t i = 1; i < source.wads.size(); ++i) ours.insert(ours.end(), {"--file", source.wads[i].string()});
    ours.insert(ours.end(), {"--map", map, "-o", (dir / "out.bsp").string()});
    const auto single = dir / "single.wad", built = dir / "built.wad";
    write_file_atomically(single, wad::map_without_nodes(*wads.map(map)));
    const std::vector<std::string> peer = {"zdbsp", "-o", built.string(), single.string()};
    std::vector<double> ours_s, peer_s;
    for (int r = 0; r < s.runs; ++r) {  // interleaved: the machine's noise hits both alike
      ours_s.push_back(run_process(ours));
      if (zdbsp) peer_s.push_back(run_process(peer));
    }
    const double ours_ms = median(ours_s) * 1000, peer_ms = zdbsp ? median(peer_s) * 1000 : 0;
    const PeerTree tree = zdbsp ? read_peer_tree(built, map) : PeerTree{};

    const auto cameras = random_cameras(level, s.cameras, 1);
    const SpriteCost t = time_sprites(level, cameras, s.skill, s);
    frame_ms.push_back(t.with_things_ms);
    sprite_ratios.push_back(t.ratio);
    const level::State state = level::start_state(level, s.skill);  // things drawn, as t.with_things_ms
    threads_ms.push_back(time_threads(level, state, cameras, s.width, s.height, cores, s.repeat).second);
    hd_ms.push_back(time_threads(level, state, cameras, 1920, 1080, cores, s.repeat).second);
    if (zdbsp) {
      time_ratios.push_back(ours_ms / peer_ms), seg_ratios.push_back(double(segs) / double(tree.segs));
      leaf_ratios.push_back(double(stats.leaves) / double(tree.subsectors));
      depth_ratios.push_back(stats.mean_depth / tree.mean_depth);
    }
    const auto peer_cell = [&](const std::string& text) { return zdbsp ? text : std::string("n/a"); };
    report.print("| %s | %zu | %s | %s | %s | %zu | %s | %s | %zu | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n",
                map.c_str(), stats.walls, fixed(ours_ms, 1).c_str(), peer_cell(fixed(peer_ms, 1)).c_str(),
                peer_cell(fixed(ours_ms / peer_ms, 2)).c_str(), segs, peer_cell(std::to_string(tree.segs)).c_str(),
                peer_cell(fixed(double(segs) / double(tree.segs), 3)).c_str(), stats.leaves,
                peer_cell(std::to_string(tree.subsectors)).c_str(),
                peer_cell(fixed(double(stats.leaves) / double(tree.subsectors), 3)).c_str(), fixed(stats.mean_depth, 2).c_str(),
                peer_cell(fixed(tree.mean_depth, 2)).c_str(), peer_cell(fixed(stats.mean_depth / tree.mean_depth, 3)).c_str(),
                fixed(t.with_things_ms, 3).c_str(),
                fixed(1000 / t.with_things_ms, 0).c_str(), fixed(t.sprites, 1).c_str(),
                fixed(t.without_things_ms, 3).c_str(), fixed(t.ratio, 2).c_str(), fixed(threads_ms.back(), 3).c_str(),
                fixed(hd_ms.back(), 3).c_str());
    std::fflush(stdout);
  }
  const auto peer_mean = [&](const std::vector<double>& v) { return zdbsp ? fixed(geomean(v), 3) : std::string("n/a"); };
  report.print("| geomean | | | | %s | | | %s | | | %s | | | %s | %s | | | | %s | %s | %s |\n",
              zdbsp ? fixed(geomean(time_ratios), 2).c_str() : "n/a", peer_mean(seg_ratios).c_str(),
              peer_mean(leaf_ratios).c_str(), peer_mean(depth_ratios).c_str(), fixed(geomean(frame_ms), 3).c_str(),
              fixed(geomean(sprite_ratios), 2).c_str(), fixed(geomean(threads_ms), 3).c_str(), fixed(geomean(hd_ms), 3).c_str());
  if (zdbsp && !maps.empty()) {
    const auto worst = [](const std::vector<double>& v) { return fixed(*std::max_element(v.begin(), v.end()), 3); };
    report.print("| worst map | | | | | | | %s | | | %s | | | %s | | | | | | | |\n", worst(seg_ratios).c_str(),
                worst(leaf_ratios).c_str(), worst(depth_ratios).c_str());
  }
  if (s.wads.map.empty() && source.wads.size() == 1) bench_whole_wad(source.wads.front(), mapc, zdbsp, dir, s.runs);
  std::filesystem::remove_all(dir);
}

// ---- hostile ------------------------------------------------------------------

// Levels built to defeat a compiler: convex sectors of 100,000 and 1,000,000 walls (a
// chain of depth n for a splitter choice that peels one wall at a time), 60,000 and
// 200,000 walls meeting at one point (every pair in one cell of a uniform grid),
// 100,000 near-parallel slivers (every pair in a few cells), mapgen's shapes of 100,000
// walls on the 1/256 grid (nearly convex rooms, where every wall's line peels a few
// walls off: circles, ellipses, jittered circles; stars, fans, spirals, combs, nested
// rings), generated rooms and soups of 1,000,000 walls, and the largest tile maps (a
// 4096x4096 maze has more walls than a level may have). With --beside, another mapc
// compiles each level just before this one.
std::string circle_text(int n, int64_t radius, bool fan) {
  std::string text = "texture brick brick.png\n";
  if (fan) text += "vertex c 0 0\n";
  else text += "sector room floor=0 ceiling=128 floor_tex=brick ceiling_tex=brick\n";
  std::vector<std::pair<int64_t, int64_t>> points;
  for (int i = 0; i < n; ++i) {
    const double a = (fan ? 2 : -2) * M_PI * i / n;  // a sector's walls run clockwise
    const std::pair<int64_t, int64_t> p{std::llround(double(radius) * std::cos(a)), std::llround(double(radius) * std::sin(a))};
    if (points.empty() || p != points.back()) points.push_back(p);
  }
  if (points.size() > 1 && points.front() == points.back()) points.pop_back();
  for (size_t i = 0; i < points.size(); ++i)
    text += "vertex p" + std::to_string(i) + " " + std::to_string(points[i].first) + " " + std::to_string(points[i].second) + "\n";
  for (size_t i = 0; i < points.size(); ++i)
    text += fan ? "segment c p" + std::to_string(i) + " texture=brick\n"
                : "wall p" + std::to_string(i) + " p" + std::to_string((i + 1) % points.size()) + " front=room middle=brick\n";
  return text + (fan ? "player " + std::to_string(radius / 3) + " 7 0\n" : "player 0 0 0\n");
}

std::string slivers_text(int n) {
  std::string text = "texture brick brick.png\n";
  for (int i = 0; i < n; ++i)
    text += "vertex a" + std::to_string(i) + " 0 " + std::to_string(4 * i) + "\nvertex b" + std::to_string(i) + " 100000 " +
            std::to_string(4 * i + 1) + "\nsegment a" + std::to_string(i) + " b" + std::to_string(i) + " texture=brick\n";
  return text + "player -50 -50 0\n";
}

// The max_depth and mean_depth a mapc --json file reports ("" when absent).
std::string depth_from_json(const std::filesystem::path& json) {
  if (!std::filesystem::exists(json)) return "";
  const std::string text = read_file_text(json);
  auto field = [&](const std::string& name) {
    const size_t at = text.find("\"" + name + "\": ");
    return at == std::string::npos ? -1.0 : std::atof(text.c_str() + at + name.size() + 4);
  };
  const double max_depth = field("max_depth"), mean_depth = field("mean_depth");
  return max_depth < 0 ? "" : fixed(max_depth, 0) + "/" + fixed(mean_depth, 1);
}

void bench_hostile(const Settings& s) {
  const auto dir = std::filesystem::temp_directory_path() / ("p3d-bench-hostile-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const auto textures = std::filesystem::path(s.source_dir) / "maps/textures";
  for (const char* name : {"brick", "stone", "metal", "wood", "tech", "tiles", "ceiling", "rock"})
    write_file_atomically(dir / (std::string(name) + ".png"), read_file_bytes(textures / (std::string(name) + ".png")));
  const bool beside = !s.beside_mapc.empty();
  report.print("\n### Hostile levels: mapc's time and memory (whole process)\n\n");
  report.print("| level | walls | outcome | seconds | CPU seconds | peak MB | bytes per wall | depth (max/mean) |%s\n"
               "|---|---:|---|---:|---:|---:|---:|---:|%s\n",
               beside ? " beside: CPU seconds | beside: peak MB | beside: depth |" : "", beside ? "---:|---:|---:|" : "");
  // Each level's text is made just before its compile, so that bench stays small when
  // it forks (see run_measured); an empty text: the file is written already.
  struct Case {
    std::string name, file;
    size_t walls;
    std::function<std::string()> text;
  };
  std::vector<Case> cases = {
      {"convex sector of 100,000 walls", "convex.map", 100000, [] { return circle_text(100000, 400000, false); }},
      {"convex sector of 1,000,000 walls", "convex1m.map", 1000000, [] { return circle_text(1000000, 2000000, false); }},
      {"60,000 walls meeting at one point", "star.map", 60000, [] { return circle_text(60000, 1000000, true); }},
      {"fan of 200,000 walls", "fan.map", 200000, [] { return circle_text(200000, 1000000, true); }},
      {"100,000 near-parallel slivers", "slivers.map", 100000, [] { return slivers_text(100000); }},
  };
  // Generated by mapgen, in its own process: bench stays small (see run_measured).
  const std::string mapgen = (own_directory() / "pseudo3d-mapgen").string();
  for (const std::string& kind : map::shape_kinds()) {
    const std::string file = "shape-" + kind + ".map";
    run_process({mapgen, kind, "--walls", "100000", "-o", (dir / file).string()});
    cases.push_back({kind + " of 100,000 walls on the 1/256 grid", file, 100000, nullptr});
  }
  for (const char* kind : {"rooms", "soup"}) {
    const std::string file = std::string(kind) + ".map";
    run_process({mapgen, kind, "--walls", "1000000", "-o", (dir / file).string()});
    cases.push_back({std::string(kind) + " of 1,000,000 walls", file, 1000000, nullptr});
  }
  map::GridOptions o;
  for (const char* name : {"brick", "stone", "metal", "wood", "tech", "tiles", "ceiling"}) o.texture_files.push_back(std::string(name) + ".png");
  o.cols = o.rows = limits::kMaxGridSide;
  for (const char* kind : {"maze", "arena"}) {
    o.kind = kind;
    cases.push_back({std::string(kind) + " of 4096x4096 tiles", std::string(kind) + ".grid", 0, [o] { return map::generate_grid_text(o); }});
  }
  const std::string mapc = (own_directory() / "pseudo3d-mapc").string();
  for (Case& c : cases) {
    if (c.text) write_file_atomically(dir / c.file, c.text());
    // The other compiler first, then this one: the machine's load falls on both alike.
    Measured other;
    std::string other_depth;
    if (beside) {
      other = run_measured({s.beside_mapc, (dir / c.file).string(), "-o", (dir / "out.bsp").string(), "--stats", "--json", (dir / "out.json").string()});
      other_depth = depth_from_json(dir / "out.json");
      std::filesystem::remove(dir / "out.json");
      std::filesystem::remove(dir / "out.bsp");
    }
    const Measured m = run_measured({mapc, (dir / c.file).string(), "-o", (dir / "out.bsp").string(), "--stats", "--json", (dir / "out.json").string()});
    std::string walls = c.walls ? std::to_string(c.walls) : "";
    if (m.status == 0) walls = std::to_string(level::read(dir / "out.bsp").walls.size());
    const double wall_count = walls.empty() ? 1.0 : std::stod(walls);
    const std::string other_cells = !beside ? ""
                                    : " " + (other.status == 0 ? fixed(other.cpu_seconds, 2) : "refused") + " | " +
                                          fixed(other.peak_mb, 0) + " | " + other_depth + " |";
    report.print("| %s | %s | %s | %s | %s | %s | %s | %s |%s\n", c.name.c_str(), walls.c_str(),
                 m.status == 0 ? "compiled" : ("refused (exit " + std::to_string(m.status) + ")").c_str(),
                 fixed(m.seconds, 2).c_str(), fixed(m.cpu_seconds, 2).c_str(), fixed(m.peak_mb, 0).c_str(),
                 walls.empty() ? "" : fixed(m.peak_mb * 1048576 / wall_count, 0).c_str(), depth_from_json(dir / "out.json").c_str(),
                 other_cells.c_str());
    std::filesystem::remove(dir / "out.bsp");
    std::filesystem::remove(dir / "out.json");
    std::fflush(stdout);
  }
  std::filesystem::remove_all(dir);
}

// ---- threads ------------------------------------------------------------------

// The BSP renderer's column strips on one thread and on every core, at four
// resolutions from 320x200 to 1920x1080, on the outpost path and (when Freedoom is
// installed) random views of freedoom2 MAP01 with its things; and what one dispatch to
// the pool costs.
void bench_threads(const Settings& s) {
  const int cores = int(std::max(1u, std::thread::hardware_concurrency()));
  report.print("\n### Threads: the BSP renderer's column strips on %d core%s\n\n", cores, cores == 1 ? "" : "s");
  report.print("| map | size | 1 thread ms/frame | %d threads ms/frame | speed-up |\n|---|---|---:|---:|---:|\n", cores);
  struct Case {
    std::string name;
    level::Level level;
    std::vector<render::Camera> path;
  };
  std::vector<Case> cases;
  const auto maps = std::filesystem::path(s.source_dir) / "maps";
  {
    level::Level level = bsp::build(map::load_map(maps / "outpost.map"), {});
    auto path = cameras_from(level, render::read_camera_list(maps / "outpost.path"));
    cases.push_back({"outpost", std::move(level), std::move(path)});
  }
  const std::filesystem::path freedoom = "/usr/share/games/doom/freedoom2.wad";
  if (std::filesystem::exists(freedoom)) {
    level::Level level = bsp::build_wad_map(bsp::read_wads({freedoom}), "MAP01", {}, nullptr);
    auto path = random_cameras(level, 100, 1);
    cases.push_back({"freedoom2 MAP01", std::move(level), std::move(path)});
  }
  for (const Case& c : cases)
    for (const auto& [w, h] : {std::pair{320, 200}, std::pair{640, 400}, std::pair{1280, 800}, std::pair{1920, 1080}}) {
      const auto [t1, tn] = time_threads(c.level, level::start_state(c.level), c.path, w, h, cores, s.repeat);
      report.print("| %s | %dx%d | %s | %s | %s |\n", c.name.c_str(), w, h, fixed(t1, 3).c_str(), fixed(tn, 3).c_str(),
                   fixed(t1 / tn, 2).c_str());
    }
  ThreadPool pool(cores);
  std::vector<double> us;
  std::atomic<int> sink{0};
  for (int i = 0; i < 2000; ++i) {
    const auto t0 = Clock::now();
    pool.run(8, [&](int task) { sink += task; });
    us.push_back(cli::seconds_since(t0) * 1e6);
  }
  report.print("\nA dispatch of 8 empty strips to the pool: median %s us.\n", fixed(median(us), 1).c_str());
}

// ---- doom: beside Crispy Doom ---------------------------------------------------

// The map a demo lump plays: its header holds skill, episode and map (after a version
// byte since Doom 1.4).
std::string demo_map(const wad::Lump& demo, bool numbered_maps) {
  const std::span<const uint8_t> d = demo.bytes;
  const size_t at = !d.empty() && d[0] >= 104 ? 2 : 1;
  if (d.size() < at + 2) throw Error(demo.name + ": not a demo");
  char name[16];
  if (numbered_maps) std::snprintf(name, sizeof name, "MAP%02d", d[at + 1]);
  else std::snprintf(name, sizeof name, "E%dM%d", d[at], d[at + 1]);
  return name;
}

// Crispy Doom's render-only ms/frame on a demo (a lump of the IWAD or a .lmp file), by
// tools/peers/doom_render_ms.py; 0 when it cannot run.
double crispy_ms(const Settings& s, const std::filesystem::path& iwad, const std::string& demo) {
  static std::map<std::string, double> measured;  // each demo once per run, for both tables
  const std::string key = iwad.string() + ":" + demo;
  if (const auto it = measured.find(key); it != measured.end()) return it->second;
  double& ms = measured[key];
  const auto script = std::filesystem::path(s.source_dir) / "tools" / "peers" / "doom_render_ms.py";
  const std::string command = "python3 '" + script.string() + "' --port crispy --iwad '" + iwad.string() + "' --demo '" +
                              demo + "' --res 640 --reps " + std::to_string(s.peer_reps) + " 2>/dev/null";
  FILE* pipe = ::popen(command.c_str(), "r");
  if (!pipe) return 0;
  std::string out;
  char buffer[256];
  while (std::fgets(buffer, sizeof buffer, pipe)) out += buffer;
  if (::pclose(pipe) != 0) return 0;
  const size_t at = out.find("render_ms_per_frame=");
  return ms = at == std::string::npos ? 0 : std::atof(out.c_str() + at + 20);
}

// The demo replayed by Doom's rules (the same path as Crispy's -timedemo, tic for tic),
// each tic's view rendered as Crispy draws it above its status bar (640x336, 8-bit):
// the mean ms/frame on one thread and on `cores`. Each pass replays the whole demo on
// one thread count, so each frame follows the tic before's as in Crispy's timedemo; the
// median of `passes` passes for each count, the counts taking turns.
std::pair<double, double> time_demo_views(const wad::Stack& wads, const level::Level& level, const std::string& map,
                                          const play::DoomDemo& doom, int cores, int passes) {
  play::GameOptions o = play::game_options_for(wads, map, doom.skill);
  o.fast = doom.fast, o.respawn = doom.respawn, o.no_monsters = doom.no_monsters;
  const play::Demo demo = play::demo_from_doom(doom, level);
  auto mean_ms = [&](int threads) {
    play::World world(play::map_from_wads(wads, map, level), level, o, play::Random{});
    auto renderer = render::make_renderer("bsp", {.threads = threads});
    render::Frame frame(640, 336);
    frame.keep_indices = true;
    double ms = 0;
    for (const play::DemoTic& t : demo.tics) {
      world.tick(t.cmd);
      const play::Mobj& mo = *world.player().mo;
      const render::Camera camera{{play::to_double(mo.x), play::to_double(mo.y)},
                                  play::to_double(world.player().view_z), double(mo.angle) * (360.0 / 4294967296.0), 90};
      const auto t0 = Clock::now();
      renderer->render(level, world.state(), camera, frame);
      ms += cli::seconds_since(t0) * 1000;
    }
    return ms / double(std::max<size_t>(1, demo.tics.size()));
  };
  std::vector<double> one, all;
  for (int pass = 0; pass < passes; ++pass) one.push_back(mean_ms(1)), all.push_back(mean_ms(cores));
  return {median(one), median(all)};
}

// A demo that stands at the map's start and turns in place, left, by Doom's smallest
// turn a tic (1/256 of a turn): a full turn in 256 tics, each tic a new view.
play::DoomDemo turn_in_place(const std::string& map) {
  play::DoomDemo demo;
  if (std::sscanf(map.c_str(), "MAP%d", &demo.map) != 1 && std::sscanf(map.c_str(), "E%dM%d", &demo.episode, &demo.map) != 2)
    throw Error(map + ": not a map name");
  demo.commands.assign(256, play::DoomTic{.turn = 256});
  return demo;
}

// Maps viewed from their start turning in place (Freedoom's E1M1, MAP01, MAP02, MAP10
// and MAP15; with --iwad, its --map or first map): Crispy Doom's render-only time on
// that demo beside ours on the same views.
void bench_doom_start_views(const Settings& s, int cores, bool crispy) {
  const std::filesystem::path games = "/usr/share/games/doom";
  std::vector<std::pair<std::filesystem::path, std::string>> maps = {
      {games / "freedoom1.wad", "E1M1"}, {games / "freedoom2.wad", "MAP01"}, {games / "freedoom2.wad", "MAP02"},
      {games / "freedoom2.wad", "MAP10"}, {games / "freedoom2.wad", "MAP15"}};
  if (!s.wads.iwad.empty()) maps = {{s.wads.iwad, bsp::resolve_map_name(bsp::read_wads({s.wads.iwad}), s.wads.map)}};
  report.print("\n### Beside Crispy Doom at each map's start: render-only ms/frame, turning in place\n\n");
  report.print("Both engines play a demo that stands at the player start and turns left by 1/256 of a turn a tic\n"
               "(256 views), measured as in the table below.\n\n");
  report.print("| iwad | map | tics | Crispy 640x400 | ours, 1 thread | ÷ Crispy | ours, %d threads | ÷ Crispy |\n"
               "|---|---|---:|---:|---:|---:|---:|---:|\n", cores);
  const auto dir = std::filesystem::temp_directory_path() / ("p3d-bench-doom-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  std::vector<double> ratio1, ration;
  for (const auto& [iwad, map] : maps) {
    if (!std::filesystem::exists(iwad)) continue;
    const wad::Stack wads = bsp::read_wads({iwad});
    if (!wads.map(map)) continue;
    const play::DoomDemo demo = turn_in_place(map);
    const auto file = dir / ("turn" + map + ".lmp");  // Doom names the demo's lump after the file
    write_file_atomically(file, play::encode_doom_demo(demo));
    const level::Level level = bsp::build_wad_map(wads, map, {}, nullptr);
    const double peer = crispy ? crispy_ms(s, iwad, file.string()) : 0;
    const auto [one, all] = time_demo_views(wads, level, map, demo, cores, s.repeat);
    if (peer > 0) ratio1.push_back(one / peer), ration.push_back(all / peer);
    report.print("| %s | %s | %zu | %s | %s | %s | %s | %s |\n", iwad.filename().c_str(), map.c_str(), demo.tic_count(),
                 peer > 0 ? fixed(peer, 3).c_str() : "n/a", fixed(one, 3).c_str(),
                 peer > 0 ? fixed(one / peer, 2).c_str() : "n/a", fixed(all, 3).c_str(),
                 peer > 0 ? fixed(all / peer, 2).c_str() : "n/a");
    std::fflush(stdout);
  }
  std::filesystem::remove_all(dir);
  report.print("| geomean | | | | | %s | | %s |\n", ratio1.empty() ? "n/a" : fixed(geomean(ratio1), 2).c_str(),
               ration.empty() ? "n/a" : fixed(geomean(ration), 2).c_str());
}

// For every demo of the IWADs (Freedoom's eight by default), the map it plays: Crispy
// Doom's render time on the demo beside ours on the same views (the demo replayed by
// Doom's rules); then ours on random cameras inside the map, at 640x400 on one thread
// and on every core, and at 1920x1080.
void bench_doom(const Settings& s) {
  const int cores = every_core(s);
  std::vector<std::filesystem::path> iwads;
  if (!s.wads.iwad.empty()) iwads.push_back(s.wads.iwad);
  else
    for (const char* name : {"freedoom1.wad", "freedoom2.wad"})
      if (std::filesystem::exists(std::filesystem::path("/usr/share/games/doom") / name))
        iwads.push_back(std::filesystem::path("/usr/share/games/doom") / name);
  if (iwads.empty()) return report.print("\n### Beside Crispy Doom: no IWAD (apt-get install freedoom, or --iwad)\n");
  const bool crispy = s.peer_reps > 0 && on_path("crispy-doom");
  bench_doom_start_views(s, cores, crispy);
  if (!s.wads.map.empty()) return;  // one map's start: the demos play others
  report.print("\n### Beside Crispy Doom on the same views: render-only ms/frame along each demo\n\n");
  report.print("Both engines play the demo (ours by Doom's rules, in sync with Doom) and draw every tic's view, 640x400\n"
               "hires: Crispy's render-only time (its -timedemo drawn without blit, less the game without drawing), ours\n"
               "the mean of every tic's view above the status bar (640x336) in Doom's 8-bit screen.\n\n");
  report.print("| iwad | demo | map | tics | Crispy 640x400 | ours, 1 thread | ÷ Crispy | ours, %d threads | ÷ Crispy |\n"
               "|---|---|---|---:|---:|---:|---:|---:|---:|\n", cores);
  std::vector<double> same1, samen;
  for (const auto& iwad : iwads) {
    const wad::Stack wads = bsp::read_wads({iwad});
    const bool numbered = wads.map("MAP01").has_value();
    for (int n = 1; n <= 4; ++n) {
      const std::string demo = "demo" + std::to_string(n);
      const wad::Lump* lump = wads.find(demo);
      if (!lump) continue;
      const std::string map = demo_map(*lump, numbered);
      if (!wads.map(map)) continue;
      const play::DoomDemo doom = play::decode_doom_demo(lump->bytes, demo);
      const level::Level level = bsp::build_wad_map(wads, map, {}, nullptr);
      const double peer = crispy ? crispy_ms(s, iwad, demo) : 0;
      const auto [one, all] = time_demo_views(wads, level, map, doom, cores, s.repeat);
      if (peer > 0) same1.push_back(one / peer), samen.push_back(all / peer);
      report.print("| %s | %s | %s | %zu | %s | %s | %s | %s | %s |\n", iwad.filename().c_str(), demo.c_str(), map.c_str(),
                   doom.tic_count(), peer > 0 ? fixed(peer, 3).c_str() : "n/a", fixed(one, 3).c_str(),
                   peer > 0 ? fixed(one / peer, 2).c_str() : "n/a", fixed(all, 3).c_str(),
                   peer > 0 ? fixed(all / peer, 2).c_str() : "n/a");
    }
  }
  report.print("| geomean | | | | | | %s | | %s |\n", same1.empty() ? "n/a" : fixed(geomean(same1), 2).c_str(),
               samen.empty() ? "n/a" : fixed(geomean(samen), 2).c_str());

  report.print("\n### Beside Crispy Doom: render-only ms/frame, things drawn (%d random cameras per map; Crispy on the map's demo)\n\n",
               s.cameras);
  report.print("Ours as Crispy's render-only time counts its own: the frame drawn into Doom's 8-bit screen, before the\n"
               "blit to colours. The last three columns: the same frames resolved to 32-bit colours by the renderer,\n"
               "as the game shows them.\n\n");
  report.print("| iwad | demo | map | Crispy 640x400 | ours 640x400, 1 thread | ÷ Crispy | ours, %d threads | ÷ Crispy | "
               "ours 1920x1080, %d threads | in colours: 1 thread | %d threads | 1920x1080 |\n"
               "|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n", cores, cores, cores);
  std::vector<double> ratio1, ration, hd, hd_rgba;
  for (const auto& iwad : iwads) {
    const wad::Stack wads = bsp::read_wads({iwad});
    const bool numbered = wads.map("MAP01").has_value();
    for (int n = 1; n <= 4; ++n) {
      const std::string demo = "demo" + std::to_string(n);
      const wad::Lump* lump = wads.find(demo);
      if (!lump) continue;
      const std::string map = demo_map(*lump, numbered);
      if (!wads.map(map)) continue;
      const level::Level level = bsp::build_wad_map(wads, map, {}, nullptr);
      const level::State state = level::start_state(level, s.skill);
      const auto cameras = random_cameras(level, s.cameras, 1);
      const double peer = crispy ? crispy_ms(s, iwad, demo) : 0;
      const auto [one, all] = time_threads(level, state, cameras, 640, 400, cores, s.repeat, true);
      const double big = time_threads(level, state, cameras, 1920, 1080, cores, s.repeat, true).second;
      const auto [one_rgba, all_rgba] = time_threads(level, state, cameras, 640, 400, cores, s.repeat);
      const double big_rgba = time_threads(level, state, cameras, 1920, 1080, cores, s.repeat).second;
      hd.push_back(big), hd_rgba.push_back(big_rgba);
      if (peer > 0) ratio1.push_back(one / peer), ration.push_back(all / peer);
      report.print("| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n", iwad.filename().c_str(), demo.c_str(),
                   map.c_str(), peer > 0 ? fixed(peer, 3).c_str() : "n/a", fixed(one, 3).c_str(),
                   peer > 0 ? fixed(one / peer, 2).c_str() : "n/a", fixed(all, 3).c_str(),
                   peer > 0 ? fixed(all / peer, 2).c_str() : "n/a", fixed(big, 3).c_str(), fixed(one_rgba, 3).c_str(),
                   fixed(all_rgba, 3).c_str(), fixed(big_rgba, 3).c_str());
      std::fflush(stdout);
    }
  }
  report.print("| geomean | | | | | %s | | %s | %s | | | %s |\n", ratio1.empty() ? "n/a" : fixed(geomean(ratio1), 2).c_str(),
               ration.empty() ? "n/a" : fixed(geomean(ration), 2).c_str(), fixed(geomean(hd), 3).c_str(),
               fixed(geomean(hd_rgba), 3).c_str());
}

// ---- capture ------------------------------------------------------------------

std::vector<uint8_t> stb_png(const image::Image& img) {  // the encoder we replaced, for comparison
  std::vector<uint8_t> out;
  auto sink = [](void* context, void* data, int size) {
    auto* v = static_cast<std::vector<uint8_t>*>(context);
    v->insert(v->end(), static_cast<uint8_t*>(data), static_cast<uint8_t*>(data) + size);
  };
  stbi_write_png_to_func(sink, &out, img.width, img.height, 4, img.pixels.data(), img.width * 4);
  return out;
}

// The outpost path's frames (RGB) and random views of freedoom2 MAP01 (8-bit, when
// Freedoom is installed): render, then each PNG encoding in one run (ours deflating
// runs, ours with libdeflate's search, stb_image_write); then whole `capture --cameras`
// processes of the outpost on one thread and on every core.
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
  report.print("\n### Capture: a frame's render and its PNG, %dx%d, one thread\n\n", s.width, s.height);
  report.print("| frames | step | ms/frame | KB/frame | ÷ render (time) |\n|---|---|---:|---:|---:|\n");
  for (const Scene& scene : scenes) {
    auto renderer = render::make_renderer("bsp");
    renderer->prepare(scene.level);
    const level::State state = level::start_state(scene.level, s.skill);
    render::Frame frame(s.width, s.height);
    frame.keep_indices = scene.indexed;
    double render_ms = 0, runs_ms = 0, search_ms = 0, stb_ms = 0, runs_bytes = 0, search_bytes = 0, stb_bytes = 0;
    for (const render::Camera& camera : scene.cameras) {
      auto t = Clock::now();
      renderer->render(scene.level, state, camera, frame);
      render_ms += cli::seconds_since(t) * 1000;
      t = Clock::now();
      runs_bytes += double(frame.png(image::PngDeflate::kRuns).size());
      runs_ms += cli::seconds_since(t) * 1000;
      t = Clock::now();
      search_bytes += double(frame.png(image::PngDeflate::kSearch).size());
      search_ms += cli::seconds_since(t) * 1000;
      if (frame.indexed()) continue;  // stb_image_write writes no palette
      t = Clock::now();
      stb_bytes += double(stb_png(frame).size());
      stb_ms += cli::seconds_since(t) * 1000;
    }
    const double n = double(scene.cameras.size());
    auto row = [&](const char* step, double ms, double bytes) {
      report.print("| %s | %s | %s | %s | %s |\n", scene.name.c_str(), step, fixed(ms / n, 2).c_str(),
                   bytes > 0 ? fixed(bytes / n / 1024, 0).c_str() : "", fixed(ms / render_ms, 2).c_str());
    };
    row("render (bsp)", render_ms, 0);
    row("PNG, ours: runs", runs_ms, runs_bytes);
    row("PNG, ours: libdeflate level 1", search_ms, search_bytes);
    if (stb_bytes > 0) row("PNG, stb_image_write", stb_ms, stb_bytes);
  }
  const std::string capture = (own_directory() / "pseudo3d-capture").string();
  const size_t frames = scenes.front().cameras.size();
  const std::string cores = std::to_string(every_core(s));
  report.print("\n| `pseudo3d-capture --cameras`, outpost path (whole process) | seconds | frames/s |\n|---|---:|---:|\n");
  for (const std::string& threads : {std::string("1"), cores}) {
    std::vector<double> runs;
    for (int r = 0; r < 3; ++r)
      runs.push_back(run_process({capture, (maps / "outpost.map").string(), "--cameras", (maps / "outpost.path").string(),
                                  "--size", std::to_string(s.width) + "x" + std::to_string(s.height), "--threads", threads,
                                  "-o", (dir / "frames").string()}));
    const double seconds = median(runs);
    report.print("| --threads %s | %s | %s |\n", threads.c_str(), fixed(seconds, 2).c_str(),
                 fixed(double(frames) / seconds, 0).c_str());
  }
  std::filesystem::remove_all(dir);
}

// ---- plots -------------------------------------------------------------------

// A table cell as a number: plain numbers and counts such as "100k" or "1M"; NaN for
// text ("n/a", "skipped").
double cell_number(const std::string& cell) {
  char* end = nullptr;
  double v = std::strtod(cell.c_str(), &end);
  if (end == cell.c_str()) return NAN;
  if (*end == 'k') v *= 1e3, ++end;
  else if (*end == 'M') v *= 1e6, ++end;
  return *end ? NAN : v;
}

// The index of the first column whose printed name starts with prefix, or -1.
int column(const Report::Section& s, const std::string& prefix) {
  for (size_t i = 0; i < s.columns.size(); ++i)
    if (s.columns[i].rfind(prefix, 0) == 0) return int(i);
  return -1;
}

double cell_at(const std::vector<std::string>& row, int column) {
  return column >= 0 && size_t(column) < row.size() ? cell_number(row[size_t(column)]) : NAN;
}

// Frame time against map size, one chart per kind of generated map, a line per renderer.
void plot_scaling(const Report::Section& table, const Settings& s, const std::filesystem::path& dir) {
  std::vector<std::string> kinds;
  for (const auto& row : table.cells)
    if (std::find(kinds.begin(), kinds.end(), row[0]) == kinds.end()) kinds.push_back(row[0]);
  for (const std::string& kind : kinds) {
    LineChart chart{"ms/frame against map size: " + kind, "walls",
                    "ms/frame, " + std::to_string(s.width) + "x" + std::to_string(s.height) + ", 1 thread", true, true, {}};
    for (size_t c = 0; c < table.columns.size(); ++c) {
      const std::string& name = table.columns[c];
      if (name.size() < 9 || name.compare(name.size() - 9, 9, " ms/frame") != 0) continue;
      LineSeries series{name.substr(0, name.size() - 9), {}, false};
      for (const auto& row : table.cells)
        if (row[0] == kind && std::isfinite(cell_at(row, int(c))))
          series.points.push_back({cell_at(row, 1), cell_at(row, int(c))});
      if (!series.points.empty()) chart.series.push_back(series);
    }
    write_file_atomically(dir / ("scaling-" + kind + ".svg"), line_chart_svg(chart));
  }
}

// Frame time against resolution, a line per map and thread count.
void plot_threads(const Report::Section& table, const std::filesystem::path& dir) {
  LineChart chart{"ms/frame against resolution and threads (BSP renderer)", "pixels per frame", "ms/frame", false, false, {}};
  std::vector<std::string> maps;
  for (const auto& row : table.cells)
    if (std::find(maps.begin(), maps.end(), row[0]) == maps.end()) maps.push_back(row[0]);
  for (size_t m = 0; m < maps.size(); ++m)
    for (const int c : {2, 3}) {  // the map's colour; one thread solid, every core dashed
      const std::string& map = maps[m];
      LineSeries series{map + ", " + table.columns[size_t(c)].substr(0, table.columns[size_t(c)].find(" ms")), {}, c == 3,
                        int(m)};
      for (const auto& row : table.cells) {
        int w = 0, h = 0;
        if (row[0] == map && std::sscanf(row[1].c_str(), "%dx%d", &w, &h) == 2)
          series.points.push_back({double(w) * h, cell_at(row, c)});
      }
      chart.series.push_back(series);
    }
  write_file_atomically(dir / "threads.svg", line_chart_svg(chart));
}

// Ours beside Crispy Doom per demo map: bars of ms/frame.
void plot_doom(const Report::Section& table, const std::filesystem::path& dir) {
  BarChart chart{"Render ms/frame beside Crispy Doom, 640x400", "ms/frame", {}, {}, 0, ""};
  const int crispy = column(table, "Crispy"), one = column(table, "ours 640x400, 1 thread"), all = column(table, "ours, ");
  if (crispy < 0 || one < 0 || all < 0) return;
  for (const int c : {crispy, one, all}) chart.series.push_back({table.columns[size_t(c)], {}});
  for (const auto& row : table.cells) {
    if (row[0] == "geomean") continue;
    chart.groups.push_back(row[2]);
    for (size_t i = 0; i < 3; ++i) chart.series[i].values.push_back(cell_at(row, std::array{crispy, one, all}[i]));
  }
  write_file_atomically(dir / "doom.svg", bar_chart_svg(chart));
}

// Charts of the tables this run printed, where a picture says it better.
void write_plots(const Settings& s, const std::filesystem::path& dir) {
  std::filesystem::create_directories(dir);
  if (const auto* table = report.find("Scaling")) plot_scaling(*table, s, dir);
  if (const auto* table = report.find("Threads")) plot_threads(*table, dir);
  if (const auto* table = report.find("Beside Crispy Doom: render-only")) plot_doom(*table, dir);  // random cameras
}

std::string cpu_name() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
  return "unknown CPU";
}

}  // namespace

int main(int argc, char** argv) {
  cli::App app{"pseudo3d-bench: renderer and compiler benchmarks, printed as markdown tables", "pseudo3d-bench"};
  Settings s;
  std::vector<std::string> sections;
  std::string size_text = "640x400";
  app.add_option("sections", sections,
                 "render, scaling, grids, strategies, hostile, capture, threads, wad, doom, play (default: all but wad, doom and play; with --iwad, wad)")
      ->check(cli::IsMember({"render", "scaling", "grids", "strategies", "hostile", "capture", "threads", "wad", "doom", "play"}));
  cli::add_wad_options(app, s.wads);
  app.add_option("--cameras", s.cameras, "wad: random cameras per map")->check(cli::Range(1, 100000))->capture_default_str();
  app.add_option("--runs", s.runs, "wad: compiles per map and tool (median)")->check(cli::Range(1, 1000))->capture_default_str();
  cli::add_skill_option(app, s.skill);
  app.add_option("--size", size_text, "resolution WxH")->capture_default_str();
  app.add_option("--repeat", s.repeat, "renders per camera")->check(cli::Range(1, 1000))->capture_default_str();
  app.add_option("--budget", s.budget_seconds, "seconds per renderer and map before the path is cut short")
      ->check(cli::finite_range(0.01, 3600.0))
      ->capture_default_str();
  app.add_option("--sizes", s.sizes, "wall counts for the scaling section")->delimiter(',')->capture_default_str();
  app.add_option("--renderers", s.renderers, "renderers to time (default: all)")->delimiter(',');
  app.add_option("--beside", s.beside_mapc, "hostile: another pseudo3d-mapc (an older build) compiling each level just before this one")
      ->check(cli::existing_file());
  std::string json;
  app.add_option("--threads", s.threads, "doom, wad and capture: the thread count timed beside one thread (default: every core)")
      ->check(cli::Range(1, 256));
  app.add_option("--peer-reps", s.peer_reps, "doom: Crispy Doom's timings per demo (median); 0: ours only")
      ->check(cli::Range(0, 100))
      ->capture_default_str();
  app.add_option("--json", json, "also write the tables as JSON (sections of rows, columns by name)");
  std::string plots;
  app.add_option("--plots", plots, "also draw charts of the scaling, threads and doom tables as SVG files in this directory");
  app.add_option("--source-dir", s.source_dir, "the project's source directory (for maps/)")
      ->check(cli::existing_directory())
      ->capture_default_str();
  return cli::run(app, argc, argv, [&] {
    cli::parse_size(size_text, s.width, s.height);
    if (!json.empty()) cli::output_file(json, ".json", "--json");
    if (!plots.empty()) cli::output_dir(plots, "--plots");  // before the run, not after it
    for (const auto& r : s.renderers)
      if (!render::make_renderer(r)) throw cli::ValidationError("--renderers", "unknown renderer '" + r + "'");
    if (sections.empty())
      sections = s.wads.iwad.empty() ? std::vector<std::string>{"render", "scaling", "grids", "strategies", "hostile", "capture", "threads"}
                                     : std::vector<std::string>{"wad"};
    // hostile measures children's peak memory, which includes this process's size at fork: first.
    std::stable_partition(sections.begin(), sections.end(), [](const std::string& name) { return name == "hostile"; });
    if (std::count(sections.begin(), sections.end(), "wad") && s.wads.iwad.empty())
      throw cli::ValidationError("--iwad", "the wad section needs WADs: --iwad [--file ...] [--map ...]");
#ifndef NDEBUG
    report.print("WARNING: not a Release build; timings are meaningless.\n");
#endif
    const bool renders = std::any_of(sections.begin(), sections.end(),
                                     [](const std::string& name) { return name != "hostile" && name != "play"; });
    if (renders)
      report.print("bench on %s, %dx%d, median of %d renders per camera\n", cpu_name().c_str(), s.width, s.height, s.repeat);
    else
      report.print("bench on %s\n", cpu_name().c_str());
    for (const std::string& section : sections) {
      if (section == "render") bench_render(s);
      if (section == "scaling") bench_scaling(s);
      if (section == "grids") bench_grids(s);
      if (section == "strategies") bench_strategies(s);
      if (section == "hostile") bench_hostile(s);
      if (section == "capture") bench_capture(s);
      if (section == "threads") bench_threads(s);
      if (section == "wad") bench_wad(s);
      if (section == "doom") bench_doom(s);
      if (section == "play") bench_play(s.skill, s.source_dir);
    }
    if (!json.empty()) write_file_atomically(json, report.json());
    if (!plots.empty()) write_plots(s, plots);
    return 0;
  });
}
