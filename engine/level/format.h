// The compiled level file (.bsp): the one description of the disk format.
//
//   header   magic "P3DBSP\r\n" (8 bytes), u32 version, u32 reserved (0),
//            u64 payload size, u64 XXH3-64 checksum of the payload (util/checksum.h)
//   payload  sections in this order, each opening with its u32 tag:
//     META     str title, f64 player x, y, angle, i32 default sector, i32 sky texture
//     PALT     u32 paletted (0 or 1); if 1: 256 RGBA8 palette colours, then kStoredMaps x 256
//              RGBA8 light-map colours (map 0 full bright; the last, Doom's invulnerability map)
//     TEXTURES u32 n; n x { str name, u32 width, u32 height, pixels in columns (pixel p is
//              row p % height of column p / height): if paletted, width*height u8 palette
//              indices then ceil(width*height / 8) opacity bytes (bit p % 8 of byte p / 8,
//              1 = opaque); else width*height RGBA8 }
//     SPRITES  u32 n; n x image { i32 texture, i32 left offset, i32 top offset };
//              u32 n; n x frame { str name, 8 x { i32 image, u8 flip }, u8 bright, u8 hanging, f64 drop }
//     SECTORS  u32 n; n x { str name, f64 floor, f64 ceiling, i32 light, i32 floor tex, i32 ceiling tex,
//                           i32 special, i32 tag }
//     PARTS    u32 n; n x { 3 x f64 part x offset, 3 x f64 part y offset } (upper, middle, lower)
//     WALLS    u32 n; n x { i64 x1, y1, x2, y2 (1/256 unit), u32 flags, i32 source, i32 special, i32 tag,
//                           2 x side }
//              side = { i32 sector, i32 upper, i32 middle, i32 lower, f64 x offset, f64 y offset,
//                       i32 part offsets (-1: none), i32 light }
//     LINES    u32 n; n x { i64 x1, y1, x2, y2 (1/256 unit) }: free splitters' lines, through two
//              distinct points; line number walls + i (a node's splitter, a fragment's cut)
//     FRAGS    u32 n; n x { u32 wall, i32 cut0 line, i32 cut1 line, f64 t0, f64 t1, u8 side (a leaf's: of its wall,
//                           facing the leaf's region: 0 front, 1 back; a node's: 0) }
//     NODES    u32 n; n x { u32 splitter line, i32 front, i32 back, u32 first frag, u32 frag count (those on
//                           its line), f64 bbox min x, min y, max x, max y }
//     LEAVES   u32 n; n x { i32 sector, u32 first frag, u32 frag count (those inside its cell, bounding a
//                           convex region) }; the nodes' and leaves' ranges tile the fragments
//     THINGS   u32 n; n x { i32 type, f64 x, y, angle, u32 flags, i32 sprite frame (-1: none), i32 sector (-1: none) }
//     ANIMS    u32 n; n x { i32 tics, i32 phase, u32 frames, frames x i32 texture }
//     GRID     u32 present (0 or 1); if 1: u32 cols, u32 rows, f64 cell,
//              cols*rows u8 solid (row 0 south), cols*rows*4 i32 face walls (east, north, west, south)
// All integers and IEEE doubles little-endian; str = u32 length + bytes.
#pragma once

#include <cstddef>
#include <cstdint>

#include "engine/util/limits.h"

namespace p3d::level::format {

constexpr char kMagic[8] = {'P', '3', 'D', 'B', 'S', 'P', '\r', '\n'};
constexpr uint32_t kVersion = 11;  // 11: free splitters (LINES); 10: leaves hold the fragments bounding their convex regions
constexpr size_t kHeaderSize = 8 + 4 + 4 + 8 + 8;

constexpr uint32_t tag(const char (&s)[5]) {
  return uint32_t(uint8_t(s[0])) | uint32_t(uint8_t(s[1])) << 8 | uint32_t(uint8_t(s[2])) << 16 |
         uint32_t(uint8_t(s[3])) << 24;
}
constexpr uint32_t kMeta = tag("META"), kPalette = tag("PALT"), kTextures = tag("TEXS"), kSprites = tag("SPRS"),
                   kSectors = tag("SECS"), kPartOffsets = tag("PRTS"),
                   kWalls = tag("WALL"), kLines = tag("LINE"), kFragments = tag("FRAG"), kNodes = tag("NODE"), kLeaves = tag("LEAF"),
                   kThings = tag("THNG"), kAnimations = tag("ANIM"), kGrid = tag("GRID");

constexpr size_t kSideRecord = 4 * 4 + 2 * 8 + 4 + 4;
constexpr size_t kPartOffsetsRecord = 6 * 8;
constexpr size_t kWallRecord = 4 * 8 + 4 * 4 + 2 * kSideRecord;
constexpr size_t kLineRecord = 4 * 8;
constexpr size_t kFragmentRecord = 4 * 3 + 8 * 2 + 1;
constexpr size_t kNodeRecord = 4 * 5 + 8 * 4;
constexpr size_t kSectorRecord = 4 + 8 * 2 + 4 * 5;
constexpr size_t kThingRecord = 4 + 8 * 3 + 4 + 4 + 4;
constexpr size_t kSpriteImageRecord = 4 * 3;
constexpr size_t kSpriteFrameRecord = 4 + 8 * (4 + 1) + 1 + 1 + 8;
constexpr size_t kLeafRecord = 4 * 3;
constexpr size_t kTextureHeader = 4 + 4 + 4;
constexpr size_t kGridCellBytes = 1 + 4 * 4;

}  // namespace p3d::level::format
