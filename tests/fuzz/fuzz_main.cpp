// libFuzzer's entry points for the one binary of every target (target.h): the target is
// the one the program's name ends in (fuzz_map: "map"), else P3D_FUZZ_TARGET's.
#include <cstdio>
#include <cstdlib>
#include <string>

#include "tests/fuzz/target.h"

namespace {

p3d::fuzz::TestOneInput chosen = nullptr;

std::string wanted(const char* program) {
  if (const char* env = std::getenv("P3D_FUZZ_TARGET")) return env;
  std::string name = program;
  name = name.substr(name.find_last_of('/') + 1);
  const std::string prefix = "fuzz_";
  return name.rfind(prefix, 0) == 0 ? name.substr(prefix.size()) : "";
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv) {
  const std::string name = wanted(*argc > 0 ? (*argv)[0] : "");
  std::string names;
  for (const p3d::fuzz::Target& t : p3d::fuzz::targets()) {
    if (t.name == name) chosen = t.run;
    names += " " + t.name;
  }
  if (!chosen) {
    std::fprintf(stderr, "fuzz: no target '%s': run it as fuzz_NAME or with P3D_FUZZ_TARGET=NAME, NAME one of:%s\n",
                 name.c_str(), names.c_str());
    std::exit(2);
  }
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) { return chosen(data, size); }
