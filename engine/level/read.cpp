// Bytes -> Level. Validates everything once so that the renderers can trust
// every index: header, checksum, counts, ranges, tree structure (the geometry of the
// tree is bsp::check_invariants').
#include <bit>
#include <cmath>
#include <cstring>

#include "engine/level/format.h"
#include "engine/level/io.h"
#include "engine/util/bytes.h"
#include "engine/util/checksum.h"
#include "engine/util/file.h"
#include "engine/util/limits.h"

namespace p3d::level {

namespace {

class Reader {
 public:
  Reader(std::span<const uint8_t> payload, const std::string& what) : in_(payload, what) {}

  Level run() {
    section(format::kMeta, "META");
    level_.title = in_.str(limits::kMaxTitleLength);
    level_.player_start = {bounded("player x", geom::kMaxCoord), bounded("player y", geom::kMaxCoord)};
    level_.player_angle = finite("player angle");
    level_.default_sector = in_.i32();
    level_.sky_texture = in_.i32();

    read_palette();
    read_textures();
    read_sprites();
    read_sectors();
    read_part_offsets();
    read_walls();
    read_free_lines();
    read_fragments();
    read_nodes();
    read_leaves();
    read_things();
    read_animations();
    read_grid();
    in_.at(nullptr);
    if (in_.remaining() != 0) in_.fail(std::to_string(in_.remaining()) + " unexpected bytes after the last section");

    check_references();
    check_grid();
    check_tree();
    finalize(level_);
    return std::move(level_);
  }

 private:
  void section(uint32_t tag, const char* name) {
    in_.at(nullptr);
    if (in_.u32() != tag) in_.fail(std::string("expected section ") + name + " at byte " + std::to_string(in_.position() - 4));
    in_.at(name);
  }
  double finite(const char* what) {
    const double v = in_.f64();
    if (!std::isfinite(v)) in_.fail(std::string(what) + " is not finite");
    return v;
  }
  // Heights are bounded like coordinates: the renderer's arithmetic is sized for them.
  double height(const char* what) {
    const double v = finite(what);
    if (std::fabs(v) > geom::kMaxCoord) in_.fail(std::string(what) + " is out of range");
    return v;
  }
  double bounded(const char* what, double limit) {
    const double v = finite(what);
    if (std::fabs(v) > limit) in_.fail(std::string(what) + " is out of range");
    return v;
  }
  void index(int32_t v, int32_t lo, size_t count, const std::string& what) const {
    if (v < lo || v >= static_cast<int64_t>(count)) in_.fail(what + " index " + std::to_string(v) + " is out of range");
  }

  void read_palette() {
    section(format::kPalette, "PALT");
    const uint32_t paletted = in_.u32();
    if (paletted > 1) in_.fail("bad palette flag");
    if (!paletted) return;
    const size_t colors = limits::kPaletteSize, maps = size_t(limits::kStoredMaps) * limits::kPaletteSize;
    if (in_.remaining() < 4 * (colors + maps)) in_.fail("truncated palette");
    level_.palette.resize(colors);
    for (uint32_t& c : level_.palette) c = in_.u32();
    level_.light_maps.resize(maps);
    for (uint32_t& c : level_.light_maps) c = in_.u32();
  }

