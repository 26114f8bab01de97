#include "engine/wad/doom_segs.h"

#include <algorithm>
#include <optional>
#include <span>

#include "engine/wad/art_cache.h"
#include "engine/wad/map_data.h"

namespace p3d::wad {

void attach_doom_segs(const MapLumps& lumps, level::Level& level) {
  level.doom_segs.clear();
  level.doom_seg_start.clear();
  const Lump *vertexes = lumps.find("VERTEXES"), *segs = lumps.find("SEGS"), *lines = lumps.find("LINEDEFS");
  if (lumps.udmf() || !vertexes || !segs || !lines || vertexes->bytes.size() % kVertexRecord ||
      segs->bytes.empty() || segs->bytes.size() % kSegRecord || lines->bytes.size() % kLinedefRecord)
    return;
  const size_t vertex_count = vertexes->bytes.size() / kVertexRecord, line_count = lines->bytes.size() / kLinedefRecord;
  auto u16 = [](std::span<const uint8_t> b, size_t at) { return uint16_t(b[at] | b[at + 1] << 8); };
  // The segs of each LINEDEF side.
  std::vector<std::vector<size_t>> by_side(line_count * 2);
  const size_t seg_count = segs->bytes.size() / kSegRecord;
  for (size_t i = 0; i < seg_count; ++i) {
    const size_t at = i * kSegRecord;
    const uint16_t v1 = u16(segs->bytes, at), v2 = u16(segs->bytes, at + 2), line = u16(segs->bytes, at + 6);
    const uint16_t side = u16(segs->bytes, at + 8);
    if (v1 >= vertex_count || v2 >= vertex_count || line >= line_count || side > 1) return;  // not vanilla's: none
    by_side[size_t(line) * 2 + side].push_back(i);
  }
  auto vertex = [&](uint16_t v) {
    return geom::Vec2{double(int16_t(u16(vertexes->bytes, v * kVertexRecord))),
                      double(int16_t(u16(vertexes->bytes, v * kVertexRecord + 2)))};
  };
  level.doom_seg_start.assign(level.walls.size() * 2 + 1, 0);
  for (size_t w = 0; w < level.walls.size(); ++w) {
    const level::Wall& wall = level.walls[w];
    const geom::Vec2 a = geom::to_world(wall.p1), b = geom::to_world(wall.p2), d = b - a;
    const double length2 = glm::dot(d, d);
    for (int side = 0; side < 2; ++side) {
      level.doom_seg_start[w * 2 + size_t(side)] = uint32_t(level.doom_segs.size());
      if (wall.source < 0 || size_t(wall.source) >= line_count || length2 == 0) continue;
      const size_t first = level.doom_segs.size();
      for (size_t i : by_side[size_t(wall.source) * 2 + size_t(side)]) {
        const size_t at = i * kSegRecord;
        const geom::Vec2 p = vertex(u16(segs->bytes, at)), q = vertex(u16(segs->bytes, at + 2));
        const double tp = glm::dot(p - a, d) / length2, tq = glm::dot(q - a, d) / length2;
        level::Level::DoomSeg s;
        s.t0 = std::min(tp, tq), s.t1 = std::max(tp, tq);
        if (s.t1 <= 0 || s.t0 >= 1) continue;  // another wall made of the same LINEDEF
        s.v1x = int32_t(p.x * 65536), s.v1y = int32_t(p.y * 65536);
        s.v2x = int32_t(q.x * 65536), s.v2y = int32_t(q.y * 65536);
        s.angle = uint32_t(u16(segs->bytes, at + 4)) << 16;
        s.offset = int32_t(int16_t(u16(segs->bytes, at + 10))) * 65536;
        level.doom_segs.push_back(s);
      }
      std::sort(level.doom_segs.begin() + std::ptrdiff_t(first), level.doom_segs.end(),
                [](const level::Level::DoomSeg& x, const level::Level::DoomSeg& y) { return x.t0 < y.t0; });
    }
  }
  level.doom_seg_start.back() = uint32_t(level.doom_segs.size());
}

namespace {

// One texture's columns, 128 rows each, as R_DrawColumn reads them: a column under one
// patch straight from the patch's lump (its post headers and the bytes past it
// included), one under several from the composed columns. Empty when the WADs define
// no texture of that name and size.
std::vector<uint8_t> doom_columns_of(const Stack& wads, const Art& art, const level::Texture& tex) {
  constexpr int kRows = 128;
  const auto it = art.texture_defs().find(normalize_name(tex.name));
  if (it == art.texture_defs().end()) return {};
  const TextureDef& def = it->second;
  if (def.width != tex.width || def.height != tex.height || tex.indices.size() != size_t(tex.width) * size_t(tex.height))
    return {};
  auto u16 = [](std::span<const uint8_t> b, size_t at) { return at + 2 <= b.size() ? uint16_t(b[at] | b[at + 1] << 8) : uint16_t(0); };
  auto u32 = [](std::span<const uint8_t> b, size_t at) {
    return at + 4 <= b.size() ? uint32_t(b[at] | b[at + 1] << 8 | b[at + 2] << 16 | uint32_t(b[at + 3]) << 24) : 0u;
  };
  // R_GenerateLookup: per column the patches over it, the last one's lump and column.
  std::vector<int> count(size_t(def.width), 0);
  std::vector<const Lump*> lump(size_t(def.width), nullptr);
  std::vector<uint32_t> offset(size_t(def.width), 0);
  for (const PatchPlacement& p : def.patches) {
    const Lump* patch = wads.find(p.patch);
    if (!patch || patch->bytes.size() < 8) continue;
    const int width = int16_t(u16(patch->bytes, 0));
    for (int x = std::max(0, p.x); x < std::min(def.width, p.x + width); ++x) {
      ++count[size_t(x)];
      lump[size_t(x)] = patch;
      offset[size_t(x)] = u32(patch->bytes, 8 + 4 * size_t(x - p.x)) + 3;
    }
  }
  // The composed columns (more than one patch), one after another, as Doom caches them:
  // a column read past its height goes on into the next.
  std::vector<uint8_t> composite;
  std::vector<size_t> composite_at(size_t(def.width), 0);
  for (int x = 0; x < def.width; ++x) {
    if (count[size_t(x)] <= 1) continue;
    composite_at[size_t(x)] = composite.size();
    composite.insert(composite.end(), tex.indices.begin() + std::ptrdiff_t(size_t(x) * size_t(def.height)),
                     tex.indices.begin() + std::ptrdiff_t(size_t(x + 1) * size_t(def.height)));
  }
  std::vector<uint8_t> columns(size_t(def.width) * kRows);
  for (int x = 0; x < def.width; ++x) {
    uint8_t* out = columns.data() + size_t(x) * kRows;
    for (int r = 0; r < kRows; ++r) {
      if (count[size_t(x)] == 1) {
        const size_t at = size_t(offset[size_t(x)]) + size_t(r);
        out[r] = at < lump[size_t(x)]->bytes.size() ? lump[size_t(x)]->bytes[at] : 0;
      } else if (count[size_t(x)] > 1) {
        const size_t at = composite_at[size_t(x)] + size_t(r);
        out[r] = at < composite.size() ? composite[at] : 0;
      } else {  // no patch: Doom reads elsewhere; the column as composed
        out[r] = tex.indices[size_t(x) * size_t(def.height) + size_t(r % def.height)];
      }
    }
  }
  return columns;
}

}  // namespace

void attach_doom_columns(const Stack& wads, level::Level& level, ArtCache* cache) {
  level.doom_column_start.assign(level.textures.size(), level::kNone);
  level.doom_columns.clear();
  if (!wads.find("PNAMES")) return;
  std::optional<ArtCache> own;
  if (!cache) {
    try {
      cache = &own.emplace(wads);
    } catch (const std::exception&) {
      return;
    }
  }
  for (size_t t = 0; t < level.textures.size(); ++t) {
    const level::Texture& tex = level.textures[t];
    const std::vector<uint8_t>& columns =
        cache->doom_columns(tex.name, [&] { return doom_columns_of(wads, cache->art(), tex); });
    if (columns.empty()) continue;
    level.doom_column_start[t] = int64_t(level.doom_columns.size());
    level.doom_columns.insert(level.doom_columns.end(), columns.begin(), columns.end());
  }
}

void attach_doom_data(const Stack& wads, const std::string& map, level::Level& level, ArtCache* cache) {
  if (const auto lumps = wads.map(map)) attach_doom_segs(*lumps, level);
  attach_doom_columns(wads, level, cache);
}

}  // namespace p3d::wad
