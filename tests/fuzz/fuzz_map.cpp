// A .map text: parsed, then compiled and drawn as fuzz::compile_and_draw says.
#include "tests/fuzz/harness.h"
#include "tests/fuzz/target.h"

using namespace p3d;

P3D_FUZZ_TARGET(map) {
  try {
    const std::string text(reinterpret_cast<const char*>(data), size);
    fuzz::compile_and_draw(map::parse_map(text, fuzz::seeds_dir() / "fuzz.map"));
  } catch (const Error&) {
  }
  return 0;
}
