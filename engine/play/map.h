// A level as Doom's play simulation sees it: Doom's own records in 16.16 fixed point
// (vertices, lines, sides, sectors, things), with the node tree, blockmap and reject
// table as the map's lumps give them, or built where a map lacks them. Doom's
// outcomes depend on these exactly: the order the blockmap lists lines in, which
// subsector a point falls in, which sectors the reject table says cannot see each
// other. The sectors, sides and lines also carry what play changes (heights, light,
// textures, specials): the World owns its Map.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "engine/level/level.h"
#include "engine/play/angle.h"
#include "engine/play/fixed.h"
#include "engine/wad/map_data.h"
#include "engine/wad/wad.h"

namespace p3d::play {

struct Mobj;
struct Thinker;

// Doom's bounding boxes: top, bottom, left, right.
enum BoxEdge { kBoxTop, kBoxBottom, kBoxLeft, kBoxRight };
using Box = std::array<Fixed, 4>;
inline void clear_box(Box& b) {
  b[kBoxTop] = b[kBoxRight] = std::numeric_limits<Fixed>::min();
  b[kBoxBottom] = b[kBoxLeft] = std::numeric_limits<Fixed>::max();
}
inline void add_to_box(Box& b, Fixed x, Fixed y) {
  if (x < b[kBoxLeft]) b[kBoxLeft] = x;
  else if (x > b[kBoxRight]) b[kBoxRight] = x;
  if (y < b[kBoxBottom]) b[kBoxBottom] = y;
  else if (y > b[kBoxTop]) b[kBoxTop] = y;
}

// Doom's line flags (as wad::LineFlag).
enum LineFlags : int {
  kMlBlocking = 1,
  kMlBlockMonsters = 2,
  kMlTwoSided = 4,
  kMlDontPegTop = 8,
  kMlDontPegBottom = 16,
  kMlSecret = 32,
  kMlSoundBlock = 64,
  kMlDontDraw = 128,
  kMlMapped = 256,
};

struct Vertex {
  Fixed x = 0, y = 0;
};

struct Line;

struct Sector {
  Fixed floor_height = 0, ceiling_height = 0;
  int floor_pic = level::kNone, ceiling_pic = level::kNone;  // level texture indices (or level::kSky)
  int light = 0, special = 0, tag = 0;
  int sound_traversed = 0;      // 0: not reached by the noise being spread; else 1 + blocking lines crossed
  Mobj* sound_target = nullptr; // the thing that made the last noise heard here
  std::array<int, 4> block_box{};  // the sector's lines' box in blockmap cells
  Fixed sound_x = 0, sound_y = 0;  // where its sounds come from (Doom's soundorg)
  int valid_count = 0;
  Mobj* thing_list = nullptr;
  Thinker* special_data = nullptr;  // the mover working on it, if any
  std::vector<Line*> lines;
  int index = 0;
};

struct Side {
  Fixed texture_offset = 0, row_offset = 0;
  int top = level::kNone, bottom = level::kNone, middle = level::kNone;  // level texture indices
  Sector* sector = nullptr;
};

enum class Slope : uint8_t { kHorizontal, kVertical, kPositive, kNegative };

// (Ordered so that what a collision check reads first shares a cache line; Doom's
// validcount mark is kept apart, in Map::line_marks.)
struct Line {
  Box bbox{};
  Slope slope = Slope::kHorizontal;
  int flags = 0;
  Fixed dx = 0, dy = 0;
  Vertex *v1 = nullptr, *v2 = nullptr;
  Sector *front = nullptr, *back = nullptr;
  int special = 0, tag = 0;
  std::array<int, 2> side{-1, -1};  // front, back: indices into Map::sides
  int index = 0;
};

struct Seg {
  Vertex *v1 = nullptr, *v2 = nullptr;
  Fixed offset = 0;
  Angle angle = 0;
  Side* side = nullptr;
  Line* line = nullptr;
  Sector *front = nullptr, *back = nullptr;
};

struct Subsector {
  Sector* sector = nullptr;
  int line_count = 0, first_line = 0;  // its segs
};

// A node of the map's tree: its partition line and children (the boxes, which only
// Doom's renderer reads, are not kept: descents stay in fewer cache lines).
struct Node {
  Fixed x = 0, y = 0, dx = 0, dy = 0;
  std::array<uint16_t, 2> children{};  // kSubsectorBit: a subsector
  static constexpr uint16_t kSubsectorBit = 0x8000;
};

// A placed thing as the map states it (Doom's mapthing_t).
struct MapThing {
  int16_t x = 0, y = 0, angle = 0, type = 0, options = 0;
  int32_t placed = -1;  // the level's thing it is (Level::things), or -1
};

constexpr int kMapBlockShift = kFracBits + 7;  // 128-unit cells
constexpr Fixed kMapBlockSize = 128 * kFracUnit;

struct Blockmap {
  Fixed origin_x = 0, origin_y = 0;
  int width = 0, height = 0;
  // Each cell's list of line numbers, as the lump lists them (each opening with a 0,
  // which Doom walks as line 0, as node builders write them), ending with kEnd; in 32
  // bits, so that levels beyond Doom's 64K words and lines fit.
  std::vector<uint32_t> offsets;  // per cell (x + y * width): where its list starts in `lists`
  std::vector<uint32_t> lists;
  static constexpr uint32_t kEnd = 0xFFFFFFFF;
  // Cell number `cell`'s list (x + y * width). Every entry is a valid line number
  // (read_blockmap checks, build_blockmap makes them so).
  const uint32_t* list(size_t cell) const { return lists.data() + offsets[cell]; }
};

struct Map {
  std::string where;  // "<wad>:<map>" for messages
  std::vector<Vertex> vertices;
  std::vector<Sector> sectors;
  std::vector<Side> sides;
  std::vector<Line> lines;
  // Per line, Doom's validcount mark: the last search that reached it (dense, so that
  // lines met again in other cells cost no visit to the line itself).
  std::vector<int> line_marks;
  std::vector<Seg> segs;
  std::vector<Subsector> subsectors;
  std::vector<Node> nodes;
  std::vector<MapThing> things;
  Blockmap blockmap;
  std::vector<uint8_t> reject;  // sectors^2 bits, padded with zeros (nothing rejected) if short
  // Without Doom's nodes (a map built from a Level, or a WAD whose nodes do not fit its
  // lines): points are located in this level's own tree, whose leaves become subsectors.
  const level::Level* located_by = nullptr;
  std::vector<int> wall_lines;  // located_by: the Map line of each level wall

