// What Doom draws from beyond a map's lines and the composed textures, for drawing by
// Doom's rules. Doom's segs: where the WAD's node builder cut each
// LINEDEF side (its SEGS, over VERTEXES with the split points it rounded to whole
// units), attached to the compiled level's walls (Level::doom_segs). Doom measures a
// wall's texture columns and distance from each seg's first vertex, so a wall cut in
// two can show its texture a texel apart across the cut; drawing from these segs
// shows it as Doom does. Our own BSP is not touched. Doom's wall columns: the bytes
// R_DrawColumn reads for each texture column (see Level::doom_columns).
#pragma once

#include "engine/level/level.h"
#include "engine/wad/wad.h"

namespace p3d::wad {

class ArtCache;

// Fills level.doom_segs from the map's SEGS and VERTEXES when they are vanilla's and
// fit its LINEDEFS (a wall's `source` is its LINEDEF); leaves them empty otherwise.
void attach_doom_segs(const MapLumps& lumps, level::Level& level);

// Fills level.doom_column_start and doom_columns: Doom's 128-row columns of each of the
// level's wall textures (a texture of the WADs' TEXTURE1/2 by its name and size). With
// a cache for these WADs, each texture's columns are made once for every map.
void attach_doom_columns(const Stack& wads, level::Level& level, ArtCache* cache = nullptr);

// Both, for map `map` of the WADs.
void attach_doom_data(const Stack& wads, const std::string& map, level::Level& level, ArtCache* cache = nullptr);

}  // namespace p3d::wad
