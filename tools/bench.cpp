// bench: the project's benchmark (Release builds). Prints markdown tables:
//   render      median ms/frame and fps per renderer along a fixed camera path
//   scaling     compile time and frame time as generated maps grow from 1k to 1M walls
//   grids       grid ray casting against open distance: mazes and open arenas
//   strategies  tree size, depth, build time and frame time per BSP strategy
//   hostile, threads: see main's help and the README
//   capture     a frame's render beside its PNG at each level, whole captures (bench_capture.cpp)
//   wad, doom   beside ZDBSP and Crispy Doom (bench_wad.cpp, bench_doom.cpp)
//   play        Doom's rules: every monster awake on every Freedoom map, Doom's demos (bench_play.cpp)
// Timings are wall-clock medians; compare ratios within one run. --json writes the
// tables as JSON, --plots draws the scaling, threads and doom tables as SVG charts.
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <map>
#include <thread>

#include "engine/bsp/build.h"
#include "engine/bsp/load.h"
#include "engine/level/io.h"
#include "engine/map/generate.h"
#include "engine/render/camera_file.h"
#include "engine/render/renderer.h"
#include "engine/util/file.h"
#include "engine/util/thread_pool.h"
#include "tools/bench_common.h"
#include "tools/bench_play.h"
#include "tools/bench_report.h"
#include "tools/cli.h"
#include "tools/plot_svg.h"

using namespace p3d;
using namespace p3d::bench;
using tools::BarChart;
using tools::LineChart;
using tools::LineSeries;

namespace {

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
