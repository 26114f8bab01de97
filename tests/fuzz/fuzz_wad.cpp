// A PWAD over a small IWAD of test art: its directory read, its first map imported
// (binary or UDMF), compiled, checked and drawn.
#include "engine/bsp/check.h"
#include "engine/bsp/load.h"
#include "tests/fuzz/harness.h"
#include "tests/fuzz/target.h"
#include "tests/support/wad_writer.h"

using namespace p3d;

P3D_FUZZ_TARGET(wad) {
  static const std::vector<uint8_t> art = [] {
    test::WadWriter w(true);
    test::add_test_art(w);
    return w.bytes();
  }();
  try {
    wad::Stack stack;
    stack.add(wad::Wad(art, "art.wad"));
    stack.add(wad::Wad(std::vector<uint8_t>(data, data + size), "fuzz.wad"));
    const std::vector<std::string> maps = stack.map_names();
    if (maps.empty()) return 0;
    const level::Level level = bsp::build_wad_map(stack, maps.front(), {}, nullptr);
    if (!bsp::check_invariants(level).empty()) __builtin_trap();
    fuzz::render_a_little(level);
  } catch (const Error&) {
  }
  return 0;
}