  void read_textures() {
    section(format::kTextures, "TEXS");
    const uint32_t n = in_.count(format::kTextureHeader, "textures");
    level_.textures.reserve(n);
    for (uint32_t i = 0; i < n; ++i) {
      in_.at("TEXS", i);
      const std::string name = in_.str(limits::kMaxNameLength);
      const uint32_t w = in_.u32(), h = in_.u32();
      const auto fits = [](uint32_t v) { return v > 0 && v <= uint32_t(limits::kMaxTextureSize); };
      if (!fits(w) || !fits(h))
        in_.fail("texture '" + name + "' has a bad size " + std::to_string(w) + "x" +
                 std::to_string(h));
      const size_t texel_count = size_t(w) * h;
      if (!level_.paletted()) {
        const auto bytes = in_.raw(texel_count * 4);  // bounds-checked before anything is allocated
        std::vector<uint32_t> texels(texel_count);
        for (size_t p = 0; p < texel_count; ++p)
          texels[p] = uint32_t(bytes[4 * p]) | uint32_t(bytes[4 * p + 1]) << 8 | uint32_t(bytes[4 * p + 2]) << 16 |
                      uint32_t(bytes[4 * p + 3]) << 24;
        level_.textures.push_back(make_texture_from_columns(name, int(w), int(h), std::move(texels)));
        continue;
      }
      const auto indices = in_.raw(texel_count);
      const auto opacity = in_.raw((texel_count + 7) / 8);
      std::vector<uint32_t> texels(texel_count);
      for (size_t p = 0; p < texel_count; ++p)
        texels[p] = level_.palette[indices[p]] & (opacity[p / 8] >> (p % 8) & 1 ? ~0u : 0u);
      level_.textures.push_back(make_texture_from_columns(name, int(w), int(h), std::move(texels),
                                                          std::vector<uint8_t>(indices.begin(), indices.end())));
    }
  }

  void read_sprites() {
    section(format::kSprites, "SPRS");
    const uint32_t images = in_.count(format::kSpriteImageRecord, "sprite images");
    level_.sprite_images.resize(images);
    for (SpriteImage& i : level_.sprite_images) {
      in_.at("SPRS (images)", &i - level_.sprite_images.data());
      i.texture = in_.i32();
      index(i.texture, 0, level_.textures.size(), "sprite image texture");
      i.left = in_.i32();
      i.top = in_.i32();
      if (std::abs(int64_t(i.left)) > limits::kMaxTextureSize || std::abs(int64_t(i.top)) > limits::kMaxTextureSize)
        in_.fail("sprite image offsets out of range");
    }
    const uint32_t frames = in_.count(format::kSpriteFrameRecord, "sprite frames");
    level_.sprite_frames.resize(frames);
    for (SpriteFrame& f : level_.sprite_frames) {
      in_.at("SPRS (frames)", &f - level_.sprite_frames.data());
      f.name = in_.str(limits::kMaxNameLength);
      for (int r = 0; r < kRotations; ++r) {
        f.image[r] = in_.i32();
        index(f.image[r], 0, images, "sprite frame '" + f.name + "' image");
        f.flip[r] = flag("sprite flip");
      }
      f.bright = flag("sprite bright flag");
      f.hanging = flag("sprite hanging flag");
      f.drop = height("sprite drop");
    }
  }

  bool flag(const char* what) {
    const uint8_t v = in_.u8();
    if (v > 1) in_.fail(std::string("bad ") + what);
    return v;
  }

  void read_sectors() {
    section(format::kSectors, "SECS");
    const uint32_t n = in_.count(format::kSectorRecord, "sectors");
    level_.sectors.resize(n);
    for (Sector& s : level_.sectors) {
      in_.at("SECS", &s - level_.sectors.data());
      s.name = in_.str(limits::kMaxNameLength);
      s.floor = height("sector floor");
      s.ceiling = height("sector ceiling");
      s.light = in_.i32();
      if (s.light < 0 || s.light > 255) in_.fail("sector light out of range");
      s.floor_texture = in_.i32();
      s.ceiling_texture = in_.i32();
      s.special = in_.i32();
      s.tag = in_.i32();
    }
  }

  Side read_side() {
    Side s;
    s.sector = in_.i32();
    s.upper = in_.i32();
    s.middle = in_.i32();
    s.lower = in_.i32();
    s.x_offset = bounded("side x offset", limits::kMaxOffset);
    s.y_offset = bounded("side y offset", limits::kMaxOffset);
    s.parts = in_.i32();
    s.light = in_.i32();
    if (s.light != kNone && (s.light < 0 || s.light > 255)) in_.fail("side light out of range");
    return s;
  }

