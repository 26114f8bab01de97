#include "engine/wad/write.h"

#include <algorithm>

#include "engine/util/bytes.h"

namespace p3d::wad {

std::vector<uint8_t> write_wad(bool iwad, const std::vector<LumpToWrite>& lumps) {
  ByteWriter out;
  out.raw(std::span(reinterpret_cast<const uint8_t*>(iwad ? "IWAD" : "PWAD"), 4));
  out.u32(uint32_t(lumps.size()));
  size_t directory = kHeaderSize;
  for (const LumpToWrite& l : lumps) directory += l.bytes.size();
  out.u32(uint32_t(directory));
  std::vector<uint32_t> offsets;
  for (const LumpToWrite& l : lumps) {
    offsets.push_back(uint32_t(out.size()));
    out.raw(l.bytes);
  }
  for (size_t i = 0; i < lumps.size(); ++i) {
    out.u32(offsets[i]);
    out.u32(uint32_t(lumps[i].bytes.size()));
    for (size_t c = 0; c < kNameSize; ++c) out.u8(c < lumps[i].name.size() ? uint8_t(lumps[i].name[c]) : 0);
  }
  return out.release();
}

std::vector<uint8_t> map_without_nodes(const MapLumps& map) {
  constexpr std::string_view kNodeLumps[] = {"SEGS", "SSECTORS", "NODES", "REJECT", "BLOCKMAP"};
  std::vector<LumpToWrite> lumps{{map.name, {}}};
  for (const Lump* l : map.lumps) {
    const bool node = std::find(std::begin(kNodeLumps), std::end(kNodeLumps), l->name) != std::end(kNodeLumps);
    lumps.push_back({l->name, node ? std::span<const uint8_t>() : l->bytes});
  }
  return write_wad(false, lumps);
}

}  // namespace p3d::wad
