// A UDMF TEXTMAP's text.
#include "engine/wad/map_data.h"
#include "engine/util/error.h"

using namespace p3d;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    wad::parse_udmf(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz:TEXTMAP");
  } catch (const Error&) {
  }
  return 0;
}
