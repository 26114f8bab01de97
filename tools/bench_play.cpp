// bench play: Doom's rules at work. Every Freedoom map with every monster awake
// (ms per tic, the player invulnerable so the fight lasts), and Doom's own demos
// replayed without drawing (tics a second), beside how far they stay in sync with
// Chocolate Doom's play of them (tests/golden/doom_demos: its traced player and
// random index after every tic).
#include "tools/bench_play.h"

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "engine/bsp/load.h"
#include "engine/play/demo.h"
#include "engine/play/world.h"
#include "tools/bench_report.h"

namespace p3d::bench {

namespace {

using Clock = std::chrono::steady_clock;
constexpr int kAwakeTics = 700;  // 20 s of play

double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

std::vector<std::filesystem::path> freedoom_iwads() {
  std::vector<std::filesystem::path> out;
  for (const char* name : {"freedoom1.wad", "freedoom2.wad"})
    if (std::filesystem::exists(std::filesystem::path("/usr/share/games/doom") / name))
      out.push_back(std::filesystem::path("/usr/share/games/doom") / name);
  return out;
}


struct Awake {
  std::string map;
  int monsters = 0;
  double ms_per_tic = 0, ms_per_tic_four = 0;
};

// A map's tics with every monster hunting an invulnerable player who stands still; and
// again in a four-player co-op game, the other three standing at their starts, pressing
// use (a dead one comes back at its start, as Doom's netgames reborn).
Awake time_awake(const wad::Stack& wads, const std::filesystem::path& iwad, const std::string& map, int skill) {
  const level::Level level = bsp::open_level(bsp::LevelSource{{}, {iwad}, map}).level;
  Awake a{map, 0, 0, 0};
  for (const int players : {1, 4}) {
    play::GameOptions o = play::game_options_for(wads, map, skill);
    o.netgame = players > 1;
    for (int i = 0; i < players; ++i) o.in_game[size_t(i)] = true;
    play::World world(play::map_from_wads(wads, map, level), level, o, play::Random{});
    world.apply_cheats(play::kToggleGod);
    const int awake = world.wake_monsters();
    if (players == 1) a.monsters = awake;  // a netgame adds the things placed for it
    std::array<play::TicCmd, play::kMaxPlayers> cmds{};
    for (int i = 1; i < play::kMaxPlayers; ++i) cmds[size_t(i)].buttons = play::kBtUse;
    const auto start = Clock::now();
    for (int t = 0; t < kAwakeTics; ++t) world.tick_players(cmds);
    (players == 1 ? a.ms_per_tic : a.ms_per_tic_four) = seconds_since(start) * 1000 / kAwakeTics;
  }
  return a;
}

// A trace's rows: tic x y z angle momx momy health prndindex viewz (empty when missing).
std::vector<std::vector<int64_t>> read_trace(const std::filesystem::path& path) {
  std::vector<std::vector<int64_t>> rows;
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    std::vector<int64_t> row;
    for (int64_t v; fields >> v;) row.push_back(v);
    rows.push_back(row);
  }
  return rows;
}

}  // namespace

