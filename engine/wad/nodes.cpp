// Doom's point location (R_PointInSubsector, R_PointOnSide) on the map's own node
// lumps: NODES 28 bytes (i16 x, y, dx, dy, 2 x 4 i16 boxes, 2 x u16 children, bit
// 15: subsector), SSECTORS 4 bytes (u16 seg count, first seg), SEGS 12 bytes (u16 v1,
// v2, i16 angle, u16 linedef, i16 side, i16 offset). Coordinates are Doom's 16.16
// fixed point, and the side test is Doom's own, ties included.
#include "engine/wad/nodes.h"

#include <cmath>

#include "engine/util/bytes.h"
#include "engine/wad/map_data.h"

namespace p3d::wad {

namespace {

constexpr uint16_t kSubsectorBit = 0x8000;
constexpr int kFracBits = 16;

struct DoomNode {
  int32_t x, y, dx, dy;  // 16.16
  uint16_t child[2];
};

int32_t fixed_mul(int32_t a, int32_t b) { return int32_t((int64_t(a) * b) >> kFracBits); }

// Doom's R_PointOnSide: 0 front (right), 1 back; a point on the line goes to the back
// unless the shortcuts for vertical and horizontal lines decide otherwise.
int point_on_side(int32_t x, int32_t y, const DoomNode& n) {
  if (n.dx == 0) return x <= n.x ? n.dy > 0 : n.dy < 0;
  if (n.dy == 0) return y <= n.y ? n.dx < 0 : n.dx > 0;
  const int32_t dx = x - n.x, dy = y - n.y;
  if ((n.dy ^ n.dx ^ dx ^ dy) & int32_t(0x80000000)) return (n.dy ^ dx) & int32_t(0x80000000) ? 1 : 0;
  const int32_t left = fixed_mul(n.dy >> kFracBits, dx), right = fixed_mul(dy, n.dx >> kFracBits);
  return right < left ? 0 : 1;
}

}  // namespace

std::optional<std::vector<int>> sectors_by_doom_nodes(const MapLumps& lumps, const MapData& data,
                                                      const std::vector<geom::Vec2>& points) {
  const Lump *nodes_lump = lumps.find("NODES"), *ss_lump = lumps.find("SSECTORS"), *segs_lump = lumps.find("SEGS");
  if (!nodes_lump || !ss_lump || !segs_lump || nodes_lump->bytes.empty() || nodes_lump->bytes.size() % kNodeRecord ||
      ss_lump->bytes.empty() || ss_lump->bytes.size() % kSubsectorRecord || segs_lump->bytes.size() % kSegRecord)
    return std::nullopt;
  std::vector<DoomNode> nodes(nodes_lump->bytes.size() / kNodeRecord);
  ByteReader in(nodes_lump->bytes, "NODES");
  for (DoomNode& n : nodes) {
    n.x = int32_t(int16_t(in.u16())) << kFracBits;
    n.y = int32_t(int16_t(in.u16())) << kFracBits;
    n.dx = int32_t(int16_t(in.u16())) << kFracBits;
    n.dy = int32_t(int16_t(in.u16())) << kFracBits;
    in.raw(16);  // bounding boxes
    n.child[0] = in.u16();
    n.child[1] = in.u16();
  }
  const size_t subsectors = ss_lump->bytes.size() / kSubsectorRecord, segs = segs_lump->bytes.size() / kSegRecord;
  // The sector of a subsector: its first seg's side of its linedef.
  auto subsector_sector = [&](size_t ss) -> int {
    ByteReader s(ss_lump->bytes.subspan(ss * kSubsectorRecord, kSubsectorRecord), "SSECTORS");
    s.u16();
    const uint16_t first = s.u16();
    if (first >= segs) return -1;
    ByteReader g(segs_lump->bytes.subspan(first * kSegRecord, kSegRecord), "SEGS");
    g.u16(), g.u16(), g.u16();
    const uint16_t line = g.u16();
    const int16_t side = int16_t(g.u16());
    if (line >= data.linedefs.size() || (side != 0 && side != 1)) return -1;
    const int sidedef = side ? data.linedefs[line].back : data.linedefs[line].front;
    if (sidedef < 0 || size_t(sidedef) >= data.sidedefs.size()) return -1;
    const int sector = data.sidedefs[size_t(sidedef)].sector;
    return sector >= 0 && size_t(sector) < data.sectors.size() ? sector : -1;
  };
  std::vector<int> out;
  for (const geom::Vec2 p : points) {
    if (std::fabs(p.x) >= 32768 || std::fabs(p.y) >= 32768) return std::nullopt;  // beyond Doom's coordinates
    const int32_t x = int32_t(std::lround(p.x * 65536)), y = int32_t(std::lround(p.y * 65536));
    size_t n = nodes.size() - 1;
    int sector = -1;
    for (size_t steps = 0; steps <= nodes.size(); ++steps) {  // a tree deeper than its nodes has a cycle
      const uint16_t c = nodes[n].child[point_on_side(x, y, nodes[n])];
      if (c & kSubsectorBit) {
        if ((c & ~kSubsectorBit) < subsectors) sector = subsector_sector(c & ~kSubsectorBit);
        break;
      }
      if (c >= nodes.size()) break;
      n = c;
    }
    if (sector < 0) return std::nullopt;
    out.push_back(sector);
  }
  return out;
}

}  // namespace p3d::wad
