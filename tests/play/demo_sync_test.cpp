// Doom's demos beside Chocolate Doom's play of them: the console player as Chocolate
// Doom left it after each tic (tests/golden/doom_demos and desync_demos, traced from
// its G_Ticker) against the World's. In sync: the player's position, angle, momentum,
// health, view height and Doom's random index all equal, tic after tic.
//
// P3D_SYNC_DUMP=DIR writes our things after every tic of each demo to DIR (the format
// of the traced Chocolate Doom's detailed trace), for finding where a demo parts.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>

#include "engine/bsp/load.h"
#include "engine/play/demo.h"
#include "engine/play/doom_demo.h"
#include "engine/play/thing_dump.h"
#include "engine/play/world.h"
#include "engine/util/bytes.h"
#include "engine/util/file.h"
#include "tests/support/player_trace.h"
#include "tests/support/support.h"

namespace p3d::play {
namespace {

struct Sync {
  size_t tics_in_sync = 0, traced = 0, demo_tics = 0;
};

// Plays a demo of the WAD beside Chocolate Doom's trace of it (tests/golden/<golden>/
// <stem>.trace); returns how many tics from the first stay in sync.
Sync sync_of(const std::string& wad_file, std::span<const uint8_t> demo_bytes, const std::string& lump,
             const std::string& stem, const std::string& golden = "doom_demos") {
  const auto wad = test::freedoom_path(wad_file);
  const wad::Stack wads = bsp::read_wads({wad});
  const DoomDemo demo = decode_doom_demo(demo_bytes, lump);
  const bool commercial = wads.map("MAP01").has_value();
  const std::string map_name = demo.map_name(commercial);
  const level::Level level = bsp::open_level(bsp::LevelSource{{}, {wad}, map_name}).level;
  GameOptions options = game_options_for(wads, map_name, demo.skill);
  options.fast = demo.fast;
  options.respawn = demo.respawn;
  options.no_monsters = demo.no_monsters;
  // Doom's G_DoReborn in a single-player game: the level from its start, the random
  // index and the game's clock going on.
  auto start = [&](const World* last) {
    if (last) options.game_tic = last->game_tic();
    return std::make_unique<World>(map_from_wads(wads, map_name, level), level, options,
                                   last ? last->random() : Random{});
  };
  std::unique_ptr<World> world = start(nullptr);

  const std::vector<test::PlayerTic> trace = test::read_player_trace(test::source_dir() / "tests/golden" / golden / (stem + ".trace"));
  std::ofstream dump;
  if (const char* d = std::getenv("P3D_SYNC_DUMP")) dump.open(std::filesystem::path(d) / (stem + ".ours"));
  Sync s;
  s.traced = trace.size();
  s.demo_tics = demo.tic_count();
  for (size_t t = 0; t < trace.size() && t < demo.tic_count(); ++t) {
    const DoomTic d = demo.console_tic(t);
    if (world->player().state == PlayerState::kReborn) world = start(world.get());
    world->tick(TicCmd{d.forward, d.side, d.turn, d.buttons});
    if (dump.is_open()) dump << dump_things(*world, t);
    const test::PlayerTic ours = test::player_tic(*world, int64_t(t));
    if (!(ours == trace[t])) {
      std::printf("[ parted   ] %s %s at tic %zu:\n  ours  %s\n  doom  %s\n", wad_file.c_str(), lump.c_str(), t,
                  test::describe(ours).c_str(), test::describe(trace[t]).c_str());
      if (!dump.is_open()) break;
    } else if (s.tics_in_sync == t) {
      ++s.tics_in_sync;
    }
  }
  std::printf("[ sync     ] %s %s %s skill %d: %zu of %zu traced tics in sync (%zu in the demo)\n", wad_file.c_str(),
              lump.c_str(), map_name.c_str(), demo.skill, s.tics_in_sync, s.traced, s.demo_tics);
  return s;
}

// DEMOn of the WAD beside its trace.
Sync sync_of(const std::string& wad_file, int demo_number) {
  const wad::Stack wads = bsp::read_wads({test::freedoom_path(wad_file)});
  const std::string lump = "DEMO" + std::to_string(demo_number);
  return sync_of(wad_file, wads.find(lump)->bytes, lump,
                 wad_file.substr(0, wad_file.find('.')) + "_demo" + std::to_string(demo_number));
}

TEST(DemoSync, FreedoomsEightDemosPlayInSyncWithChocolateDoomToTheirLastTic) {
  for (const char* wad : {"freedoom1.wad", "freedoom2.wad"})
    for (int demo = 1; demo <= 4; ++demo) {
      const Sync s = sync_of(wad, demo);
      EXPECT_EQ(s.traced, s.demo_tics) << wad << " DEMO" << demo << ": the trace covers the whole demo";
      EXPECT_EQ(s.tics_in_sync, s.demo_tics) << wad << " DEMO" << demo;
    }
}

// Our --record of the freedoom2 MAP01 walk (game_test checks the game still records
// these bytes), as Chocolate Doom played it: in sync to the exit.
TEST(DemoSync, OurRecordedDemoPlaysInChocolateDoomAsInOurs) {
  const std::vector<uint8_t> bytes =
      read_file_bytes(test::source_dir() / "tests/golden/doom_demos/recorded_freedoom2_map01.lmp");
  const Sync s = sync_of("freedoom2.wad", bytes, "recorded_freedoom2_map01.lmp", "recorded_freedoom2_map01");
  EXPECT_EQ(s.traced, s.demo_tics);
  EXPECT_EQ(s.tics_in_sync, s.demo_tics);
}

// A demo of random play in tests/golden/<directory>/<iwad stem>-<map>-<skill>...lmp
// beside Chocolate Doom's trace of it: in sync to its last tic.
void expect_golden_demo_in_sync(const std::string& directory, const std::string& stem) {
  const std::string wad_file = stem.substr(0, stem.find('-')) + ".wad";
  const std::vector<uint8_t> bytes = read_file_bytes(test::source_dir() / "tests/golden" / directory / (stem + ".lmp"));
  const Sync s = sync_of(wad_file, bytes, stem + ".lmp", stem, directory);
  EXPECT_EQ(s.traced, s.demo_tics) << stem << ": the trace covers the whole demo";
  EXPECT_EQ(s.tics_in_sync, s.demo_tics) << stem;
}

// Demos of random play that once parted from Chocolate Doom, each at a rule of ours
// that was not Doom's. The player dies in most of them, and the level starts again
// (Doom's G_DoReborn).
TEST(DemoSync, DemosOfRandomPlayOnFreedomsHarderMapsPlayInSyncToTheirLastTic) {
  for (const char* stem : {"freedoom2-map32-nightmare-fast", "freedoom2-map32-skill2", "freedoom2-map32-skill3",
                           "freedoom2-map32-skill5", "freedoom2-map21-skill4", "freedoom2-map13-skill3",
                           "freedoom2-map14-skill4", "freedoom1-e3m7-skill2"})
    expect_golden_demo_in_sync("desync_demos", stem);
}

// tools/peers/random_demo.py's demos on each IWAD (freedm's single player among them,
// one in Doom v1.91's long tics), every option: in sync to their last tic.
TEST(DemoSync, GeneratedRandomDemosPlayInSyncToTheirLastTic) {
  size_t demos = 0;
  for (const auto& entry : std::filesystem::directory_iterator(test::source_dir() / "tests/golden/random_demos"))
    if (entry.path().extension() == ".lmp") {
      expect_golden_demo_in_sync("random_demos", entry.path().stem().string());
      ++demos;
    }
  EXPECT_GE(demos, 4u);
}

// ---- netgames: every player after every tic

// Plays DEMOn of a netgame WAD (every player's input) beside Chocolate Doom's trace of it.
Sync net_sync_of(const std::string& wad_file, int demo_number,
                 const std::filesystem::path& golden = test::source_dir() / "tests/golden/netgame_demos") {
  const auto wad = test::freedoom_path(wad_file);
  const wad::Stack wads = bsp::read_wads({wad});
  const std::string lump = "DEMO" + std::to_string(demo_number);
  const DoomDemo demo = decode_doom_demo(wads.find(lump)->bytes, lump);
  const bool commercial = wads.map("MAP01").has_value();
  const std::string map_name = demo.map_name(commercial);
  const level::Level level = bsp::open_level(bsp::LevelSource{{}, {wad}, map_name}).level;
  GameOptions options = game_options_for(wads, map_name, demo.skill);
  set_demo_game(options, demo);
  World world(map_from_wads(wads, map_name, level), level, options, Random{});
  const std::string stem = wad_file.substr(0, wad_file.find('.')) + "_demo" + std::to_string(demo_number);
  const test::NetTrace trace = test::read_net_trace(golden / (stem + ".trace"));
  std::ofstream dump;
  if (const char* d = std::getenv("P3D_SYNC_DUMP")) dump.open(std::filesystem::path(d) / (stem + ".ours"));
  Sync s;
  s.traced = trace.hashes.size();
  s.demo_tics = demo.tic_count();
  for (size_t t = 0; t < trace.hashes.size() && t < demo.tic_count(); ++t) {
    world.tick_players(players_tic(demo, t));
    if (dump.is_open()) dump << dump_things(world, t);
    const std::vector<std::string> ours = test::net_lines(world, t);
    if (test::net_hash(ours) != trace.hashes[t]) {
      std::printf("[ parted   ] %s %s at tic %zu:\n", wad_file.c_str(), lump.c_str(), t);
      for (const std::string& l : ours) std::printf("  ours  %s\n", l.c_str());
      if (const auto it = trace.full.find(t); it != trace.full.end())
        for (const std::string& l : it->second) std::printf("  doom  %s\n", l.c_str());
      break;
    }
    ++s.tics_in_sync;
  }
  std::printf("[ sync     ] %s %s %s skill %d, %d players: %zu of %zu traced tics in sync (%zu in the demo)\n",
              wad_file.c_str(), lump.c_str(), map_name.c_str(), demo.skill, demo.player_count(), s.tics_in_sync,
              s.traced, s.demo_tics);
  return s;
}

// FreeDM's own demos: three- and four-player altdeath games. Two are in the tree;
// P3D_FREEDM_TRACES=DIR plays all four beside the traces there (freedm_demoN.trace,
// made as tools/peers/netgame_trace.py says).
TEST(DemoSync, FreedmsAltdeathDemosPlayInSyncWithChocolateDoomForEveryPlayer) {
  const char* all = std::getenv("P3D_FREEDM_TRACES");
  for (int demo : all ? std::vector<int>{1, 2, 3, 4} : std::vector<int>{3, 4}) {
    const Sync s = all ? net_sync_of("freedm.wad", demo, all) : net_sync_of("freedm.wad", demo);
    EXPECT_EQ(s.traced, s.demo_tics) << "freedm DEMO" << demo << ": the trace covers the whole demo";
    EXPECT_EQ(s.tics_in_sync, s.demo_tics) << "freedm DEMO" << demo;
  }
}

}  // namespace
}  // namespace p3d::play
