// mapc: the map compiler. map source -> validate -> BSP -> self-contained .bsp.
#include <unistd.h>

#include <atomic>
#include <condition_variable>
#include <mutex>
#include <thread>

#include "engine/bsp/build.h"
#include "engine/bsp/load.h"
#include "engine/bsp/check.h"
#include "engine/level/io.h"
#include "engine/render/renderer.h"
#include "engine/util/file.h"
#include "engine/wad/art_cache.h"
#include "tools/cli.h"
#include "tools/overview_svg.h"

#ifdef P3D_MIMALLOC
#include <mimalloc.h>
#endif

using namespace p3d;

namespace {

struct Args {
  cli::LevelArgs level;
  std::string output, strategy = "greedy", svg, pos;
  double angle = 0, fov = 90;
  int columns = 160;
  uint64_t seed = 1;
  bool stats = false, check = false, all_maps = false, all_warnings = false;
  std::string json;
  bsp::Options options;
};

Stats stat_fields(const bsp::Stats& s) {
  const double bound = s.random_bound();
  return {{"walls", double(s.walls)},
          {"fragments", double(s.fragments)},
          {"splits", double(s.splits)},
          {"nodes", double(s.nodes)},
          {"leaves", double(s.leaves)},
          {"segs", double(s.segs)},
          {"empty_leaves", double(s.empty_leaves)},
          {"free_splits", double(s.free_splits)},
          {"free_lines", double(s.free_lines)},
          {"max_depth", double(s.max_depth)},
          {"mean_depth", s.mean_depth},
          {"shortest_fragment", s.shortest_fragment},
          {"ray_cast_leaves", double(s.ray_cast_leaves)},
          {"random_bound", std::round(bound)},
          {"fragments_per_bound", bound > 0 ? s.fragments / bound : 0.0}};
}

Stats time_fields(double parse_seconds, double build_seconds) {
  return {{"parse_seconds", std::round(parse_seconds * 1000) / 1000},
          {"build_seconds", std::round(build_seconds * 1000) / 1000}};
}

// Shows the current phase (and the build's percentage) on a terminal once the
// compile has taken more than a second; silent otherwise.
class Progress {
 public:
  Progress() : enabled_(::isatty(2)), start_(std::chrono::steady_clock::now()) {
    if (enabled_) thread_ = std::thread([this] { loop(); });
  }
  ~Progress() {
    if (!enabled_) return;
    {
      std::lock_guard lock(mutex_);
      done_ = true;
    }
    wake_.notify_all();
    thread_.join();
    if (shown_) std::fprintf(stderr, "\r%-40s\r", "");
  }
  void phase(const char* name) {
    phase_.store(name);
    fraction_.store(-1);
  }
  void fraction(double f) { fraction_.store(f); }

