// A demo's bytes (checksum made right), replayed on a small level when accepted.
#include <cstring>

#include "engine/bsp/build.h"
#include "engine/map/source.h"
#include "engine/sim/demo.h"
#include "engine/util/bytes.h"
#include "tests/fuzz/harness.h"

using namespace p3d;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const level::Level level = bsp::build(map::load_map(fuzz::maps_dir() / "outpost.map"), {});
  if (size < 8) return 0;
  std::vector<uint8_t> bytes(data, data + size);
  const uint64_t checksum = fnv1a64(std::span(bytes).first(size - 8));
  std::memcpy(bytes.data() + size - 8, &checksum, 8);
  try {
    const sim::Demo demo = sim::decode_demo(bytes, "fuzz.demo");
    sim::World world(level, demo.skill);
    sim::Player p = world.spawn_at(demo.start, demo.angle);
    p.keys = demo.keys;
    for (size_t t = 0; t < demo.tics.size() && t < 700; ++t) world.tick(p, demo.tics[t]);
  } catch (const Error&) {
  }
  return 0;
}
