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

namespace p3d::map {

constexpr int kNone = -1;
constexpr int kSkyTexture = -2;  // the ceiling texture name "sky": draw the sky there

struct Texture {
  std::string name;
  image::Image image;  // power-of-two sides, at most kMaxTextureSize
  FileLoc loc;
};
constexpr int kMaxTextureSize = 1024;

struct Vertex {
  std::string name;
  geom::IPoint pos;
  FileLoc loc;
};

struct Sector {
  std::string name;
  double floor = 0, ceiling = 128;
  int light = 160;  // 0..255
  int floor_texture = kNone, ceiling_texture = kNone;  // index, or kSkyTexture for the ceiling
  FileLoc loc;
};

// What a wall looks like from one side.
struct Side {
  int sector = kNone;
  int upper = kNone, middle = kNone, lower = kNone;  // texture indices
  double x_offset = 0, y_offset = 0;
};

enum WallFlags : unsigned {
  kUnpegUpper = 1,  // upper texture hangs from the ceiling instead of resting on the back ceiling
  kUnpegLower = 2,  // lower (and one-sided middle) texture is aligned from the bottom
};

struct Wall {
  int v1 = 0, v2 = 0;  // vertex indices; the front side is on the right walking v1 -> v2
  Side front, back;    // back.sector == kNone: one-sided or a plain segment
  bool segment = false;  // a plain solid segment with no sector, visible from both sides
  unsigned flags = 0;
  FileLoc loc;

  bool two_sided() const { return back.sector != kNone; }
};

struct Thing {
  int type = 0;
  geom::Vec2 pos;
  double angle = 0;  // degrees, counter-clockwise from east
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
  std::vector<Thing> things;
  PlayerStart player;
  int default_sector = kNone;  // used where no sector bounds a point (segment-only maps always have one)
  int sky_texture = kNone;
  std::optional<GridInfo> grid;  // for .grid maps

  geom::IPoint point(int vertex) const { return vertices[vertex].pos; }
};

// Parses and validates a .map file (see maps/FORMAT.md). Throws Error("file:line: message").
Source load_map(const std::filesystem::path& path);
Source parse_map(const std::string& text, const std::filesystem::path& path);

// Parses and validates a .grid tile map into walls (see maps/FORMAT.md).
Source load_grid(const std::filesystem::path& path);
Source parse_grid(const std::string& text, const std::filesystem::path& path);

// A .map or a .grid, by extension.
Source load_source(const std::filesystem::path& path);

// Walls along the edges between empty and solid cells (outside the grid counts as
// solid), collinear runs of one texture merged, each facing its empty cell; fills
// source.vertices, source.walls and source.grid. tile_texture[i] is cell i's texture.
void grid_to_walls(Source& source, const GridInfo& grid, const std::vector<int>& tile_texture, int border_texture,
                   int sector);

// Geometry and consistency checks shared by every source format: zero-length,
// crossing and overlapping walls, sector closure, heights, required textures.
void validate(const Source& source);

}  // namespace p3d::map