  void read_part_offsets() {
    section(format::kPartOffsets, "PRTS");
    const uint32_t n = in_.count(format::kPartOffsetsRecord, "part offsets");
    level_.part_offsets.resize(n);
    for (PartOffsets& p : level_.part_offsets) {
      in_.at("PRTS", &p - level_.part_offsets.data());
      for (double& v : p.x) v = bounded("side part x offset", limits::kMaxOffset);
      for (double& v : p.y) v = bounded("side part y offset", limits::kMaxOffset);
    }
  }

  // A wall's or a free line's two ends, each coordinate within the fixed-point range.
  void read_ends(geom::IPoint& p1, geom::IPoint& p2, const std::string& what) {
    p1 = {in_.i64(), in_.i64()};
    p2 = {in_.i64(), in_.i64()};
    for (int64_t c : {p1.x, p1.y, p2.x, p2.y})
      if (c < -geom::kMaxFixed || c > geom::kMaxFixed) in_.fail(what + " coordinate out of range");
  }

  void read_walls() {
    section(format::kWalls, "WALL");
    const uint32_t n = in_.count(format::kWallRecord, "walls");
    if (n > limits::kMaxWalls) in_.fail(limits::too_many_walls());
    level_.walls.resize(n);
    for (Wall& w : level_.walls) {
      in_.at("WALL", &w - level_.walls.data());
      read_ends(w.p1, w.p2, "wall");
      if (w.p1 == w.p2) in_.fail("zero-length wall");
      w.flags = in_.u32();
      if (w.flags & ~kWallFlags) in_.fail("unknown wall flags");
      w.source = in_.i32();
      if (w.source < 0) in_.fail("wall source number is negative");
      w.special = in_.i32();
      w.tag = in_.i32();
      w.sides[0] = read_side();
      w.sides[1] = read_side();
    }
  }

  void read_free_lines() {
    section(format::kLines, "LINE");
    const uint32_t n = in_.count(format::kLineRecord, "free lines");
    if (n > limits::kMaxWalls) in_.fail("more free lines than a level may have walls");
    level_.free_lines.resize(n);
    for (FreeLine& l : level_.free_lines) {
      in_.at("LINE", &l - level_.free_lines.data());
      read_ends(l.p1, l.p2, "free line");
      if (l.p1 == l.p2) in_.fail("free line through one point");
    }
  }

  void read_fragments() {
    section(format::kFragments, "FRAG");
    const uint32_t n = in_.count(format::kFragmentRecord, "fragments");
    level_.fragments.resize(n);
    for (Fragment& f : level_.fragments) {
      in_.at("FRAG", &f - level_.fragments.data());
      f.wall = in_.u32();
      f.cut[0] = in_.i32();
      f.cut[1] = in_.i32();
      f.t0 = finite("fragment t0");
      f.t1 = finite("fragment t1");
      f.side = in_.u8();
      if (f.side > 1) in_.fail("bad fragment side");
    }
  }

  void read_nodes() {
    section(format::kNodes, "NODE");
    const uint32_t n = in_.count(format::kNodeRecord, "nodes");
    level_.nodes.resize(n);
    for (Node& node : level_.nodes) {
      in_.at("NODE", &node - level_.nodes.data());
      node.splitter = in_.u32();
      node.child[0] = in_.i32();
      node.child[1] = in_.i32();
      node.first_fragment = in_.u32();
      node.fragment_count = in_.u32();
      node.bbox.min = {finite("node bbox"), finite("node bbox")};
      node.bbox.max = {finite("node bbox"), finite("node bbox")};
    }
  }

  void read_leaves() {
    section(format::kLeaves, "LEAF");
    const uint32_t n = in_.count(format::kLeafRecord, "leaves");
    level_.leaves.resize(n);
    for (Leaf& l : level_.leaves) {
      in_.at("LEAF", &l - level_.leaves.data());
      l.sector = in_.i32();
      l.first_fragment = in_.u32();
      l.fragment_count = in_.u32();
    }
  }

