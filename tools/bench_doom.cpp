// bench doom: beside Crispy Doom on the same views (its render-only time from
// tools/peers/doom_render_ms.py): each map's start turning in place, the IWADs' demos,
// and random cameras.
#include <unistd.h>

#include <cstdio>
#include <map>

#include "engine/bsp/build.h"
#include "engine/bsp/load.h"
#include "engine/play/demo.h"
#include "engine/play/doom_demo.h"
#include "engine/play/world.h"
#include "engine/render/renderer.h"
#include "engine/util/error.h"
#include "engine/util/file.h"
#include "tools/bench_common.h"
#include "tools/bench_report.h"

namespace p3d::bench {

namespace {

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

// Calls visit(iwad, wads, demo, lump, map) for each demo lump of the IWADs (DEMO1 to
// DEMO4) whose map the IWAD holds.
template <typename Visit>
void for_each_demo_map(const std::vector<std::filesystem::path>& iwads, const Visit& visit) {
  for (const auto& iwad : iwads) {
    const wad::Stack wads = bsp::read_wads({iwad});
    const bool numbered = wads.map("MAP01").has_value();
    for (int n = 1; n <= 4; ++n) {
      const std::string demo = "demo" + std::to_string(n);
      const wad::Lump* lump = wads.find(demo);
      if (!lump) continue;
      const std::string map = demo_map(*lump, numbered);
      if (wads.map(map)) visit(iwad, wads, demo, *lump, map);
    }
  }
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

}  // namespace

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
  for_each_demo_map(iwads, [&](const std::filesystem::path& iwad, const wad::Stack& wads, const std::string& demo,
                               const wad::Lump& lump, const std::string& map) {
    const play::DoomDemo doom = play::decode_doom_demo(lump.bytes, demo);
    const level::Level level = bsp::build_wad_map(wads, map, {}, nullptr);
    const double peer = crispy ? crispy_ms(s, iwad, demo) : 0;
    const auto [one, all] = time_demo_views(wads, level, map, doom, cores, s.repeat);
    if (peer > 0) same1.push_back(one / peer), samen.push_back(all / peer);
    report.print("| %s | %s | %s | %zu | %s | %s | %s | %s | %s |\n", iwad.filename().c_str(), demo.c_str(), map.c_str(),
                 doom.tic_count(), peer > 0 ? fixed(peer, 3).c_str() : "n/a", fixed(one, 3).c_str(),
                 peer > 0 ? fixed(one / peer, 2).c_str() : "n/a", fixed(all, 3).c_str(),
                 peer > 0 ? fixed(all / peer, 2).c_str() : "n/a");
  });
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
  for_each_demo_map(iwads, [&](const std::filesystem::path& iwad, const wad::Stack& wads, const std::string& demo,
                               const wad::Lump&, const std::string& map) {
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
  });
  report.print("| geomean | | | | | %s | | %s | %s | | | %s |\n", ratio1.empty() ? "n/a" : fixed(geomean(ratio1), 2).c_str(),
               ration.empty() ? "n/a" : fixed(geomean(ration), 2).c_str(), fixed(geomean(hd), 3).c_str(),
               fixed(geomean(hd_rgba), 3).c_str());
}

}  // namespace p3d::bench
