// A savegame's bytes (Doom's format with our extension) loaded onto a small WAD map, as
// Doom would and with our extension: refused with an Error, or accepted, played a
// second and saved, the save loading back to the same save.
#include <cstdlib>

#include "engine/bsp/load.h"
#include "engine/play/savegame.h"
#include "tests/fuzz/harness.h"
#include "tests/fuzz/target.h"
#include "tests/fuzz/save_map.h"

using namespace p3d;

P3D_FUZZ_TARGET(save) {
  static const wad::Stack wads = fuzz::save_map_wads();
  static const level::Level level = bsp::build_wad_map(wads, "MAP01", {}, nullptr);
  static const play::DoomNumbers numbers(wads, level);
  static const play::GameOptions options = play::game_options_for(wads, "MAP01", 3);
  static const play::World before(play::map_from_wads(wads, "MAP01", level), level, options, play::Random{});
  const std::span<const uint8_t> bytes(data, size);
  (void)play::save_description(bytes);
  for (bool doom_only : {false, true}) {
    try {
      const play::SaveHeader header = play::read_save_header(bytes, "fuzz.dsg");
      play::World world(play::map_from_wads(wads, "MAP01", level), level, options, play::Random{});
      play::carry_over(world, before, header);
      play::read_save(world, bytes, "fuzz.dsg", numbers, doom_only);
      for (int t = 0; t < 35; ++t) world.tick(play::TicCmd{25, 0, 256, uint8_t(t % 2 ? play::kBtUse : play::kBtAttack)});
      (void)world.state();
      const std::vector<uint8_t> again = play::write_save(world, numbers, "again", {});
      play::World back(play::map_from_wads(wads, "MAP01", level), level, options, play::Random{});
      play::carry_over(back, world, play::read_save_header(again, "again.dsg"));
      play::read_save(back, again, "again.dsg", numbers);
      if (play::write_save(back, numbers, "again", {}) != again) std::abort();  // our saves load back whole
    } catch (const Error&) {
    }
  }
  return 0;
}