 private:
  void loop() {
    std::unique_lock lock(mutex_);
    while (!wake_.wait_for(lock, std::chrono::milliseconds(200), [this] { return done_; })) {
      if (cli::seconds_since(start_) < 1.0) continue;
      const double f = fraction_.load();
      if (f >= 0)
        std::fprintf(stderr, "\r%s: %3.0f%%   ", phase_.load(), 100 * f);
      else
        std::fprintf(stderr, "\r%s...        ", phase_.load());
      shown_ = true;
    }
  }
  const bool enabled_;
  const std::chrono::steady_clock::time_point start_;
  std::atomic<const char*> phase_{"reading"};
  std::atomic<double> fraction_{-1};
  std::mutex mutex_;
  std::condition_variable wake_;
  bool done_ = false, shown_ = false;
  std::thread thread_;
};

// Prints one line per violated invariant; false if there were any.
bool check(const level::Level& level, const std::string& name) {
  const auto problems = bsp::check_invariants(level);
  for (const std::string& p : problems) std::fprintf(stderr, "%s: invariant violated: %s\n", name.c_str(), p.c_str());
  return problems.empty();
}

wad::ImportOptions import_options(const Args& a) {
  wad::ImportOptions o;
  if (!a.all_warnings) o.max_warnings_per_kind = 5;
  o.colours = !a.svg.empty();  // the .bsp keeps palette indices: colours only for --svg's view
  return o;
}

// One level: compile, check, write the .bsp (and the SVG), print statistics.
int compile_one(Args& a, const bsp::LevelSource& source, Progress& progress) {
  progress.phase(source.is_wad() ? "reading the WADs" : "parsing and validating");
  const auto start = std::chrono::steady_clock::now();
  std::optional<map::Source> parsed;
  std::optional<wad::Stack> wads;
  std::string map_name;
  if (source.is_wad()) {
    wads = bsp::read_wads(source.wads);
    map_name = bsp::resolve_map_name(*wads, source.map);
  } else if (const bsp::FileKind kind = bsp::file_kind(source.file);
             kind == bsp::FileKind::kMapSource || kind == bsp::FileKind::kGridSource) {
    parsed = map::load_source(source.file, source.load);
  } else if (kind == bsp::FileKind::kCompiled) {
    throw Error(source.file.string() + ": a compiled level (.bsp) already: capture, compare and game read it");
  } else {
    throw Error(source.file.string() + ": " + bsp::describe(kind) + "; mapc compiles .map and .grid sources and WAD maps");
  }
  const double parse_seconds = cli::seconds_since(start);

  progress.phase("building the BSP");
  const auto build_start = std::chrono::steady_clock::now();
  a.options.progress = [&](double done) { progress.fraction(done); };
  bsp::Stats stats;
  std::vector<std::string> warnings;
  const level::Level level = parsed ? bsp::build(std::move(*parsed), a.options, &stats)
                                    : bsp::build_wad_map(*wads, map_name, a.options, &warnings, &stats, import_options(a));
  const double build_seconds = cli::seconds_since(build_start);
  const std::string name = parsed ? source.file.string() : source.wads.back().filename().string() + ":" + map_name;
  parsed.reset();  // what the build left of it (its sectors, textures, things)
  wads.reset();
  for (const std::string& w : warnings) std::fprintf(stderr, "%s\n", w.c_str());
  if (a.check) {
    progress.phase("checking invariants");
    if (!check(level, name)) return 1;
  }
  // Everything that can fail is decided before anything is written.
  std::optional<tools::ViewTrace> view;
  if (!a.svg.empty() && !a.pos.empty()) {
    const auto camera = render::camera_at(level, cli::parse_point(a.pos, "--pos"), a.angle, render::kEyeHeight, a.fov);
    view = tools::trace_view(level, camera, a.columns, std::max(1, a.columns * 5 / 8));
  }
  progress.phase("writing");
  Outputs outputs;  // all or nothing
  outputs.add(a.output, [&](OutputFile& file) { level::encode(level, file); });
  if (!a.svg.empty()) outputs.add(a.svg, tools::overview_svg(level, view));
  const Stats times = time_fields(parse_seconds, build_seconds);
  if (!a.json.empty())
    outputs.add(a.json, "{\"stats\": " + stats_json(stat_fields(stats)) + ", \"time\": " + stats_json(times) + "}\n");
  outputs.commit();
  std::printf("%s: %zu walls, %zu fragments, %zu nodes, %zu leaves, depth %zu (mean %.1f) -> %s\n", name.c_str(),
              stats.walls, stats.fragments, stats.nodes, stats.leaves, stats.max_depth, stats.mean_depth, a.output.c_str());
  if (a.check) std::printf("%s: the BSP invariants hold\n", name.c_str());
  if (a.stats) std::printf("stats: %s\ntime: %s\n", statdump(stat_fields(stats)).c_str(), statdump(times).c_str());
  return 0;
}

// Every map of the WADs into a directory, with a progress line and a summary table.
// Memory a map's compile frees stays the process's for the next map's, not given back
// and faulted in again (the kernel zeroing every page), at the same peak: freedoom2
// --all never slower, and in 0.5 to 0.8 of the time while this host's faults were
// dear. (A single map keeps mimalloc's default: at a million walls its peak would grow
// by a tenth.)
void keep_freed_memory() {
#ifdef P3D_MIMALLOC
  mi_option_disable(mi_option_allow_decommit);
#endif
}

int compile_all(Args& a, const bsp::LevelSource& source) {
  if (!source.is_wad()) throw cli::ValidationError("--all", "compiles every map of WADs: use it with --iwad (or a WAD)");
  if (!a.svg.empty()) throw cli::ValidationError("--svg", "draws one level: leave out --all");
  keep_freed_memory();
  const wad::Stack wads = bsp::read_wads(source.wads);
  const std::vector<std::string> maps = wads.map_names();
  if (maps.empty()) throw Error(source.wads.back().string() + ": the WADs hold no maps");
  wad::ImportOptions import = import_options(a);
  try {  // the art every map shares, made once (without art, each map says why it fails)
    import.art_cache = std::make_shared<wad::ArtCache>(wads);
  } catch (const Error&) {
  }
  std::filesystem::create_directories(a.output);
  const bool terminal = ::isatty(2);
  std::printf("%-6s %-28s %7s %9s %7s %7s %9s %8s %9s\n", "map", "title", "walls", "fragments", "nodes", "leaves", "depth",
              "warnings", "ms");
  size_t failed = 0, total_warnings = 0;
  double total_ms = 0;
  for (size_t i = 0; i < maps.size(); ++i) {
    if (terminal) std::fprintf(stderr, "\r[%zu/%zu] %s...   ", i + 1, maps.size(), maps[i].c_str());
    try {
      const auto start = std::chrono::steady_clock::now();
      bsp::Stats stats;
      std::vector<std::string> warnings;
      const level::Level level = bsp::build_wad_map(wads, maps[i], a.options, &warnings, &stats, import);
      if (a.check && !check(level, maps[i])) throw Error(maps[i] + ": the BSP breaks its invariants");
      level::write(level, std::filesystem::path(a.output) / (maps[i] + ".bsp"));
      const double ms = cli::seconds_since(start) * 1000;
      total_ms += ms;
      total_warnings += stats.warnings;
      if (terminal) std::fprintf(stderr, "\r%40s\r", "");
      if (a.all_warnings)
        for (const std::string& w : warnings) std::fprintf(stderr, "%s\n", w.c_str());
      std::string title = level.title.substr(std::min(level.title.size(), maps[i].size() + 2));
      if (title.size() > 28) title = title.substr(0, 27) + "~";
      char depth[32];
      std::snprintf(depth, sizeof depth, "%zu/%.1f", stats.max_depth, stats.mean_depth);
      std::printf("%-6s %-28s %7zu %9zu %7zu %7zu %9s %8zu %9.1f\n", maps[i].c_str(), title.c_str(), stats.walls,
                  stats.fragments, stats.nodes, stats.leaves, depth, stats.warnings, ms);
    } catch (const std::exception& e) {
      if (terminal) std::fprintf(stderr, "\r%40s\r", "");
      std::fprintf(stderr, "%s\n", e.what());
      ++failed;
    }
  }
  std::printf("%zu maps compiled into %s, %zu failed, %zu warnings%s, %.0f ms\n", maps.size() - failed,
              a.output.c_str(), failed, total_warnings, a.all_warnings ? "" : " (--all-warnings lists them)", total_ms);
  return failed ? 1 : 0;
}

}  // namespace

