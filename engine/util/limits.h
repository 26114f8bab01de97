// The project's limits, in one place: the parsers, the importer, the compiler's
// writer and the reader all apply these, so nothing is written that cannot be read.
// (Coordinates: geom::kMaxCoord.)
#pragma once

#include <cstddef>

namespace p3d::limits {

constexpr int kMaxTextureSize = 4096;    // texels per side
constexpr size_t kMaxNameLength = 256;   // texture, sector and vertex names
constexpr size_t kMaxTitleLength = 1024;
constexpr int kMaxGridSide = 4096;       // tiles per side of a .grid map
constexpr double kMaxOffset = 1 << 21;   // texture offsets, map units (as coordinates: the texture arithmetic is sized for it)
constexpr double kMinGridCell = 1;       // map units per tile
constexpr size_t kMaxFileBytes = size_t{1} << 31;  // any input file: 2 GiB
// Walls of one level (Doom's own format holds 65,535): compiling that many takes about
// 2.5 GB of memory, so a larger level is refused as its walls are read, not after
// the machine runs out of memory. The .bsp reader holds files to it too.
constexpr size_t kMaxWalls = size_t{1} << 21;
inline const char* too_many_walls() { return "more walls than a level may have (2,097,152)"; }

// Paletted art (WAD levels): a 256-colour palette and Doom's 32 light maps over it,
// stored with Doom's invulnerability map after them (COLORMAP's 33rd).
constexpr int kPaletteSize = 256;
constexpr int kLightMaps = 32;
constexpr int kInverseMap = kLightMaps;
constexpr int kStoredMaps = kLightMaps + 1;

}  // namespace p3d::limits