  bool has_nodes() const { return !nodes.empty() && located_by == nullptr; }
  // Where point_in_subsector's descent may start for the points of each 32-unit cell
  // of the blockmap's area: the deepest node (or subsector) every point of the cell
  // reaches from the root, so starting there gives exactly the root's answer in fewer
  // steps. Built by index_cells.
  static constexpr int kCellShift = kFracBits + 5;
  // The cells' own origin: the blockmap's may change as the level is played (an
  // intercepts overrun, World::overrun_intercepts), the nodes' answers may not.
  std::vector<uint16_t> cell_start;
  Fixed cell_origin_x = 0, cell_origin_y = 0;
  int cell_columns = 0, cell_rows = 0;
  void index_cells();
  // Doom's R_PointInSubsector.
  Subsector* point_in_subsector(Fixed x, Fixed y);
  // Doom's reject table: true when sector a's things can never see sector b's.
  bool rejected(int a, int b) const {
    const size_t bit = size_t(a) * sectors.size() + size_t(b);
    return (reject[bit >> 3] >> (bit & 7)) & 1;
  }
};

// Doom's map from a WAD map's records and lumps (its BLOCKMAP, REJECT, NODES, SSECTORS,
// SEGS when present and sound; else built, or located by `level`'s tree). Textures
// and flats are `level`'s (a level compiled from the same map: its sectors are the
// map's, and each line's walls carry the line's number as their source).
Map map_from_wad(const wad::MapData& data, const wad::MapLumps* lumps, const level::Level& level);
// Doom's map of any level (.map, .grid, or a compiled WAD level without its lumps): a
// line per wall, its sectors, a blockmap built from the walls, nothing rejected, points
// located in the level's own tree.
Map map_from_level(const level::Level& level);

// The same for map `name` of a WAD stack (the level compiled from it gives the art).
// Throws Error when the WADs lack the map or its records are broken.
Map map_from_wads(const wad::Stack& wads, const std::string& name, const level::Level& level);

// A blockmap for these lines as Doom's node builders make one (each list in line order,
// opening with line 0's number).
Blockmap build_blockmap(const std::vector<Line>& lines, const std::vector<Vertex>& vertices);

}  // namespace p3d::play
