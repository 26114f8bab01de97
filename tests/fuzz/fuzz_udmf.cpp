// A UDMF TEXTMAP's text.
#include "engine/wad/map_data.h"
#include "engine/util/error.h"
#include "tests/fuzz/target.h"

using namespace p3d;

P3D_FUZZ_TARGET(udmf) {
  try {
    wad::parse_udmf(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz:TEXTMAP");
  } catch (const Error&) {
  }
  return 0;
}
