// Opening a level by path: a compiled .bsp is read (and validated); a .map or
// .grid source is compiled on the fly with the given options.
#pragma once

#include <filesystem>

#include "engine/bsp/build.h"

namespace p3d::bsp {

bool is_source_path(const std::filesystem::path& path);  // .map or .grid
level::Level load_level(const std::filesystem::path& path, const Options& options = {});

}  // namespace p3d::bsp
