// bench wad: every map of WADs compiled by pseudo3d-mapc beside ZDBSP (whole processes,
// the trees compared), each rendered at random cameras; then the whole WAD at once.
#include <unistd.h>

#include <algorithm>
#include <cmath>

#include "engine/bsp/build.h"
#include "engine/bsp/load.h"
#include "engine/render/renderer.h"
#include "engine/util/error.h"
#include "engine/util/file.h"
#include "engine/wad/write.h"
#include "tools/bench_common.h"
#include "tools/bench_report.h"

namespace p3d::bench {

namespace {

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

}  // namespace

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

}  // namespace p3d::bench
