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
#include "engine/util/doom.h"
#include "engine/util/limits.h"

namespace p3d::level {

using geom::BBox;
using geom::Vec2;

constexpr int kNone = -1;
constexpr int kSky = -2;  // ceiling texture index meaning "draw the sky"

// x mod n in [0, n), for any sign of x (n > 0).
inline int64_t floor_mod(int64_t x, int64_t n) {
  const int64_t r = x % n;
  return r < 0 ? r + n : r;
}

// A texture of any size. Sides that are powers of two wrap by mask, others by
// modulo (Doom's 72- and 96-high textures repeat like any other).
struct Texture {
  std::string name;
  int width = 0, height = 0;
  std::vector<uint32_t> texels;   // column-major: texels[u * height + v], RGBA8; alpha 0 = transparent
  std::vector<uint8_t> indices;   // paletted levels: palette indices, laid out as texels; else empty
  // A level made only to be written (pseudo3d-mapc: make_texture_without_colours) has
  // no texels: this is 1 where a texel is drawn, laid out as indices, and its runs are
  // not derived. Renderers need the texels: such a level is read back before it is drawn.
  std::vector<uint8_t> opaque;
  // Derived by make_texture:
  bool holes = false;             // some texel is transparent
  bool pow2_width = false, pow2_height = false;
  // Textures with holes: each column's runs of opaque texels (Doom's posts), rows
  // [first, end); column u's are runs[run_start[u]] up to runs[run_start[u + 1]].
  struct Run {
    uint16_t first, end;
  };
  std::vector<uint32_t> run_start;
  std::vector<Run> runs;

  int wrap_u(int64_t u) const { return int(pow2_width ? u & (width - 1) : floor_mod(u, width)); }
  int wrap_v(int64_t v) const { return int(pow2_height ? v & (height - 1) : floor_mod(v, height)); }
  const uint32_t* column(int64_t u) const { return texels.data() + size_t(wrap_u(u)) * height; }
  const uint8_t* index_column(int64_t u) const { return indices.data() + size_t(wrap_u(u)) * height; }
  uint32_t at(int64_t u, int64_t v) const { return column(u)[wrap_v(v)]; }
};

// What renderers show where no sector is (the void) and for a missing texture: on
// paletted levels, the palette's nearest colours (Level::void_index, missing_index).
constexpr uint32_t kVoidColor = 18 | 18 << 8 | 26 << 16 | 0xFFu << 24;
constexpr uint32_t kMissingColor = 255 | 0 << 8 | 255 << 16 | 0xFFu << 24;

struct Sector {
  std::string name;
  double floor = 0, ceiling = 0;  // a ceiling below the floor is drawn as Doom draws it
  int light = 0;  // 0..255
  int floor_texture = kNone, ceiling_texture = kNone;  // either may be kSky
  int special = 0, tag = 0;  // Doom's sector special and tag
};

// Per wall part, as in PartOffsets.
enum Part { kUpperPart = 0, kMiddlePart = 1, kLowerPart = 2 };

// UDMF's offsets per wall part, added to its side's offsets. Rare, so kept apart from
// the sides (Level::part_offsets), which they would make twice as big.
struct PartOffsets {
  double x[3] = {0, 0, 0}, y[3] = {0, 0, 0};  // by Part
};

struct Side {
  int sector = kNone;
  int upper = kNone, middle = kNone, lower = kNone;
  double x_offset = 0, y_offset = 0;
  int32_t parts = kNone;  // its PartOffsets in Level::part_offsets, or kNone: all zero
  int light = kNone;      // the wall's own light level, or kNone for its sector's
};

enum WallFlag : uint32_t {
  kSegment = 1,     // a plain solid segment with no sector, visible from both sides
  kUnpegUpper = 2,
  kUnpegLower = 4,
  kImpassable = 8,  // a two-sided wall that blocks movement
  kSecret = 16,     // automap: drawn as one-sided
  kHidden = 32,     // automap: never drawn
  kMapped = 64,     // automap: known from the start
};
constexpr uint32_t kWallFlags = kSegment | kUnpegUpper | kUnpegLower | kImpassable | kSecret | kHidden | kMapped;

struct Wall {
  geom::IPoint p1, p2;  // exact fixed-point ends; the front side is on the right of p1 -> p2
  Side sides[2];        // [0] front (right), [1] back (left); one-sided walls have sides[1].sector == kNone
  uint32_t flags = 0;
  int32_t source = 0;   // the number users know it by: its statement (.map) or LINEDEF (WAD); --columns reports it
  int32_t special = 0, tag = 0;  // Doom's line special and tag
  // Derived on load:
  Vec2 a, b;            // p1, p2 in map units
  double length = 0;
  int contrast = 0;     // Doom's fake contrast: -1 along x, +1 along y, 0 otherwise
  int segment_sector = kNone;  // for a plain segment: the sector it stands in

