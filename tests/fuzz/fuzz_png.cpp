// A texture file's bytes.
#include "engine/image/image.h"
#include "engine/util/error.h"

using namespace p3d;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    image::decode_png(std::span(data, size), "fuzz.png");
  } catch (const Error&) {
  }
  return 0;
}
