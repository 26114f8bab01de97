// A Doom demo's bytes (.lmp): read, written back and read again the same, and its
// console player's moves played on a small level when accepted.
#include <cstdlib>

#include "engine/bsp/build.h"
#include "engine/map/source.h"
#include "engine/play/demo.h"
#include "engine/play/doom_demo.h"
#include "tests/fuzz/harness.h"
#include "tests/fuzz/target.h"

using namespace p3d;

P3D_FUZZ_TARGET(lmp) {
  static const level::Level level = bsp::build(map::load_map(fuzz::maps_dir() / "outpost.map"), {});
  try {
    const play::DoomDemo doom = play::decode_doom_demo(std::span(data, size), "fuzz.lmp");
    const play::DoomDemo again = play::decode_doom_demo(play::encode_doom_demo(doom), "again.lmp");
    if (again.commands != doom.commands || again.skill != doom.skill || again.map != doom.map) std::abort();
    const play::Demo demo = play::demo_from_doom(doom, level);
    play::GameOptions options;
    options.skill = demo.skill;
    options.fast = demo.fast;
    options.respawn = demo.respawn;
    options.no_monsters = demo.no_monsters;
    options.map = 0;
    play::World world(play::map_from_level(level), level, options, play::Random{});
    for (size_t t = 0; t < demo.tics.size() && t < 700; ++t) world.tick(demo.tics[t].cmd);
  } catch (const Error&) {
  }
  return 0;
}