void bench_play(int skill, const std::string& source_dir) {
  const std::vector<std::filesystem::path> iwads = freedoom_iwads();
  if (iwads.empty()) return report.print("\n### Doom's rules: no Freedoom (apt-get install freedoom)\n");

  report.print("\n### Doom's rules: every monster awake, ms per tic (%d tics, skill %d, the player invulnerable)\n\n",
               kAwakeTics, skill);
  report.print("| iwad | maps | monsters, most | busiest map | ms/tic there | slowest map | ms/tic, most | "
               "four players: slowest map | ms/tic, most |\n|---|---:|---:|---|---:|---|---:|---|---:|\n");
  for (const auto& iwad : iwads) {
    const wad::Stack wads = bsp::read_wads({iwad});
    std::vector<Awake> maps;
    for (const std::string& map : wads.map_names()) maps.push_back(time_awake(wads, iwad, map, skill));
    const Awake& busiest = *std::max_element(maps.begin(), maps.end(), [](const Awake& a, const Awake& b) { return a.monsters < b.monsters; });
    const Awake& slowest = *std::max_element(maps.begin(), maps.end(), [](const Awake& a, const Awake& b) { return a.ms_per_tic < b.ms_per_tic; });
    const Awake& slowest_four = *std::max_element(
        maps.begin(), maps.end(), [](const Awake& a, const Awake& b) { return a.ms_per_tic_four < b.ms_per_tic_four; });
    report.print("| %s | %zu | %d | %s | %s | %s | %s | %s | %s |\n", iwad.filename().c_str(), maps.size(), busiest.monsters,
                 busiest.map.c_str(), fixed(busiest.ms_per_tic, 4).c_str(), slowest.map.c_str(),
                 fixed(slowest.ms_per_tic, 4).c_str(), slowest_four.map.c_str(), fixed(slowest_four.ms_per_tic_four, 4).c_str());
  }

  report.print("\n### Doom's demos: in sync with Chocolate Doom, and replayed without drawing\n\n");
  report.print("| demo | map, skill | tics | in sync with Chocolate Doom | tics/s |\n|---|---|---:|---:|---:|\n");
  for (const auto& iwad : iwads) {
    const wad::Stack wads = bsp::read_wads({iwad});
    const bool commercial = wads.map("MAP01").has_value();
    for (int n = 1; n <= 4; ++n) {
      const std::string lump = "DEMO" + std::to_string(n);
      const wad::Lump* found = wads.find(lump);
      if (!found) continue;
      const play::DoomDemo doom = play::decode_doom_demo(found->bytes, lump);
      const std::string map = doom.map_name(commercial);
      const level::Level level = bsp::open_level(bsp::LevelSource{{}, {iwad}, map}).level;
      const play::Demo demo = play::demo_from_doom(doom, level);
      play::GameOptions o = play::game_options_for(wads, map, doom.skill);
      o.fast = doom.fast, o.respawn = doom.respawn, o.no_monsters = doom.no_monsters;
      const std::string stem = iwad.stem().string() + "_demo" + std::to_string(n);
      const auto trace = read_trace(std::filesystem::path(source_dir) / "tests/golden/doom_demos" / (stem + ".trace"));
      // The timed run: the rules alone.
      double best = 1e9;
      for (int run = 0; run < 3; ++run) {
        play::World world(play::map_from_wads(wads, map, level), level, o, play::Random{});
        const auto start = Clock::now();
        for (const play::DemoTic& t : demo.tics) world.tick(t.cmd);
        best = std::min(best, seconds_since(start));
      }
      // The checked run: tic by tic against Chocolate Doom's.
      play::World world(play::map_from_wads(wads, map, level), level, o, play::Random{});
      size_t in_sync = 0;
      for (size_t t = 0; t < demo.tics.size() && t < trace.size(); ++t) {
        world.tick(demo.tics[t].cmd);
        const play::Player& p = world.player();
        const std::vector<int64_t> ours = {int64_t(t), p.mo->x, p.mo->y, p.mo->z, int64_t(p.mo->angle), p.mo->mom_x,
                                           p.mo->mom_y, p.inv.health, world.random().play_index(), p.view_z};
        if (ours != trace[t]) break;
        ++in_sync;
      }
      const std::string sync = trace.empty() ? std::string("no trace")
                                             : std::to_string(in_sync) + " of " + std::to_string(demo.tics.size());
      report.print("| %s %s | %s, %d | %zu | %s | %s |\n", iwad.filename().c_str(), lump.c_str(), map.c_str(), doom.skill,
                   demo.tics.size(), sync.c_str(), fixed(double(demo.tics.size()) / best, 0).c_str());
    }
  }
}

}  // namespace p3d::bench
