// The map source model: what a level designer wrote in a .map (or .grid) file,
// parsed and validated, with its textures decoded. Input of the BSP compiler.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "engine/geom/geom.h"
#include "engine/image/image.h"
#include "engine/util/error.h"
#include "engine/util/doom.h"
#include "engine/util/limits.h"

namespace p3d::map {

constexpr int kNone = -1;
constexpr int kSkyTexture = -2;  // the ceiling texture name "sky": draw the sky there

struct Texture {
  std::string name;
  image::Image image;             // RGBA; alpha 0 where transparent. Any size up to kMaxTextureSize
  std::vector<uint8_t> indices;   // paletted art (WAD levels): each pixel's palette index, laid out as image; else empty
  // A picture imported without its colours (wad::ImportOptions::colours false): image
  // has its size but no pixels, and this 1 where a pixel is drawn, laid out as indices.
  std::vector<uint8_t> opaque;
  FileLoc loc;
  // image and indices hold columns one after another (pixel (x, y) at x * height + y),
  // as Doom's art and level::Texture keep them, not rows: image.at() does not apply.
  bool column_major = false;
};
using limits::kMaxTextureSize;

// Walls refer to vertices by index; their names are the parser's business, and an
// error about a vertex is about the wall that uses it.
struct Vertex {
  geom::IPoint pos;
};

struct Sector {
  std::string name;
  double floor = 0, ceiling = 128;
  int light = 160;  // 0..255
  int floor_texture = kNone, ceiling_texture = kNone;  // index, or kSkyTexture for the ceiling
  int special = 0, tag = 0;  // Doom's sector special and tag (WAD levels)
  FileLoc loc;
};

// Offsets added per part of a side: upper, middle, lower (UDMF). Rare, so kept apart
// from the sides: a million-wall map's sides are 96 MB smaller.
struct PartOffsets {
  double x[3] = {0, 0, 0}, y[3] = {0, 0, 0};
};

// What a wall looks like from one side.
struct Side {
  int sector = kNone;
  int upper = kNone, middle = kNone, lower = kNone;  // texture indices
  double x_offset = 0, y_offset = 0;
  int parts = kNone;  // its offsets per part: an index into Source::part_offsets, or kNone (all 0)
  int light = kNone;  // the wall's own light level, or kNone for its sector's
};

enum WallFlags : unsigned {
  kUnpegUpper = 1,  // upper texture hangs from the ceiling instead of resting on the back ceiling
  kUnpegLower = 2,  // lower (and one-sided middle) texture is aligned from the bottom
  kImpassable = 4,  // a two-sided wall nothing walks through (Doom's ML_BLOCKING)
  kSecret = 8,      // shown as one-sided on the automap
  kHidden = 16,     // never shown on the automap
  kMapped = 32,     // on the automap from the start
};

struct Wall {
  int v1 = 0, v2 = 0;  // vertex indices; the front side is on the right walking v1 -> v2
  Side front, back;    // back.sector == kNone: one-sided or a plain segment
  bool segment = false;  // a plain solid segment with no sector, visible from both sides
  unsigned flags = 0;
  int source = kNone;  // the number users know the wall by (WAD levels: its LINEDEF); kNone: its index
  int special = 0, tag = 0;  // Doom's line special and tag (WAD levels)
  FileLoc loc;