int main(int argc, char** argv) {
  cli::App app{"pseudo3d-mapc: compile a level (.map, .grid, or a WAD map) into a self-contained BSP (.bsp)", "pseudo3d-mapc"};
  Args a;
  cli::add_level_options(app, a.level);
  app.add_option("-o,--output", a.output,
                 "compiled level to write (default: out/<level>.bsp); with --all, a directory (default: out/<wad>/)");
  app.add_flag("--all", a.all_maps, "compile every map of the WADs into the -o directory, with a summary table");
  app.add_flag("--all-warnings", a.all_warnings, "list every warning about a WAD map's quirks (default: 5 of a kind)");
  app.add_option("--strategy", a.strategy, "splitter choice: first, random, freesplit or greedy")
      ->check(cli::IsMember({"first", "random", "freesplit", "greedy"}))
      ->capture_default_str();
  app.add_option("--seed", a.seed, "seed for random choices (same seed, same file)")->capture_default_str();
  app.add_option("--candidates", a.options.greedy_candidates, "greedy: candidate splitters per cell")
      ->check(cli::Range(1, 1 << 20))
      ->capture_default_str();
  app.add_option("--sample", a.options.greedy_sample, "greedy: fragments scored per candidate")
      ->check(cli::Range(1, 1 << 30))
      ->capture_default_str();
  // Greedy's weights, each a finite cost of its own.
  struct Weight {
    const char* name;
    const char* help;
    double* value;
  };
  const Weight weights[] = {
      {"--split-weight", "greedy: cost of a split", &a.options.split_weight},
      {"--balance-weight", "greedy: cost of a barrier (two-sided wall) of imbalance", &a.options.balance_weight},
      {"--plain-weight", "greedy: a wall that is no barrier, in barriers, in the balance", &a.options.plain_weight},
      {"--line-weight", "greedy: gain per fragment on the splitter's line", &a.options.line_weight},
      {"--peel-weight", "greedy: cost of a splitter leaving one side empty", &a.options.peel_weight},
      {"--sliver-weight", "greedy: cost of a split leaving a piece under 1/16 unit", &a.options.sliver_weight},
  };
  for (const Weight& w : weights)
    app.add_option(w.name, *w.value, w.help)->check(cli::finite_range(0.0, 1e9))->capture_default_str();
  app.add_option("--free-min", a.options.free_min_fragments, "greedy: fragments a cell needs for a free splitter (a line holding no wall)")
      ->check(cli::Range(2, 1 << 30))
      ->capture_default_str();
  app.add_option("--free-lopsided", a.options.free_lopsided,
                 "greedy: a free splitter is tried when the best wall's line takes less than this share of the cell")
      ->check(cli::finite_range(0.0, 1.0))
      ->capture_default_str();
  app.add_option("--free-balance", a.options.free_balance, "greedy: the share of the cell a free splitter leaves on either side, at least")
      ->check(cli::finite_range(0.0, 0.5))
      ->capture_default_str();
  app.add_option("--free-candidates", a.options.free_candidates, "greedy: lines through two vertices scored as free splitters per cell")
      ->check(cli::Range(0, 1 << 20))
      ->capture_default_str();
  app.add_flag("--stats", a.stats, "print tree statistics (a statdump line) and times (apart)");
  app.add_option("--json", a.json, "with --stats: also write them as JSON, with the same names");
  app.add_flag("--check", a.check, "verify the BSP invariants exactly before writing");
  app.add_option("--svg", a.svg, "also draw the level and its BSP from above as SVG");
  app.add_option("--pos", a.pos, "--svg: show a camera at X,Y: its view cone, draw order and closed columns");
  app.add_option("--angle", a.angle, "--svg: the camera's angle")->check(cli::finite())->capture_default_str();
  app.add_option("--fov", a.fov, "--svg: the camera's field of view")->check(cli::finite_range(1.0, 179.0))->capture_default_str();
  app.add_option("--columns", a.columns, "--svg: screen columns traced")->check(cli::Range(1, 4096))->capture_default_str();

  return cli::run(app, argc, argv, [&] {
    a.options.strategy = *bsp::parse_strategy(a.strategy);
    a.options.seed = a.seed;
    const bsp::LevelSource source = cli::level_source(a.level);
    if (!a.json.empty() && !a.stats) throw cli::ValidationError("--json", "writes the --stats: add --stats");
    if (!a.json.empty()) cli::output_file(a.json, ".json", "--json");
    if (!a.svg.empty()) cli::output_file(a.svg, ".svg", "--svg");
    if (a.output.empty()) a.output = cli::default_output(source, a.all_maps ? "/" : ".bsp");
    if (a.all_maps) {
      if (!a.level.map.empty()) throw cli::ValidationError("--all", "compiles every map: leave out --map");
      return compile_all(a, source);
    }
    cli::output_file(a.output, ".bsp", "--output");
    Progress progress;
    return compile_one(a, source, progress);
  });
}
