// A texture file's bytes.
#include "engine/image/image.h"
#include "engine/util/error.h"
#include "tests/fuzz/target.h"

using namespace p3d;

P3D_FUZZ_TARGET(png) {
  try {
    image::decode_png(std::span(data, size), "fuzz.png");
  } catch (const Error&) {
  }
  return 0;
}
