// The small WAD map savegames are fuzzed on (fuzz_save.cpp) and its seed made on
// (tests/play/savegame_test.cpp): a room of the test art with a door, lights that flash
// and flicker, an imp, a barrel and the player.
#pragma once

#include "engine/wad/wad.h"
#include "tests/support/wad_writer.h"

namespace p3d::fuzz {

inline wad::Stack save_map_wads() {
  test::TestMap m;
  m.add_room({{0, 0}, {0, 512}, {512, 512}, {512, 0}}, {0, 128, "FLOOR", "CEIL", 160, 0, 0});
  m.add_room({{512, 192}, {512, 320}, {576, 320}, {576, 192}}, {0, 0, "FLOOR", "CEIL", 160, 10, 0});  // a door closing in 30 s
  m.add_room({{0, 512}, {0, 640}, {256, 640}, {256, 512}}, {0, 128, "FLOOR", "F_SKY1", 192, 1, 0});   // a flash
  m.add_room({{256, 512}, {256, 640}, {512, 640}, {512, 512}}, {0, 128, "NUKAGE1", "CEIL", 192, 17, 0});  // a flicker
  m.things = {{64, 64, 45, 1}, {400, 400, 225, 3001}, {256, 256, 0, 2035}};
  return test::test_stack({{"MAP01", m}});
}

}  // namespace p3d::fuzz
