// bench play: Doom's rules timed on every Freedoom map and Doom's own demos.
#pragma once

#include <string>

namespace p3d::bench {

void bench_play(int skill, const std::string& source_dir);

}  // namespace p3d::bench