  bool segment() const { return flags & kSegment; }
  bool two_sided() const { return !segment() && sides[1].sector != kNone; }
  bool solid() const { return !two_sided(); }
  // The sector behind side `side`: kNone when one-sided.
  int far_sector(int side) const { return two_sided() ? sides[1 - side].sector : kNone; }
  geom::Line line() const { return geom::Line::through(p1, p2); }
  Vec2 at(double t) const { return a + (b - a) * t; }
};

// A piece [t0, t1] of a wall: on the splitter line of the node that holds it, or inside
// the cell of the leaf that holds it. cut[k] is the line (Level::line) that produced end
// k (an ancestor's splitter), or kNone for an original wall end.
struct Fragment {
  uint32_t wall = 0;
  int32_t cut[2] = {kNone, kNone};
  double t0 = 0, t1 = 1;
  int32_t side = 0;  // a leaf's: the side of its wall facing the leaf's region (0 front, 1 back); a node's: 0
  // Derived on load:
  Vec2 p0, p1;
};

// A splitter line that holds no wall: through two distinct fixed points.
struct FreeLine {
  geom::IPoint p1, p2;
  geom::Line line() const { return geom::Line::through(p1, p2); }
};

// Children: index >= 0 is a node, index < 0 is leaf ~index.
struct Node {
  uint32_t splitter = 0;  // the line (Level::line) that splits this node: a wall's, or a free line
  int32_t child[2] = {0, 0};  // [0] front (right of the splitter), [1] back (left)
  uint32_t first_fragment = 0, fragment_count = 0;  // the fragments on its line
  BBox bbox;  // of every fragment in this subtree
  // Derived on load:
  Vec2 origin, direction;  // the splitter line in map units
};

inline bool is_leaf(int32_t child) { return child < 0; }
inline int32_t leaf_index(int32_t child) { return ~child; }
inline int32_t leaf_child(int32_t leaf) { return ~leaf; }

// A leaf (Doom's subsector): a convex cell of the partition and the fragments inside
// it, which bound a convex region of one sector (each lies on the side facing the
// region of every other's line; those on the cell's edges are its ancestors'). Doom's
// rule: every point of the cell, even one outside that region (behind a wall, in the
// void), is in the leaf's sector.
struct Leaf {
  int32_t sector = kNone;  // the cell's: its fragments', or its edges', or found by a ray cast (kNone: none)
  uint32_t first_fragment = 0, fragment_count = 0;
  // Derived on load:
  BBox bbox;  // of its fragments (empty when it holds none)
};

// A picture shown for a thing: a texture and Doom's picture offsets. The thing's
// position lies `left` texels right of the picture's left edge; its origin (its
// feet) `top` texels below the picture's top edge.
struct SpriteImage {
  int32_t texture = kNone;
  int32_t left = 0, top = 0;
};

constexpr int kRotations = 8;

// How a kind of thing looks (Doom's sprite frame): a picture for each of the eight
// directions it can be seen from, some mirrored. image[r] is Doom's rotation r + 1:
// r = 0 seen from the front, then in 45-degree steps as the viewer goes round it
// clockwise (Doom's rotation 0, a picture for every direction, fills all eight).
struct SpriteFrame {
  std::string name;                  // Doom's lump prefix and frame ("BAR1A"), or the picture's name
  int32_t image[kRotations] = {};    // indices into Level::sprite_images
  bool flip[kRotations] = {};
  bool bright = false;               // full bright (lamps, torches)
  bool hanging = false;              // hangs from the ceiling (Doom's MF_SPAWNCEILING)
  double drop = 0;                   // hanging: its origin lies this far below the ceiling
  // Derived on load:
  double reach = 0;                  // the farthest any of its pictures extends sideways from the thing
};

struct Thing {
  int type = 0;
  Vec2 pos;
  double angle = 0;
  uint32_t flags = 0;  // doom::ThingFlags
  int32_t sprite = kNone;  // its first frame in Level::sprite_frames, or kNone: never drawn (player starts...)
  int32_t sector = kNone;  // the sector it stands in (finalize finds it by point location when kNone)
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
  std::vector<PartOffsets> part_offsets;  // named by Side::parts
  // Free splitters' lines: lines through two points of the fixed grid that hold no wall,
  // where every wall's line would peel a few walls off a big cell (a nearly convex room).
  // Line numbers (Node::splitter, Fragment::cut) below walls.size() are walls' lines,
  // the rest these, in order.
  std::vector<FreeLine> free_lines;
  std::vector<Fragment> fragments;  // node by node and leaf by leaf, as the tree was built
  std::vector<Node> nodes;  // preorder: node 0 is the root, children come after their parent
  std::vector<Leaf> leaves;
  std::vector<Thing> things;
  std::vector<SpriteImage> sprite_images;
  std::vector<SpriteFrame> sprite_frames;
  Vec2 player_start;
  double player_angle = 0;
  int default_sector = kNone;
  int sky_texture = kNone;
  std::vector<doom::TextureAnimation> animations;  // textures shown in turn, in place of each other
  // Doom's segs of each wall side as the WAD's node builder cut its LINEDEF (its SEGS and
  // VERTEXES), along the side from its start, for drawing by Doom's rules: filled when a
  // WAD map is compiled in this run (bsp::build_wad_map), not kept in compiled files;
  // empty: each side is one seg from its own start.
  struct DoomSeg {
    double t0 = 0, t1 = 1;        // the part of the wall it covers (the wall's parameter, 0 at p1)
    int32_t v1x = 0, v1y = 0;     // its first vertex in 16.16 (the side's start, or a split point as Doom rounded it)
    int32_t v2x = 0, v2y = 0;     // its last vertex, likewise
    uint32_t angle = 0;           // its direction, a binary angle
    int32_t offset = 0;           // its distance along the LINEDEF from the side's start, 16.16
  };
  std::vector<DoomSeg> doom_segs;          // grouped by wall side, each side's in order of t0
  std::vector<uint32_t> doom_seg_start;    // per wall side (wall * 2 + side), and one more: empty or walls * 2 + 1
  // Doom's wall columns as R_DrawColumn reads them, 128 rows each (its texel row is
  // & 127): a column only one patch covers is the patch's own column, and past its
  // post the bytes that follow it in the lump; other columns run on into the next
  // composed one (the tutti-frutti of textures under 128 rows). Per texture the first
  // of its columns in doom_columns (kNone: none), filled with doom_segs.
  std::vector<int64_t> doom_column_start;
  std::vector<uint8_t> doom_columns;
  // Paletted levels (WAD art): the palette, and limits::kStoredMaps maps of its colours
  // (map m of index i at [m * kPaletteSize + i]): kLightMaps shaded, map 0 full bright,
  // then Doom's invulnerability map (kInverseMap). Both empty:
  // textures are RGBA, shaded by multiplying.
  std::vector<uint32_t> palette, light_maps;
  bool paletted() const { return !light_maps.empty(); }
  // Derived on load (derive_shading), for paletted levels: the light maps as palette
  // indices (Doom's COLORMAP itself), laid out as light_maps, when every shade is a
  // palette colour, else empty (renderers may then draw indices and look the palette up
  // once per pixel at the end); the palette's colours nearest to kVoidColor and
  // kMissingColor, which stand for them.
  std::vector<uint8_t> light_indices;
  uint8_t void_index = 0, missing_index = 0;
  double part_x(const Side& s, int part) const { return s.parts == kNone ? 0 : part_offsets[size_t(s.parts)].x[part]; }
  double part_y(const Side& s, int part) const { return s.parts == kNone ? 0 : part_offsets[size_t(s.parts)].y[part]; }
  std::optional<Grid> grid;  // levels compiled from .grid maps
  // Derived on load:
  BBox bounds;              // of all walls
  uint64_t generation = 0;  // unique per finalize(): renderers key per-level caches on it