  bool two_sided() const { return back.sector != kNone; }
};

struct Thing {
  int type = 0;
  geom::Vec2 pos;
  double angle = 0;  // degrees, counter-clockwise from east
  uint32_t flags = doom::kThingAllSkills;
  int sprite = kNone;  // index into Source::sprites, or kNone: not drawn
  int sector = kNone;  // where it stands, when the source says (a WAD's own nodes); else the compiler finds it
};

// A picture for things: a .map `sprite` statement's PNG, or one of a WAD's sprite lumps.
struct SpriteImage {
  std::string name;
  image::Image image;            // RGBA; alpha 0 where transparent
  std::vector<uint8_t> indices;  // paletted art: each pixel's palette index, laid out as image; else empty
  std::vector<uint8_t> opaque;   // as Texture::opaque
  int left = 0, top = 0;         // the thing's position lies `left` pixels right of the left edge, its feet `top` below the top
  bool column_major = false;     // as Texture::column_major
};

constexpr int kRotations = 8;

// How a kind of thing looks: as level::SpriteFrame, images indexing Source::sprite_images.
struct SpriteFrame {
  std::string name;
  int image[kRotations] = {};
  bool flip[kRotations] = {};
  bool bright = false, hanging = false;
  double drop = 0;  // hanging: the thing's origin lies this far below the ceiling
};

struct PlayerStart {
  geom::Vec2 pos;
  double angle = 0;
  FileLoc loc;
};

// A Wolfenstein-style tile grid behind a .grid map: kept so that the grid ray
// caster (DDA) can walk the very walls the BSP draws.
struct GridInfo {
  int cols = 0, rows = 0;
  double cell = 64;               // map units per cell
  std::vector<uint8_t> solid;     // cols * rows, row 0 is the southernmost
  std::vector<int32_t> faces;     // 4 per cell (east, north, west, south): the wall on that side of
                                  // an empty cell whose neighbour is solid, else kNone
  bool is_solid(int c, int r) const { return c < 0 || r < 0 || c >= cols || r >= rows || solid[size_t(r) * cols + c]; }
};

struct Source {
  std::filesystem::path path;
  std::string title;
  std::vector<Texture> textures;
  std::vector<Vertex> vertices;
  std::vector<Sector> sectors;
  std::vector<Wall> walls;  // in file order: the wall index of --columns and the game
  std::vector<PartOffsets> part_offsets;  // what sides' `parts` index
  std::vector<Thing> things;
  std::vector<SpriteImage> sprite_images;
  std::vector<SpriteFrame> sprites;
  PlayerStart player;
  int default_sector = kNone;  // used where no sector bounds a point (segment-only maps always have one)
  int sky_texture = kNone;
  std::vector<doom::TextureAnimation> animations;  // WAD levels: Doom's animated textures and flats in use
  // Paletted art (WAD levels): the palette and its limits::kLightMaps light maps (Doom's
  // COLORMAP through PLAYPAL; map m of index i at [m * kPaletteSize + i], map 0 full bright).
  std::vector<uint32_t> palette, light_maps;
  std::optional<GridInfo> grid;  // for .grid maps

  geom::IPoint point(int vertex) const { return vertices[vertex].pos; }
  PartOffsets parts(const Side& side) const { return side.parts == kNone ? PartOffsets{} : part_offsets[size_t(side.parts)]; }
};

// How a text map may reach other files. Texture and sprite pictures resolve relative to
// the map's directory and may not leave it (no absolute paths, no "..": a map from
// elsewhere reads only what lies beside it) unless textures_anywhere is set. A bare
// file name found nowhere beside the map is looked for among the bundled textures, as
// a Doom PWAD takes the IWAD's art: a map naming them works wherever it is moved.
struct LoadOptions {
  bool textures_anywhere = false;
  std::filesystem::path bundled_textures;  // the project's maps/textures; empty: no fallback
};

// Parses and validates a .map file (see maps/FORMAT.md). Throws Error("file:line: message").
Source load_map(const std::filesystem::path& path, const LoadOptions& options = {});
Source parse_map(std::string_view text, const std::filesystem::path& path, const LoadOptions& options = {});

// Parses and validates a .grid tile map into walls (see maps/FORMAT.md).
Source load_grid(const std::filesystem::path& path, const LoadOptions& options = {});
Source parse_grid(const std::string& text, const std::filesystem::path& path, const LoadOptions& options = {});

// A .map or a .grid, by extension.
Source load_source(const std::filesystem::path& path, const LoadOptions& options = {});

// Walls along the edges between empty and solid cells (outside the grid counts as
// solid), collinear runs of one texture merged, each facing its empty cell; fills
// source.vertices, source.walls and source.grid. tile_texture[i] is cell i's texture.
void grid_to_walls(Source& source, GridInfo grid, const std::vector<int>& tile_texture, int border_texture, int sector);

// Geometry and consistency checks shared by every source format: zero-length,
// crossing and overlapping walls, sector closure, heights, required textures.
// Throws Error at the first problem (hand-written maps must be clean).
void validate(const Source& source);

// The values a compiled level can hold (engine/util/limits.h): names, title, heights,
// offsets, lights, positions, picture sizes. Part of validate; the compiler applies it
// to every source, so it never writes what the reader refuses.
void check_limits(const Source& source);

// The checks behind validate, as lists (WAD imports report them as warnings).
struct Contact {
  uint32_t a, b;  // walls, a < b
  geom::SegmentContact kind;  // kCross or kOverlap
};
// Pairs of walls that cross or overlap: the max_count with the smallest (b, a), in that order.
std::vector<Contact> find_contacts(const Source& source, size_t max_count);
// The pair find_contacts(source, 1) gives, found by a sweep line in O(n log^2 n)
// whatever the walls' layout (find_contacts takes it where its grid would be slow).
std::optional<Contact> first_contact_by_sweep(const Source& source);
struct OpenSector {
  int sector;
  geom::IPoint at;  // the open point at the smallest coordinates
};
// Sectors whose boundary does not close, in sector order.
std::vector<OpenSector> find_open_sectors(const Source& source);
// Sectors no wall bounds (the default sector excepted).
std::vector<int> unused_sectors(const Source& source);

}  // namespace p3d::map