  void read_things() {
    section(format::kThings, "THNG");
    const uint32_t n = in_.count(format::kThingRecord, "things");
    level_.things.resize(n);
    for (Thing& t : level_.things) {
      in_.at("THNG", &t - level_.things.data());
      t.type = in_.i32();
      t.pos = {bounded("thing x", geom::kMaxCoord), bounded("thing y", geom::kMaxCoord)};
      t.angle = finite("thing angle");
      t.flags = in_.u32();
      t.sprite = in_.i32();
      index(t.sprite, kNone, level_.sprite_frames.size(), "thing sprite");
      t.sector = in_.i32();
    }
  }

  void read_animations() {
    section(format::kAnimations, "ANIM");
    const uint32_t n = in_.count(12, "animations");
    level_.animations.resize(n);
    for (doom::TextureAnimation& a : level_.animations) {
      in_.at("ANIM", &a - level_.animations.data());
      a.tics = in_.i32();
      a.phase = in_.i32();
      if (a.tics <= 0 || a.tics > 35 * 60) in_.fail("bad tics per frame " + std::to_string(a.tics));
      const uint32_t frames = in_.count(4, "animation frames");
      if (frames < 2) in_.fail("an animation needs two frames or more");
      if (a.phase < 0 || uint32_t(a.phase) >= frames) in_.fail("bad phase " + std::to_string(a.phase));
      a.frames.resize(frames);
      for (int32_t& f : a.frames) f = in_.i32();
    }
  }

  void read_grid() {
    section(format::kGrid, "GRID");
    const uint32_t present = in_.u32();
    if (present > 1) in_.fail("bad grid flag");
    if (!present) return;
    Grid g;
    const uint32_t cols = in_.u32(), rows = in_.u32();
    if (cols < 1 || rows < 1 || cols > uint32_t(limits::kMaxGridSide) || rows > uint32_t(limits::kMaxGridSide))
      in_.fail("grid size out of range");
    g.cols = int(cols);
    g.rows = int(rows);
    g.cell = finite("grid cell");
    if (!(g.cell >= limits::kMinGridCell) || g.cell * std::max(cols, rows) > geom::kMaxCoord)
      in_.fail("grid cell size out of range");
    const size_t cells = size_t(cols) * rows;
    if (in_.remaining() < cells * format::kGridCellBytes) in_.fail("truncated grid");
    const auto solid = in_.raw(cells);
    g.solid.assign(solid.begin(), solid.end());
    g.faces.resize(cells * 4);
    for (int32_t& f : g.faces) f = in_.i32();
    level_.grid = std::move(g);
  }

  // Every face of an empty cell against a solid one has the wall lying along that
  // face (exactly, on the fixed grid), and no other face has one: the grid ray
  // caster trusts this mapping.
  void check_grid() const {
    if (!level_.grid) return;
    const Grid& g = *level_.grid;
    for (size_t i = 0; i < g.solid.size(); ++i) {
      in_.at("GRID", int64_t(i));
      if (g.solid[i] > 1) in_.fail("bad grid cell");
    }
    auto corner = [&](int gx, int gy) {
      geom::IPoint p;
      if (!geom::to_fixed(gx * g.cell, p.x) || !geom::to_fixed(gy * g.cell, p.y)) in_.fail("grid corner out of range");
      return p;
    };
    const int dc[4] = {1, 0, -1, 0}, dr[4] = {0, 1, 0, -1};
    for (int r = 0; r < g.rows; ++r)
      for (int c = 0; c < g.cols; ++c)
        for (int f = 0; f < 4; ++f) {
          in_.at("GRID", int64_t(r) * g.cols + c);
          const int32_t w = g.face(c, r, f);
          const bool needs_wall = !g.is_solid(c, r) && g.is_solid(c + dc[f], r + dr[f]);
          if ((w != kNone) != needs_wall) in_.fail("grid face wall does not match the tiles");
          if (w == kNone) continue;
          index(w, 0, level_.walls.size(), "grid face wall");
          // The face runs between two corners of the cell.
          const int x0 = c + (f == Grid::kEast), y0 = r + (f == Grid::kNorth);
          const int x1 = f == Grid::kNorth || f == Grid::kSouth ? x0 + 1 : x0, y1 = f == Grid::kEast || f == Grid::kWest ? y0 + 1 : y0;
          const geom::IPoint a = corner(x0, y0), b = corner(x1, y1);
          const Wall& wall = level_.walls[w];
          if (geom::orient(wall.p1, wall.p2, a) != 0 || geom::orient(wall.p1, wall.p2, b) != 0 ||
              geom::segment_contact(wall.p1, wall.p2, a, b) != geom::SegmentContact::kOverlap)
            in_.fail("grid face wall does not lie along its face");
        }
  }

