// A .grid tile map: parsed, validated, compiled, checked, written, read back, drawn.
#include "engine/bsp/build.h"
#include "engine/bsp/check.h"
#include "engine/level/io.h"
#include "engine/map/source.h"
#include "tests/fuzz/harness.h"

using namespace p3d;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    const map::Source src = map::parse_grid(std::string(reinterpret_cast<const char*>(data), size), fuzz::seeds_dir() / "fuzz.grid");
    map::validate(src);
    const level::Level level = bsp::build(src, {});
    if (!bsp::check_invariants(level).empty()) __builtin_trap();                  // the compiler's promise
    const level::Level back = level::decode(level::encode(level), "round trip");  // never writes what it cannot read
    fuzz::render_a_little(back);
  } catch (const Error&) {
  }
  return 0;
}
