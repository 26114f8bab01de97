// Writing WAD files: a header, the lumps in order, the directory. Used to hand a
// single map to other Doom tools (bench gives ZDBSP one map to build).
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "engine/wad/wad.h"

namespace p3d::wad {

struct LumpToWrite {
  std::string name;  // at most 8 characters
  std::span<const uint8_t> bytes;
};

std::vector<uint8_t> write_wad(bool iwad, const std::vector<LumpToWrite>& lumps);

// A PWAD holding one binary-format map (its marker and its lumps), with the node
// lumps (SEGS, SSECTORS, NODES, REJECT, BLOCKMAP) empty for a node builder to fill.
std::vector<uint8_t> map_without_nodes(const MapLumps& map);

}  // namespace p3d::wad