  void check_references() const {
    const size_t textures = level_.textures.size(), sectors = level_.sectors.size(), walls = level_.walls.size(),
                 lines = level_.line_count();
    in_.at("META");
    index(level_.default_sector, kNone, sectors, "default sector");
    index(level_.sky_texture, kNone, textures, "sky texture");
    for (const doom::TextureAnimation& a : level_.animations) {
      in_.at("ANIM", &a - level_.animations.data());
      for (int32_t f : a.frames) index(f, 0, textures, "animation frame");
    }
    for (const Sector& s : level_.sectors) {
      in_.at("SECS", &s - level_.sectors.data());
      if (s.floor_texture != kSky) index(s.floor_texture, 0, textures, "floor texture");
      if (s.ceiling_texture != kSky) index(s.ceiling_texture, 0, textures, "ceiling texture");
    }
    for (const Wall& w : level_.walls) {
      in_.at("WALL", &w - level_.walls.data());
      for (const Side& s : w.sides) {
        index(s.sector, kNone, sectors, "side sector");
        for (int t : {s.upper, s.middle, s.lower}) index(t, kNone, textures, "side texture");
        index(s.parts, kNone, level_.part_offsets.size(), "side part offsets");
      }
      if (w.segment()) {
        if (w.sides[0].middle == kNone || w.sides[1].middle == kNone) in_.fail("segment without a texture");
      } else if (w.sides[0].sector == kNone) {
        in_.fail("wall without a front sector");
      }
    }
    for (const Fragment& f : level_.fragments) {
      in_.at("FRAG", &f - level_.fragments.data());
      index(static_cast<int32_t>(f.wall), 0, walls, "fragment wall");
      if (!(0 <= f.t0 && f.t0 < f.t1 && f.t1 <= 1)) in_.fail("fragment with an empty or inverted range");
      for (int k = 0; k < 2; ++k) {
        const double t = k ? f.t1 : f.t0;
        const bool original_end = t == (k ? 1.0 : 0.0);
        if (original_end != (f.cut[k] == kNone)) in_.fail("fragment end does not match its cut");
        index(f.cut[k], kNone, lines, "fragment cut");
        if (f.cut[k] != kNone && geom::parallel(level_.walls[f.wall].line(), level_.line(uint32_t(f.cut[k]))))
          in_.fail("fragment cut by a parallel line");
      }
    }
    for (const Leaf& l : level_.leaves) {
      in_.at("LEAF", &l - level_.leaves.data());
      index(l.sector, kNone, sectors, "leaf sector");
    }
    for (const Thing& t : level_.things) {
      in_.at("THNG", &t - level_.things.data());
      index(t.sector, kNone, sectors, "thing sector");
    }
  }

