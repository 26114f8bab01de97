// Doom's own demos beside Chocolate Doom's play of them: the first 300 tics of the
// console player as Chocolate Doom left them after each tic (tests/golden/doom_demos,
// traced from its G_Ticker) against the simulation's. How many tics stay in sync is
// this project's measure of its way to Doom's rules; the floors below are what the
// simulation reaches today and may only rise.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "engine/bsp/load.h"
#include "engine/play/doom_demo.h"
#include "engine/sim/demo.h"
#include "tests/support/support.h"

namespace p3d::sim {
namespace {

struct TraceTic {
  int64_t x, y, z, angle, momx, momy, health, random_index, view_z;
};

std::vector<TraceTic> read_trace(const std::string& name) {
  std::ifstream in(test::source_dir() / "tests/golden/doom_demos" / name);
  std::vector<TraceTic> out;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    int64_t tic;
    TraceTic t;
    fields >> tic >> t.x >> t.y >> t.z >> t.angle >> t.momx >> t.momy >> t.health >> t.random_index >> t.view_z;
    out.push_back(t);
  }
  return out;
}

struct Sync {
  size_t position = 0, random = 0, traced = 0;
};

// Tics from the start in which the player stands where Doom's did (within 4/65536
// of a unit), and in which Doom's random stream stands at the same index.
Sync sync_of(const std::string& wad_file, int demo_number) {
  const auto wad = test::freedoom_path(wad_file);
  const wad::Stack wads = bsp::read_wads({wad});
  const std::string lump = "DEMO" + std::to_string(demo_number);
  const play::DoomDemo doom = play::decode_doom_demo(wads.find(lump)->bytes, lump);
  const std::string map = doom.map_name(wads.map("MAP01").has_value());
  const level::Level level = bsp::open_level(bsp::LevelSource{{}, {wad}, map}).level;
  World world(level, doom.skill);
  Player player = world.spawn();
  const Demo demo = demo_from_doom(doom, level);
  const std::vector<TraceTic> trace =
      read_trace(wad_file.substr(0, wad_file.find('.')) + "_demo" + std::to_string(demo_number) + ".trace");
  Sync s;
  s.traced = trace.size();
  bool position = true, random = true;
  for (size_t t = 0; t < trace.size() && t < demo.tics.size(); ++t) {
    world.tick(player, demo.tics[t]);
    const double off = std::hypot(player.pos.x - trace[t].x / 65536.0, player.pos.y - trace[t].y / 65536.0);
    position = position && off <= 4 / 65536.0;
    random = random && world.random_index() == trace[t].random_index;
    s.position += position;
    s.random += random;
  }
  std::printf("[ sync     ] %s %s %s skill %d: player %zu, random stream %zu of %zu traced tics (%zu in the demo)\n",
              wad_file.c_str(), lump.c_str(), map.c_str(), doom.skill, s.position, s.random, s.traced, doom.tic_count());
  return s;
}

TEST(DoomSync, FreedoomDemosStayInSyncAtLeastAsFarAsToday) {
  struct Floor {
    const char* wad;
    int demo;
    size_t position, random;
  };
  // Spawning draws Doom's random numbers as Doom's P_SpawnMapThing and P_SpawnSpecials
  // do, so the stream is in step from the first tic on every demo; it parts when a
  // monster wakes or the player fires. The player parts where the movement's floating
  // point first differs from Doom's fixed point.
  for (const Floor& f : {Floor{"freedoom1.wad", 1, 33, 91}, Floor{"freedoom1.wad", 2, 17, 63},
                         Floor{"freedoom1.wad", 3, 19, 35}, Floor{"freedoom1.wad", 4, 34, 3},
                         Floor{"freedoom2.wad", 1, 37, 61}, Floor{"freedoom2.wad", 2, 43, 8},
                         Floor{"freedoom2.wad", 3, 27, 192}, Floor{"freedoom2.wad", 4, 3, 21}}) {
    const Sync s = sync_of(f.wad, f.demo);
    EXPECT_EQ(s.traced, 300u);
    EXPECT_GE(s.position, f.position) << f.wad << " DEMO" << f.demo;
    EXPECT_GE(s.random, f.random) << f.wad << " DEMO" << f.demo;
    EXPECT_GE(s.random, 1u) << "the stream is in step after the first tic";
  }
}

}  // namespace
}  // namespace p3d::sim