  // Point location: descend the BSP. A point on a splitter goes to the front. Every point
  // is in its leaf's sector (Doom's rule), outside the map too.
  int leaf_at(Vec2 p) const;
  // The tree's root: node 0, or leaf 0 when the tree is a single leaf (its walls bound one convex region).
  int32_t root() const { return nodes.empty() ? leaf_child(0) : 0; }
  int sector_at(Vec2 p) const { return leaves[leaf_at(p)].sector; }
  // Line number i: wall i's line, or free line i - walls.size(). Exact.
  geom::Line line(uint32_t i) const {
    return i < walls.size() ? walls[i].line() : free_lines[i - walls.size()].line();
  }
  size_t line_count() const { return walls.size() + free_lines.size(); }
};

// Fills the derived fields: derive_geometry, derive_shading, then place_in_sectors.
void finalize(Level& level);
// Level::light_indices, void_index and missing_index, from the palette and light maps.
void derive_shading(Level& level);
// The fields geometry alone decides: wall and fragment points, node lines, leaf boxes,
// bounds, sprite reaches.
void derive_geometry(Level& level);
// The sectors plain segments and things stand in (by point location). Needs
// derive_geometry and the leaves' sectors: call again after changing them.
void place_in_sectors(Level& level);

// What changes while a level is played, beside the immutable level: sector heights,
// flats, light and special (doors and lifts move, floors change their flat), wall
// textures (switches flip) and specials (used up), and the things in the world (the
// skill played, pickups taken, monsters walking, missiles flying). Renderers and the
// simulation read the level through a state.
struct SectorState {
  double floor = 0, ceiling = 0;
  int light = 0;
  int floor_texture = kNone, ceiling_texture = kNone;  // either may be kSky
  int special = 0;
};
// A thing as the world shows it now (Doom's mobj as the renderer sees it).
struct ShownThing {
  Vec2 pos;
  double z = 0;            // feet (the sprite's origin) height, absolute
  double angle = 0;        // degrees, counter-clockwise from east: picks the rotation
  int32_t frame = kNone;   // index into Level::sprite_frames; kNone: not drawn
  int32_t sector = kNone;  // the sector whose light it takes (Doom: its subsector's sector)
  uint8_t flags = 0;       // ShownFlag bits
  int32_t placed = kNone;  // its index in Level::things when placed on the map (Doom's spawnpoint), else kNone
};
// kShownShadow: Doom's partial invisibility (MF_SHADOW), drawn as Doom's fuzz.
// kShownTranslation: a player's colour, 1..3 (render/translation.h), in those bits.
enum ShownFlag : uint8_t { kShownShadow = 1, kShownTranslation = 6 };
constexpr int kShownTranslationShift = 1;

struct State {
  std::vector<SectorState> sectors;
  // Doom's fixedcolormap: every wall, flat and thing in this light map (the light
  // amplification visor's 1, invulnerability's limits::kInverseMap), or kNone.
  int fixed_light_map = kNone;
  // The things in the world, drawn whatever their order (equal depths: the lower index
  // first). A sprite may reach SpriteFrame::reach sideways from its thing.
  std::vector<ShownThing> things;
  std::vector<int32_t> textures;  // per wall, side and Part: [(wall * 2 + side) * 3 + part]
  std::vector<int32_t> specials;  // per wall: its line special, 0 once used up
  // Per texture, the one drawn in its place (animations); empty: each draws itself.
  std::vector<int32_t> shown_textures;
  // Per wall, how far its front side's texture has scrolled left (Doom's special 48,
  // one unit a tic); empty: no wall scrolls.
  std::vector<double> scrolled;

