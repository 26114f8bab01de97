#include "engine/bsp/load.h"

#include "engine/level/io.h"

namespace p3d::bsp {

bool is_source_path(const std::filesystem::path& path) {
  return path.extension() == ".map" || path.extension() == ".grid";
}

level::Level load_level(const std::filesystem::path& path, const Options& options) {
  if (!is_source_path(path)) return level::read(path);
  return build(map::load_source(path), options);
}

}  // namespace p3d::bsp
