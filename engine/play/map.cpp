// Doom's map for the rules: records converted to 16.16 as Doom's P_SetupLevel does
// (P_LoadVertexes ... P_GroupLines), the map's own node lumps, blockmap and reject
// table where they are present and sound, our substitutes where not.
#include "engine/play/map.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <unordered_map>

#include "engine/util/bytes.h"
#include "engine/util/error.h"

namespace p3d::play {

namespace {

constexpr size_t kNodeRecord = 28, kSubsectorRecord = 4, kSegRecord = 12;

Fixed units_to_fixed(double units) { return Fixed(std::llround(units * kFracUnit)); }

void derive_line(Line& ld) {
  ld.dx = wrap_sub(ld.v2->x, ld.v1->x);
  ld.dy = wrap_sub(ld.v2->y, ld.v1->y);
  if (!ld.dx)
    ld.slope = Slope::kVertical;
  else if (!ld.dy)
    ld.slope = Slope::kHorizontal;
  else
    ld.slope = fixed_div(ld.dy, ld.dx) > 0 ? Slope::kPositive : Slope::kNegative;
  ld.bbox[kBoxLeft] = std::min(ld.v1->x, ld.v2->x);
  ld.bbox[kBoxRight] = ld.v1->x < ld.v2->x ? ld.v2->x : ld.v1->x;
  ld.bbox[kBoxBottom] = std::min(ld.v1->y, ld.v2->y);
  ld.bbox[kBoxTop] = ld.v1->y < ld.v2->y ? ld.v2->y : ld.v1->y;
}

// Doom's P_GroupLines: each sector's lines (in line order), its sound origin and its
// box in blockmap cells.
void group_lines(Map& m) {
  for (Line& ld : m.lines) {
    ld.front->lines.push_back(&ld);
    if (ld.back && ld.back != ld.front) ld.back->lines.push_back(&ld);
  }
  const Blockmap& bm = m.blockmap;
  for (Sector& s : m.sectors) {
    Box box;
    clear_box(box);
    for (const Line* li : s.lines) {
      add_to_box(box, li->v1->x, li->v1->y);
      add_to_box(box, li->v2->x, li->v2->y);
    }
    // Doom's sums, overflowing as its ints did.
    s.sound_x = Fixed(int64_t(wrap_add(box[kBoxRight], box[kBoxLeft])) / 2);
    s.sound_y = Fixed(int64_t(wrap_add(box[kBoxTop], box[kBoxBottom])) / 2);
    if (s.lines.empty()) s.sound_x = s.sound_y = 0;
    const Fixed r = 32 * kFracUnit;  // Doom's MAXRADIUS
    int block = wrap_add(wrap_sub(box[kBoxTop], bm.origin_y), r) >> kMapBlockShift;
    s.block_box[kBoxTop] = block >= bm.height ? bm.height - 1 : block;
    block = wrap_sub(wrap_sub(box[kBoxBottom], bm.origin_y), r) >> kMapBlockShift;
    s.block_box[kBoxBottom] = block < 0 ? 0 : block;
    block = wrap_add(wrap_sub(box[kBoxRight], bm.origin_x), r) >> kMapBlockShift;
    s.block_box[kBoxRight] = block >= bm.width ? bm.width - 1 : block;
    block = wrap_sub(wrap_sub(box[kBoxLeft], bm.origin_x), r) >> kMapBlockShift;
    s.block_box[kBoxLeft] = block < 0 ? 0 : block;
  }
}

// The map's BLOCKMAP if it is whole: a header, an offset per cell, lists inside the lump
// ending with 0xFFFF, every entry a line of the map.
std::optional<Blockmap> read_blockmap(const wad::Lump* lump, size_t line_count) {
  if (!lump || lump->bytes.size() < 8 || lump->bytes.size() % 2) return std::nullopt;
  std::vector<uint16_t> words(lump->bytes.size() / 2);
  for (size_t i = 0; i < words.size(); ++i) words[i] = uint16_t(lump->bytes[2 * i] | lump->bytes[2 * i + 1] << 8);
  Blockmap bm;
  bm.origin_x = int32_t(int16_t(words[0])) << kFracBits;
  bm.origin_y = int32_t(int16_t(words[1])) << kFracBits;
  bm.width = words[2];
  bm.height = words[3];
  constexpr size_t kHeaderWords = 4;
  const size_t cells = size_t(bm.width) * size_t(bm.height);
  if (cells == 0 || kHeaderWords + cells > words.size()) return std::nullopt;
  std::unordered_map<size_t, uint32_t> copied;  // a list's place in the lump -> in `lists` (cells share lists)
  for (size_t c = 0; c < cells; ++c) {
    const size_t start = words[kHeaderWords + c];
    if (const auto it = copied.find(start); it != copied.end()) {
      bm.offsets.push_back(it->second);
      continue;
    }
    const uint32_t at_list = uint32_t(bm.lists.size());
    size_t at = start;
    for (; at < words.size() && words[at] != 0xFFFF; ++at) {
      if (words[at] >= line_count) return std::nullopt;
      bm.lists.push_back(words[at]);
    }
    if (at >= words.size()) return std::nullopt;  // a list running off the lump
    bm.lists.push_back(Blockmap::kEnd);
    copied.emplace(start, at_list);
    bm.offsets.push_back(at_list);
  }
  return bm;
}

// The map's NODES, SSECTORS and SEGS if they are vanilla's and fit its lines: every
// child, seg, vertex and line in range, children before their parents (no cycles).
bool read_nodes(const wad::MapLumps& lumps, Map& m) {
  const wad::Lump *nodes = lumps.find("NODES"), *subsectors = lumps.find("SSECTORS"), *segs = lumps.find("SEGS");
  if (!nodes || !subsectors || !segs || nodes->bytes.size() % kNodeRecord || subsectors->bytes.empty() ||
      subsectors->bytes.size() % kSubsectorRecord || segs->bytes.empty() || segs->bytes.size() % kSegRecord)
    return false;
  ByteReader in(segs->bytes, "SEGS");
  m.segs.resize(segs->bytes.size() / kSegRecord);
  for (Seg& seg : m.segs) {
    const uint16_t v1 = in.u16(), v2 = in.u16();
    const int16_t angle = int16_t(in.u16());
    const uint16_t line = in.u16();
    const int16_t side = int16_t(in.u16()), offset = int16_t(in.u16());
    if (v1 >= m.vertices.size() || v2 >= m.vertices.size() || line >= m.lines.size() || (side != 0 && side != 1))
      return false;
    Line& ld = m.lines[line];
    if (ld.side[side] < 0) return false;
    seg.v1 = &m.vertices[v1];
    seg.v2 = &m.vertices[v2];
    seg.angle = Angle(uint32_t(uint16_t(angle)) << 16);
    seg.offset = int32_t(offset) << kFracBits;
    seg.line = &ld;
    seg.side = &m.sides[size_t(ld.side[side])];
    seg.front = seg.side->sector;
    seg.back = (ld.flags & kMlTwoSided) && ld.side[side ^ 1] >= 0 ? m.sides[size_t(ld.side[side ^ 1])].sector : nullptr;
  }
  ByteReader ss(subsectors->bytes, "SSECTORS");
  m.subsectors.resize(subsectors->bytes.size() / kSubsectorRecord);
  for (Subsector& s : m.subsectors) {
    s.line_count = ss.u16();
    s.first_line = ss.u16();
    if (s.line_count == 0 || size_t(s.first_line) + size_t(s.line_count) > m.segs.size()) return false;
    s.sector = m.segs[size_t(s.first_line)].side->sector;
  }
  ByteReader nd(nodes->bytes, "NODES");
  m.nodes.resize(nodes->bytes.size() / kNodeRecord);
  for (size_t i = 0; i < m.nodes.size(); ++i) {
    Node& n = m.nodes[i];
    n.x = int32_t(int16_t(nd.u16())) << kFracBits;
    n.y = int32_t(int16_t(nd.u16())) << kFracBits;
    n.dx = int32_t(int16_t(nd.u16())) << kFracBits;
    n.dy = int32_t(int16_t(nd.u16())) << kFracBits;
    nd.raw(16);  // the children's boxes
    for (uint16_t& c : n.children) {
      c = nd.u16();
      const bool leaf = c & Node::kSubsectorBit;
      const size_t target = c & ~Node::kSubsectorBit;
      if (leaf ? target >= m.subsectors.size() : target >= i) return false;
    }
  }
  return true;
}

// Doom's R_PointOnSide.
int point_on_node_side(Fixed x, Fixed y, const Node& node) {
  if (!node.dx) return x <= node.x ? node.dy > 0 : node.dy < 0;
  if (!node.dy) return y <= node.y ? node.dx < 0 : node.dx > 0;
  const Fixed dx = wrap_sub(x, node.x), dy = wrap_sub(y, node.y);
  if ((node.dy ^ node.dx ^ dx ^ dy) & Fixed(0x80000000)) return (node.dy ^ dx) & Fixed(0x80000000) ? 1 : 0;
  const Fixed left = fixed_mul(node.dy >> kFracBits, dx), right = fixed_mul(dy, node.dx >> kFracBits);
  return right < left ? 0 : 1;
}

// Subsectors standing for the level's leaves, when points are located in its tree.
void leaves_as_subsectors(Map& m, const level::Level& level) {
  m.located_by = &level;
  m.nodes.clear();
  m.segs.clear();
  m.subsectors.assign(level.leaves.size(), {});
  for (size_t i = 0; i < level.leaves.size(); ++i) {
    const int s = level.leaves[i].sector;
    m.subsectors[i].sector = &m.sectors[size_t(s >= 0 && size_t(s) < m.sectors.size() ? s : 0)];
  }
}

// A reject table of the map's size: the lump's bytes, zeros (nothing rejected) after them.
std::vector<uint8_t> reject_table(const wad::Lump* lump, size_t sectors) {
  std::vector<uint8_t> table((sectors * sectors + 7) / 8, 0);
  if (lump) std::copy_n(lump->bytes.begin(), std::min(table.size(), lump->bytes.size()), table.begin());
  return table;
}

// A WAD map's reject table as Doom reads it. Where the lump is shorter than the map
// needs (node builders may leave it empty), Doom read on into the zone memory after it:
// the header of the block P_GroupLines allocated next (its size, from the sectors' line
// lists; its tag, PU_LEVEL; the zone's id), then, as Chocolate Doom has it, zeros.
std::vector<uint8_t> doom_reject_table(const wad::Lump* lump, const Map& m) {
  std::vector<uint8_t> table = reject_table(lump, m.sectors.size());
  const size_t from = lump ? lump->bytes.size() : 0;
  if (from >= table.size()) return table;
  uint32_t line_refs = 0;  // Doom's totallines
  for (const Line& ld : m.lines) line_refs += ld.back && ld.back != ld.front ? 2 : 1;
  const uint32_t pad[4] = {((line_refs * 4 + 3) & ~3u) + 24, 0, 50, 0x1d4a11};
  for (size_t i = 0; i < 16 && from + i < table.size(); ++i) table[from + i] = uint8_t(pad[i / 4] >> (8 * (i % 4)));
  return table;
}

// The side of the node the cell's points are all on (0 or 1), or -1 when they differ or
// might: Doom's side test is monotone in x and in y within a quadrant around the
// node's origin, so a cell inside one quadrant has its sides' extremes at its corners.
int cell_side(const Node& node, Fixed x0, Fixed y0, Fixed x1, Fixed y1) {
  if (!node.dx) return x1 <= node.x ? node.dy > 0 : x0 > node.x ? node.dy < 0 : -1;
  if (!node.dy) return y1 <= node.y ? node.dx < 0 : y0 > node.y ? node.dx > 0 : -1;
  const bool x_split = (int64_t(x0) - node.x < 0) != (int64_t(x1) - node.x < 0);
  const bool y_split = (int64_t(y0) - node.y < 0) != (int64_t(y1) - node.y < 0);
  if (x_split || y_split) return -1;
  const int side = point_on_node_side(x0, y0, node);
  for (const auto& [x, y] : {std::pair{x1, y0}, {x0, y1}, {x1, y1}})
    if (point_on_node_side(x, y, node) != side) return -1;
  return side;
}

}  // namespace

void Map::index_cells() {
  cell_start.clear();
  if (!has_nodes()) return;
  const uint16_t root = uint16_t(nodes.size() - 1);
  cell_origin_x = blockmap.origin_x;
  cell_origin_y = blockmap.origin_y;
  cell_columns = blockmap.width << (kMapBlockShift - kCellShift);
  cell_rows = blockmap.height << (kMapBlockShift - kCellShift);
  cell_start.assign(size_t(cell_columns) * size_t(cell_rows), root);
  for (int by = 0; by < cell_rows; ++by)
    for (int bx = 0; bx < cell_columns; ++bx) {
      const int64_t x0 = int64_t(cell_origin_x) + (int64_t(bx) << kCellShift);
      const int64_t y0 = int64_t(cell_origin_y) + (int64_t(by) << kCellShift);
      const int64_t x1 = x0 + (int64_t(1) << kCellShift) - 1, y1 = y0 + (int64_t(1) << kCellShift) - 1;
      if (x1 > INT32_MAX || y1 > INT32_MAX) continue;  // beyond Doom's coordinates: from the root
      uint16_t n = root;
      while (!(n & Node::kSubsectorBit)) {
        const int side = cell_side(nodes[n], Fixed(x0), Fixed(y0), Fixed(x1), Fixed(y1));
        if (side < 0) break;
        n = nodes[n].children[size_t(side)];
      }
      cell_start[size_t(by) * size_t(cell_columns) + size_t(bx)] = n;
    }
}

Subsector* Map::point_in_subsector(Fixed x, Fixed y) {
  if (located_by) {
    if (subsectors.empty()) return nullptr;
    return &subsectors[size_t(located_by->leaf_at({to_double(x), to_double(y)}))];
  }
  if (nodes.empty()) return &subsectors[0];
  uint16_t n = uint16_t(nodes.size() - 1);
  const int64_t bx = (int64_t(x) - cell_origin_x) >> kCellShift, by = (int64_t(y) - cell_origin_y) >> kCellShift;
  if (bx >= 0 && by >= 0 && bx < cell_columns && by < cell_rows && !cell_start.empty())
    n = cell_start[size_t(by) * size_t(cell_columns) + size_t(bx)];
  while (!(n & Node::kSubsectorBit)) {
    const Node& node = nodes[n];
    n = node.children[size_t(point_on_node_side(x, y, node))];
  }
  return &subsectors[n & ~Node::kSubsectorBit];
}

Blockmap build_blockmap(const std::vector<Line>& lines, const std::vector<Vertex>& vertices) {
  Blockmap bm;
  if (vertices.empty()) {
    bm.width = bm.height = 1;
    bm.offsets = {0};
    bm.lists = {Blockmap::kEnd};
    return bm;
  }
  Fixed min_x = INT_MAX, min_y = INT_MAX, max_x = INT_MIN, max_y = INT_MIN;
  for (const Vertex& v : vertices) {
    min_x = std::min(min_x, v.x), min_y = std::min(min_y, v.y);
    max_x = std::max(max_x, v.x), max_y = std::max(max_y, v.y);
  }
  // The origin on whole units, as the lump stores it.
  bm.origin_x = (min_x >> kFracBits) << kFracBits;
  bm.origin_y = (min_y >> kFracBits) << kFracBits;
  bm.width = int((int64_t(max_x) - bm.origin_x) >> kMapBlockShift) + 1;
  bm.height = int((int64_t(max_y) - bm.origin_y) >> kMapBlockShift) + 1;
  const size_t cells = size_t(bm.width) * size_t(bm.height);
  std::vector<std::vector<uint32_t>> lists(cells);
  for (size_t i = 0; i < lines.size(); ++i) {
    // Every cell the segment passes through, found by its box then a side test per
    // cell (a cell is crossed when its corners are not all on one side).
    const Line& ld = lines[i];
    const double x1 = to_double(ld.v1->x) - to_double(bm.origin_x), y1 = to_double(ld.v1->y) - to_double(bm.origin_y);
    const double x2 = to_double(ld.v2->x) - to_double(bm.origin_x), y2 = to_double(ld.v2->y) - to_double(bm.origin_y);
    const int c0 = std::max(0, int(std::floor(std::min(x1, x2) / 128))), c1 = std::min(bm.width - 1, int(std::floor(std::max(x1, x2) / 128)));
    const int r0 = std::max(0, int(std::floor(std::min(y1, y2) / 128))), r1 = std::min(bm.height - 1, int(std::floor(std::max(y1, y2) / 128)));
    for (int r = r0; r <= r1; ++r)
      for (int c = c0; c <= c1; ++c) {
        int sides = 0;
        for (int corner = 0; corner < 4; ++corner) {
          const double cx = (c + (corner & 1)) * 128.0, cy = (r + (corner >> 1)) * 128.0;
          const double cross = (x2 - x1) * (cy - y1) - (y2 - y1) * (cx - x1);
          sides |= cross > 0 ? 1 : cross < 0 ? 2 : 3;
        }
        if (sides == 3 || (x1 == x2 && y1 == y2)) lists[size_t(r) * size_t(bm.width) + size_t(c)].push_back(uint32_t(i));
      }
  }
  for (size_t c = 0; c < cells; ++c) {
    bm.offsets.push_back(uint32_t(bm.lists.size()));
    if (!lines.empty()) bm.lists.push_back(0);  // the list's opening word, which Doom reads as line 0
    bm.lists.insert(bm.lists.end(), lists[c].begin(), lists[c].end());
    bm.lists.push_back(Blockmap::kEnd);
  }
  return bm;
}

Map map_from_wad(const wad::MapData& data, const wad::MapLumps* lumps, const level::Level& level) {
  Map m;
  m.where = data.where;
  m.vertices.reserve(data.vertices.size());
  for (const wad::MapVertex& v : data.vertices) m.vertices.push_back({units_to_fixed(v.x), units_to_fixed(v.y)});

  m.sectors.resize(std::max<size_t>(data.sectors.size(), 1));
  for (size_t i = 0; i < data.sectors.size(); ++i) {
    const wad::MapSector& ms = data.sectors[i];
    Sector& s = m.sectors[i];
    s.floor_height = units_to_fixed(ms.floor);
    s.ceiling_height = units_to_fixed(ms.ceiling);
    if (i < level.sectors.size()) {
      s.floor_pic = level.sectors[i].floor_texture;
      s.ceiling_pic = level.sectors[i].ceiling_texture;
    }
    s.light = ms.light;
    s.special = ms.special;
    s.tag = ms.tag;
  }
  for (size_t i = 0; i < m.sectors.size(); ++i) m.sectors[i].index = int(i);

  auto sector_of = [&](int k) { return &m.sectors[k >= 0 && size_t(k) < data.sectors.size() ? size_t(k) : 0]; };
  m.sides.resize(data.sidedefs.size());
  for (size_t i = 0; i < data.sidedefs.size(); ++i) {
    const wad::MapSidedef& ms = data.sidedefs[i];
    Side& s = m.sides[i];
    s.texture_offset = units_to_fixed(ms.x_offset);
    s.row_offset = units_to_fixed(ms.y_offset);
    s.sector = sector_of(ms.sector);
  }
  // Each side's textures are the ones the level's walls of a line using it show.
  std::vector<const level::Wall*> first_wall(data.linedefs.size(), nullptr);
  for (const level::Wall& w : level.walls)
    if (w.source >= 0 && size_t(w.source) < first_wall.size() && !first_wall[size_t(w.source)]) first_wall[size_t(w.source)] = &w;

  m.lines.resize(data.linedefs.size());
  for (size_t i = 0; i < data.linedefs.size(); ++i) {
    const wad::MapLinedef& ml = data.linedefs[i];
    Line& ld = m.lines[i];
    ld.index = int(i);
    ld.flags = int(ml.flags);
    ld.special = ml.special;
    ld.tag = ml.tag;
    ld.v1 = &m.vertices[size_t(ml.v1)];
    ld.v2 = &m.vertices[size_t(ml.v2)];
    derive_line(ld);
    auto valid = [&](int k) { return k >= 0 && size_t(k) < m.sides.size(); };
    if (!valid(ml.front)) {  // Doom would crash: a side of its own in sector 0
      m.sides.push_back({0, 0, level::kNone, level::kNone, level::kNone, &m.sectors[0]});
      ld.side[0] = int(m.sides.size() - 1);
    } else {
      ld.side[0] = ml.front;
    }
    ld.side[1] = valid(ml.back) ? ml.back : -1;
  }
  for (size_t i = 0; i < m.lines.size(); ++i) {
    Line& ld = m.lines[i];
    ld.front = m.sides[size_t(ld.side[0])].sector;
    ld.back = ld.side[1] >= 0 ? m.sides[size_t(ld.side[1])].sector : nullptr;
    if (const level::Wall* w = first_wall[i]) {
      for (int k = 0; k < 2; ++k) {
        if (ld.side[k] < 0 || w->sides[k].sector == level::kNone) continue;
        Side& s = m.sides[size_t(ld.side[k])];
        s.top = w->sides[k].upper;
        s.middle = w->sides[k].middle;
        s.bottom = w->sides[k].lower;
      }
    }
  }

  size_t next_placed = 0;  // the importer keeps the THINGS it can place, in order
  for (const wad::MapThing& t : data.things) {
    MapThing mt;
    if (next_placed < level.things.size() && level.things[next_placed].type == t.type &&
        level.things[next_placed].pos == geom::Vec2(t.x, t.y))
      mt.placed = int32_t(next_placed++);
    mt.x = int16_t(std::lround(t.x));
    mt.y = int16_t(std::lround(t.y));
    mt.angle = int16_t(std::lround(t.angle));
    mt.type = int16_t(t.type);
    mt.options = int16_t(t.flags);
    m.things.push_back(mt);
  }

  std::optional<Blockmap> blockmap = lumps ? read_blockmap(lumps->find("BLOCKMAP"), m.lines.size()) : std::nullopt;
  m.blockmap = blockmap ? std::move(*blockmap) : build_blockmap(m.lines, m.vertices);
  m.reject = lumps && !data.udmf ? doom_reject_table(lumps->find("REJECT"), m) : reject_table(nullptr, m.sectors.size());
  if (!lumps || data.udmf || !read_nodes(*lumps, m)) leaves_as_subsectors(m, level);
  group_lines(m);
  m.index_cells();
  m.line_marks.assign(m.lines.size(), 0);
  return m;
}

Map map_from_wads(const wad::Stack& wads, const std::string& name, const level::Level& level) {
  const std::optional<wad::MapLumps> lumps = wads.map(name);
  if (!lumps) throw Error("no map " + name + " in the WADs");
  return map_from_wad(wad::read_map(*lumps), &*lumps, level);
}

Map map_from_level(const level::Level& level) {
  Map m;
  m.where = level.title;
  m.sectors.resize(std::max<size_t>(level.sectors.size(), 1));
  for (size_t i = 0; i < level.sectors.size(); ++i) {
    const level::Sector& ls = level.sectors[i];
    Sector& s = m.sectors[i];
    s.floor_height = units_to_fixed(ls.floor);
    s.ceiling_height = units_to_fixed(ls.ceiling);
    s.floor_pic = ls.floor_texture;
    s.ceiling_pic = ls.ceiling_texture;
    s.light = ls.light;
    s.special = ls.special;
    s.tag = ls.tag;
  }
  for (size_t i = 0; i < m.sectors.size(); ++i) m.sectors[i].index = int(i);
  m.vertices.reserve(level.walls.size() * 2);
  m.lines.resize(level.walls.size());
  m.wall_lines.resize(level.walls.size());
  for (size_t i = 0; i < level.walls.size(); ++i) {
    const level::Wall& w = level.walls[i];
    m.vertices.push_back({units_to_fixed(geom::to_world(w.p1).x), units_to_fixed(geom::to_world(w.p1).y)});
    m.vertices.push_back({units_to_fixed(geom::to_world(w.p2).x), units_to_fixed(geom::to_world(w.p2).y)});
  }
  for (size_t i = 0; i < level.walls.size(); ++i) {
    const level::Wall& w = level.walls[i];
    Line& ld = m.lines[i];
    ld.index = int(i);
    ld.v1 = &m.vertices[2 * i];
    ld.v2 = &m.vertices[2 * i + 1];
    derive_line(ld);
    ld.special = w.special;
    ld.tag = w.tag;
    ld.flags = (w.two_sided() ? kMlTwoSided : kMlBlocking) | (w.flags & level::kImpassable ? kMlBlocking : 0) |
               (w.flags & level::kUnpegUpper ? kMlDontPegTop : 0) | (w.flags & level::kUnpegLower ? kMlDontPegBottom : 0) |
               (w.flags & level::kSecret ? kMlSecret : 0) | (w.flags & level::kHidden ? kMlDontDraw : 0) |
               (w.flags & level::kMapped ? kMlMapped : 0);
    for (int k = 0; k < 2; ++k) {
      const level::Side& ls = w.sides[k];
      int sector = ls.sector;
      if (k == 0 && w.segment()) sector = w.segment_sector;
      if (sector == level::kNone) {
        if (k == 0) sector = 0;  // a side for a line with none: it blocks
        else continue;
      }
      if (k == 1 && !w.two_sided()) continue;
      Side s;
      s.texture_offset = units_to_fixed(ls.x_offset);
      s.row_offset = units_to_fixed(ls.y_offset);
      s.top = ls.upper, s.middle = ls.middle, s.bottom = ls.lower;
      s.sector = &m.sectors[size_t(sector)];
      ld.side[k] = int(m.sides.size());
      m.sides.push_back(s);
    }
    m.wall_lines[i] = int(i);
  }
  for (Line& ld : m.lines) {
    ld.front = m.sides[size_t(ld.side[0])].sector;
    ld.back = ld.side[1] >= 0 ? m.sides[size_t(ld.side[1])].sector : nullptr;
  }
  for (const level::Thing& t : level.things) {
    MapThing mt;
    mt.placed = int32_t(m.things.size());
    mt.x = int16_t(std::clamp<long>(std::lround(t.pos.x), -32768, 32767));
    mt.y = int16_t(std::clamp<long>(std::lround(t.pos.y), -32768, 32767));
    mt.angle = int16_t(std::lround(t.angle));
    mt.type = int16_t(t.type);
    mt.options = int16_t(t.flags);
    m.things.push_back(mt);
  }
  if (std::none_of(m.things.begin(), m.things.end(), [](const MapThing& t) { return t.type == 1; })) {
    MapThing start;  // the level's player start as Doom's player 1 start
    start.x = int16_t(std::clamp<long>(std::lround(level.player_start.x), -32768, 32767));
    start.y = int16_t(std::clamp<long>(std::lround(level.player_start.y), -32768, 32767));
    start.angle = int16_t(std::lround(level.player_angle));
    start.type = 1;
    m.things.push_back(start);
  }
  m.blockmap = build_blockmap(m.lines, m.vertices);
  m.reject = reject_table(nullptr, m.sectors.size());
  leaves_as_subsectors(m, level);
  group_lines(m);
  m.line_marks.assign(m.lines.size(), 0);
  return m;
}

}  // namespace p3d::play
