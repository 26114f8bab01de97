// A demo's bytes (checksum made right), replayed on a small level when accepted.
#include <cmath>
#include <cstring>

#include "engine/bsp/build.h"
#include "engine/map/source.h"
#include "engine/play/demo.h"
#include "engine/util/bytes.h"
#include "tests/fuzz/harness.h"
#include "tests/fuzz/target.h"

using namespace p3d;

P3D_FUZZ_TARGET(demo) {
  static const level::Level level = bsp::build(map::load_map(fuzz::maps_dir() / "outpost.map"), {});
  if (size < 8) return 0;
  std::vector<uint8_t> bytes(data, data + size);
  const uint64_t checksum = fnv1a64(std::span(bytes).first(size - 8));
  std::memcpy(bytes.data() + size - 8, &checksum, 8);
  try {
    const play::Demo demo = play::decode_demo(bytes, "fuzz.demo");
    play::GameOptions options;
    options.skill = demo.skill;
    options.fast = demo.fast;
    options.respawn = demo.respawn;
    options.no_monsters = demo.no_monsters;
    options.map = 0;
    play::World world(play::map_from_level(level), level, options, play::Random{});
    if (demo.custom_start) {  // decode_demo keeps the start within Doom's coordinates
      const double turns = std::fmod(demo.angle, 360.0) / 360.0 + 1;
      world.place_player(play::Fixed(std::llround(demo.start.x * play::kFracUnit)),
                         play::Fixed(std::llround(demo.start.y * play::kFracUnit)),
                         play::Angle(uint64_t(std::llround(turns * 4294967296.0))));
    }
    world.player().cards = demo.keys;
    for (size_t t = 0; t < demo.tics.size() && t < 700; ++t) {
      if (demo.tics[t].cheats) world.apply_cheats(demo.tics[t].cheats);
      world.tick(demo.tics[t].cmd);
    }
  } catch (const Error&) {
  }
  return 0;
}