  // A proper binary tree rooted at node 0 (or a single leaf), whose nodes' and leaves'
  // fragment ranges tile the fragment array, each node's fragments exactly on its
  // splitter line.
  void check_tree() const {
    const size_t nodes = level_.nodes.size(), leaves = level_.leaves.size();
    in_.at("NODE");
    if (leaves != nodes + 1) in_.fail("tree has " + std::to_string(nodes) + " nodes and " + std::to_string(leaves) + " leaves");
    std::vector<uint8_t> node_seen(nodes, 0), leaf_seen(leaves, 0), fragment_seen(level_.fragments.size(), 0);
    auto claim = [&](uint32_t first, uint32_t count, const char* what) {
      if (uint64_t(first) + count > level_.fragments.size()) in_.fail(std::string(what) + " fragment range out of bounds");
      for (uint32_t f = first; f < first + count; ++f)
        if (fragment_seen[f]++) in_.fail("fragment " + std::to_string(f) + " belongs to two nodes or leaves");
    };
    for (size_t i = 0; i < nodes; ++i) {
      in_.at("NODE", int64_t(i));
      const Node& n = level_.nodes[i];
      index(static_cast<int32_t>(n.splitter), 0, level_.line_count(), "node splitter");
      for (int32_t c : n.child) {
        if (is_leaf(c)) {
          index(leaf_index(c), 0, leaves, "leaf");
          if (leaf_seen[leaf_index(c)]++) in_.fail("leaf " + std::to_string(leaf_index(c)) + " has two parents");
        } else {
          if (c <= static_cast<int32_t>(i) || c >= static_cast<int32_t>(nodes)) in_.fail("node child out of order");
          if (node_seen[c]++) in_.fail("node " + std::to_string(c) + " has two parents");
        }
      }
      claim(n.first_fragment, n.fragment_count, "node");
      const geom::Line splitter = level_.line(n.splitter);
      for (uint32_t f = n.first_fragment; f < n.first_fragment + n.fragment_count; ++f)
        if (!geom::same_line(splitter, level_.walls[level_.fragments[f].wall].line()))
          in_.fail("fragment " + std::to_string(f) + " is not on its node's splitter");
    }
    in_.at("NODE");
    for (size_t i = 1; i < nodes; ++i)
      if (!node_seen[i]) in_.fail("node " + std::to_string(i) + " is unreachable");
    in_.at("LEAF");
    for (size_t i = 0; i < leaves && nodes > 0; ++i)
      if (!leaf_seen[i]) in_.fail("leaf " + std::to_string(i) + " is unreachable");
    for (const Leaf& l : level_.leaves) {
      in_.at("LEAF", &l - level_.leaves.data());
      claim(l.first_fragment, l.fragment_count, "leaf");
    }
    in_.at("FRAG");
    for (size_t i = 0; i < fragment_seen.size(); ++i)
      if (!fragment_seen[i]) in_.fail("fragment " + std::to_string(i) + " belongs to no node or leaf");
  }

  mutable ByteReader in_;
  Level level_;
};

}  // namespace

Level decode(std::span<const uint8_t> bytes, const std::string& what) {
  if (bytes.size() < 8 || std::memcmp(bytes.data(), format::kMagic, 8) != 0)
    throw Error(what + ": not a compiled level (bad magic; compile maps with mapc)");
  if (bytes.size() < format::kHeaderSize) throw Error(what + ": truncated header");
  ByteReader header(bytes.subspan(8, format::kHeaderSize - 8), what);
  const uint32_t version = header.u32();
  if (version != format::kVersion)
    throw Error(what + ": compiled level version " + std::to_string(version) + " is not supported (expected " +
                std::to_string(format::kVersion) + "; recompile with mapc)");
  header.u32();
  const uint64_t size = header.u64();
  const uint64_t checksum = header.u64();
  const auto payload = bytes.subspan(format::kHeaderSize);
  if (size != payload.size())
    throw Error(what + ": truncated or padded file (payload is " + std::to_string(payload.size()) + " bytes, header says " +
                std::to_string(size) + ")");
  if (checksum64(payload) != checksum) throw Error(what + ": checksum mismatch (the file is corrupted)");
  return Reader(payload, what).run();
}

Level read(const std::filesystem::path& path) { return decode(read_file_bytes(path), path.string()); }

}  // namespace p3d::level
