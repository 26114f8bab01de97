// The fuzz targets live in one binary (their headers compiled once, not once a
// target): each file names its target with P3D_FUZZ_TARGET(name) { body over data, size }
// and the binary runs the one its name says (build-sanitize/tests/fuzz/fuzz_NAME, a link
// to it) or P3D_FUZZ_TARGET names (fuzz_main.cpp).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace p3d::fuzz {

using TestOneInput = int (*)(const uint8_t* data, size_t size);

struct Target {
  std::string name;
  TestOneInput run;
};

inline std::vector<Target>& targets() {
  static std::vector<Target> all;
  return all;
}

inline bool add_target(const char* name, TestOneInput run) {
  targets().push_back({name, run});
  return true;
}

}  // namespace p3d::fuzz

#define P3D_FUZZ_TARGET(name)                                                                           \
  static int fuzz_one_##name(const uint8_t* data, size_t size);                                         \
  [[maybe_unused]] static const bool fuzz_target_##name = p3d::fuzz::add_target(#name, fuzz_one_##name); \
  static int fuzz_one_##name(const uint8_t* data, size_t size)
