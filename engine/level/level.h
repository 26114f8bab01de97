// The compiled, immutable world: textures, sectors, walls, and the BSP (nodes
// with their splitter and fragments, leaves with their sector). Produced by the
// compiler (bsp::build) or the loader (level::read); consumed by the renderers.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "engine/geom/geom.h"

namespace p3d::level {

using geom::BBox;
using geom::Vec2;

constexpr int kNone = -1;
constexpr int kSky = -2;  // ceiling texture index meaning "draw the sky"

struct Texture {
  std::string name;
  int width = 0, height = 0;           // powers of two
  std::vector<uint32_t> texels;        // column-major: texels[u * height + v], RGBA8
  uint32_t width_mask = 0, height_mask = 0;
  int height_shift = 0;                // log2(height)

  const uint32_t* column(int u) const { return texels.data() + (size_t(u & width_mask) << height_shift); }
  uint32_t at(int u, int v) const { return column(u)[v & height_mask]; }
};

struct Sector {
  std::string name;
  double floor = 0, ceiling = 0;
  int light = 0;  // 0..255
  int floor_texture = kNone, ceiling_texture = kNone;  // ceiling may be kSky
};

struct Side {
  int sector = kNone;
  int upper = kNone, middle = kNone, lower = kNone;
  double x_offset = 0, y_offset = 0;
};

enum WallFlag : uint32_t {
  kSegment = 1,     // a plain solid segment with no sector, visible from both sides
  kUnpegUpper = 2,
  kUnpegLower = 4,
};

struct Wall {
  geom::IPoint p1, p2;  // exact fixed-point ends; the front side is on the right of p1 -> p2
  Side sides[2];        // [0] front (right), [1] back (left); one-sided walls have sides[1].sector == kNone
  uint32_t flags = 0;
  // Derived on load:
  Vec2 a, b;            // p1, p2 in map units
  double length = 0;
  int contrast = 0;     // Doom's fake contrast: -1 along x, +1 along y, 0 otherwise
  int segment_sector = kNone;  // for a plain segment: the sector it stands in

  bool segment() const { return flags & kSegment; }
  bool two_sided() const { return !segment() && sides[1].sector != kNone; }
  bool solid() const { return !two_sided(); }
  geom::Line line() const { return geom::Line::through(p1, p2); }
  Vec2 at(double t) const { return a + (b - a) * t; }
};

// A piece [t0, t1] of a wall, lying on the splitter line of the node that holds it.
// cut[k] is the wall whose line produced end k, or kNone for an original wall end.
struct Fragment {
  uint32_t wall = 0;
  int32_t cut[2] = {kNone, kNone};
  double t0 = 0, t1 = 1;
  // Derived on load:
  Vec2 p0, p1;
  bool same_direction = true;  // the wall runs the same way as its node's splitter
};

// Children: index >= 0 is a node, index < 0 is leaf ~index.
struct Node {
  uint32_t splitter = 0;  // the wall whose line splits this node
  int32_t child[2] = {0, 0};  // [0] front (right of the splitter), [1] back (left)
  uint32_t first_fragment = 0, fragment_count = 0;
  BBox bbox;  // of every fragment in this subtree
  // Derived on load:
  Vec2 origin, direction;  // the splitter line in map units
};

inline bool is_leaf(int32_t child) { return child < 0; }
inline int32_t leaf_index(int32_t child) { return ~child; }
inline int32_t leaf_child(int32_t leaf) { return ~leaf; }

struct Leaf {
  int32_t sector = kNone;  // the sector filling this convex cell, or kNone outside the map
};

struct Thing {
  int type = 0;
  Vec2 pos;
  double angle = 0;
};

// The tile grid of a level compiled from a .grid map, for the grid ray caster.
// Cell (c, r) spans [c, c+1] x [r, r+1] cells from the origin; row 0 is the south.
struct Grid {
  enum Face { kEast = 0, kNorth = 1, kWest = 2, kSouth = 3 };
  int cols = 0, rows = 0;
  double cell = 64;             // map units
  std::vector<uint8_t> solid;   // cols * rows
  std::vector<int32_t> faces;   // 4 per cell: the wall on that side of an empty cell with a solid neighbour

  bool inside(int c, int r) const { return c >= 0 && r >= 0 && c < cols && r < rows; }
  bool is_solid(int c, int r) const { return !inside(c, r) || solid[size_t(r) * cols + c]; }
  int32_t face(int c, int r, int f) const { return faces[(size_t(r) * cols + c) * 4 + f]; }
};

struct Level {
  std::string title;
  std::vector<Texture> textures;
  std::vector<Sector> sectors;
  std::vector<Wall> walls;  // in source order
  std::vector<Fragment> fragments;
  std::vector<Node> nodes;  // preorder: node 0 is the root, children come after their parent
  std::vector<Leaf> leaves;
  std::vector<Thing> things;
  Vec2 player_start;
  double player_angle = 0;
  int default_sector = kNone;
  int sky_texture = kNone;
  std::optional<Grid> grid;  // levels compiled from .grid maps
  // Derived on load:
  BBox bounds;              // of all walls
  uint64_t generation = 0;  // unique per finalize(): renderers key per-level caches on it

  // Point location: descend the BSP. A point on a splitter goes to the front.
  int leaf_at(Vec2 p) const;
  int sector_at(Vec2 p) const { return leaves[leaf_at(p)].sector; }
};

// Fills the derived fields (wall and fragment points, node lines, bounds, the
// sectors plain segments stand in). Call again after changing leaf sectors.
void finalize(Level& level);

// Side of p relative to a node's splitter: > 0 back (left), < 0 front (right).
inline double splitter_side(const Node& n, Vec2 p) { return geom::cross(n.direction, p - n.origin); }

// Texture from an RGBA8 row-major image.
Texture make_texture(const std::string& name, int width, int height, const uint32_t* rgba_rows);

// Walks the walls hit by the ray origin + s * dir (s > 0) in order of distance,
// using the BSP. visit(wall, s, t) returns false to stop. Hits at a fragment's
// end may be reported twice (once per fragment).
void ray_cast(const Level& level, Vec2 origin, Vec2 dir,
              const std::function<bool(uint32_t wall, double s, double t)>& visit);

// The sector containing p by brute force: crossing parity of each sector's
// boundary, no BSP. The oracle for point location.
int sector_at_brute_force(const Level& level, Vec2 p);

// The convex cell of every leaf, clipped to `bounds` (for drawing and checks).
std::vector<std::vector<Vec2>> leaf_cells(const Level& level, const BBox& bounds);

// The convex cell of the leaf containing p (clipped to `bounds`): point location
// that keeps the polygon, for highlighting the player's leaf.
std::vector<Vec2> cell_at(const Level& level, Vec2 p, const BBox& bounds);

// For every node, the piece of its splitter line inside its cell (clipped to `bounds`).
struct Chord {
  Vec2 a, b;
  bool empty = true;
};
std::vector<Chord> node_chords(const Level& level, const BBox& bounds);

}  // namespace p3d::level
