// A WAD map's records as the file states them, before any repair: Doom's binary
// lumps (THINGS, LINEDEFS, SIDEDEFS, VERTEXES, SECTORS; node lumps are ignored,
// the compiler builds its own tree) and UDMF's TEXTMAP both decode to this.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "engine/map/source.h"
#include "engine/wad/wad.h"

namespace p3d::wad {

constexpr int kNoSide = -1;

// The sizes of Doom's binary map lumps' records, in bytes.
constexpr size_t kThingRecord = 10, kLinedefRecord = 14, kSidedefRecord = 30, kVertexRecord = 4, kSectorRecord = 26,
                 kSegRecord = 12, kSubsectorRecord = 4, kNodeRecord = 28;

// Doom's linedef flags (the binary format's bits; UDMF's booleans map onto them).
enum LineFlag : uint32_t {
  kLineBlocking = 1,
  kLineBlockMonsters = 2,
  kLineTwoSided = 4,
  kLineUnpegUpper = 8,
  kLineUnpegLower = 16,
  kLineSecret = 32,
  kLineBlockSound = 64,
  kLineHidden = 128,  // never on the automap
  kLineMapped = 256,  // on the automap from the start
};

struct MapVertex {
  double x = 0, y = 0;
};

struct MapLinedef {
  int v1 = 0, v2 = 0;
  uint32_t flags = 0;
  int special = 0, tag = 0;
  int front = kNoSide, back = kNoSide;  // sidedef indices
};

struct MapSidedef {
  double x_offset = 0, y_offset = 0;
  double part_x[3] = {0, 0, 0}, part_y[3] = {0, 0, 0};  // UDMF's per-part offsets: upper, middle, lower
  std::string upper = "-", lower = "-", middle = "-";
  int sector = 0;
  int light = 0;                // UDMF (zdoom): added to the sector's light, or replacing it
  bool light_absolute = false;
};

struct MapSector {
  double floor = 0, ceiling = 0;
  std::string floor_flat, ceiling_flat;
  int light = 160;
  int special = 0, tag = 0;
};

struct MapThing {
  double x = 0, y = 0;
  double angle = 0;  // degrees, counter-clockwise from east
  int type = 0;
  uint32_t flags = 0;  // doom::ThingFlags
};

struct MapData {
  std::string where;  // "<wad>:<map>", the prefix of every message about this map
  std::string name;   // MAP01, E1M1
  bool udmf = false;
  std::vector<MapVertex> vertices;
  std::vector<MapLinedef> linedefs;
  std::vector<MapSidedef> sidedefs;
  std::vector<MapSector> sectors;
  std::vector<MapThing> things;
};

// Decodes a map in either format. Throws Error("<wad>:<map>: LUMP: ...") when a lump
// is missing, its size is not a whole number of records, a linedef names a vertex
// that does not exist, or the TEXTMAP does not parse. Other inconsistencies are
// kept as stated, for the importer to repair (engine/wad/import.h).
MapData read_map(const MapLumps& lumps);

// The two formats (read_map picks one).
MapData read_binary_map(const MapLumps& lumps);
MapData parse_udmf(std::string_view text, const std::string& where);

}  // namespace p3d::wad
