// Where Doom puts things: the sector of the subsector its own nodes (the map's NODES,
// SSECTORS and SEGS, as a node builder left them) place a point in. A thing standing
// exactly on a line between two sectors stands on whichever floor Doom's tree says;
// our own tree may say the other. Used only to place things; the map is still
// compiled from its lines.
#pragma once

#include <optional>
#include <vector>

#include "engine/geom/geom.h"
#include "engine/wad/map_data.h"
#include "engine/wad/wad.h"

namespace p3d::wad {

// The sector index for each point, or nullopt when the map carries no vanilla nodes
// (none, extended ones, or ones that do not fit its lines and sides: stale or broken).
std::optional<std::vector<int>> sectors_by_doom_nodes(const MapLumps& lumps, const MapData& data,
                                                      const std::vector<geom::Vec2>& points);

}  // namespace p3d::wad