  // The texture drawn for `texture` (kNone and kSky stay as they are).
  int shown(int texture) const { return texture < 0 || shown_textures.empty() ? texture : shown_textures[size_t(texture)]; }
  double scroll(uint32_t wall, int side) const { return side != 0 || scrolled.empty() ? 0 : scrolled[wall]; }

  int texture(uint32_t wall, int side, int part) const { return textures[(size_t(wall) * 2 + size_t(side)) * 3 + size_t(part)]; }
  int& texture(uint32_t wall, int side, int part) { return textures[(size_t(wall) * 2 + size_t(side)) * 3 + size_t(part)]; }
};

constexpr int kDefaultSkill = 3;  // Doom's "Hurt me plenty"
// The level as it starts at a skill (1..5, as Doom's -skill): its things in THINGS
// order, each showing its first frame where it rests (resting_z); things absent at
// that skill and things only in multiplayer games are left out (things without a
// sprite are in, with frame kNone: player starts, teleport destinations).
State start_state(const Level& level, int skill = kDefaultSkill);
// Where a thing showing `frame` rests in `sector` now: on its floor, or for a hanging
// frame (SpriteFrame::hanging) its drop below the ceiling.
double resting_z(const Level& level, const State& state, int32_t frame, int32_t sector);
// Every thing back to rest (resting_z): how a simulation without heights of its own
// keeps things on floors that move.
void rest_things(const Level& level, State& state);
// The entry of placed thing `thing` (an index in Level::things) in state.things, or kNone.
int32_t find_placed(const State& state, int32_t thing);
// Shows each animation's frames as Doom does after the tic at level time `tic`
// (the first tic is 0); before the first tic every texture shows itself.
void animate_textures(const Level& level, State& state, uint64_t tic);

// Side of p relative to a node's splitter: > 0 back (left), < 0 front (right).
inline double splitter_side(const Node& n, Vec2 p) { return geom::cross(n.direction, p - n.origin); }

// Texture from an RGBA8 row-major image, with its palette indices (row-major) when the level is paletted.
Texture make_texture(const std::string& name, int width, int height, const uint32_t* rgba_rows,
                     const uint8_t* index_rows = nullptr);
// The same from texels already column-major (as Texture keeps them; indices likewise, or empty).
Texture make_texture_from_columns(std::string name, int width, int height, std::vector<uint32_t> texels,
                                  std::vector<uint8_t> indices = {});
// A paletted texture without its colours, for a level that is only written: its
// indices and `opaque` (1 where drawn), column-major; no texels (see Texture::opaque).
Texture make_texture_without_colours(std::string name, int width, int height, std::vector<uint8_t> indices,
                                     std::vector<uint8_t> opaque);

// Walks the walls hit by the ray origin + s * dir (s > 0) in order of distance,
// using the BSP (leaf by leaf, each leaf's hits sorted). visit(wall, s, t) returns
// false to stop. Hits at a fragment's end may be reported twice (once per fragment).
void ray_cast(const Level& level, Vec2 origin, Vec2 dir,
              const std::function<bool(uint32_t wall, double s, double t)>& visit);

// The sector containing p by brute force: crossing parity of each sector's
// boundary, no BSP. The oracle for point location inside closed sectors (outside
// every sector it says the default sector, where Level::sector_at says its leaf's).
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
