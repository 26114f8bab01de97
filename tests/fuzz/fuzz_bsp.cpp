// A compiled level's bytes. The header (magic, version, payload size) and the checksum
// are made right first, so the validation behind them is what gets exercised; what is
// accepted is drawn.
#include <cstring>

#include "engine/level/format.h"
#include "engine/level/io.h"
#include "engine/util/bytes.h"
#include "engine/util/checksum.h"
#include "tests/fuzz/harness.h"
#include "tests/fuzz/target.h"

using namespace p3d;

P3D_FUZZ_TARGET(bsp) {
  using level::format::kHeaderSize;
  if (size < kHeaderSize) return 0;
  std::vector<uint8_t> bytes(data, data + size);
  std::memcpy(bytes.data(), level::format::kMagic, 8);
  const uint32_t version = level::format::kVersion;
  std::memcpy(bytes.data() + 8, &version, 4);
  const uint64_t payload = size - kHeaderSize;
  std::memcpy(bytes.data() + 16, &payload, 8);
  const uint64_t checksum = checksum64(std::span(bytes).subspan(kHeaderSize));
  std::memcpy(bytes.data() + 24, &checksum, 8);
  try {
    fuzz::render_a_little(level::decode(bytes, "fuzz.bsp"));
  } catch (const Error&) {
  }
  return 0;
}
