// Level queries: derived fields, point location, BSP ray casting, brute-force
// sector lookup (the oracle) and leaf cells.
#include "engine/level/level.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>

#ifdef __SSE2__
#include <emmintrin.h>
#endif

#include "engine/geom/polygon.h"
#include "engine/util/doom.h"

namespace p3d::level {

namespace {

// dst[x * h + y] = src[y * w + x], by tiles of 16 x 16 so that both sides stay in cache.
template <typename T>
void transpose_to_columns(const T* src, int w, int h, T* dst) {
  constexpr int kTile = 16;
  for (int y0 = 0; y0 < h; y0 += kTile)
    for (int x0 = 0; x0 < w; x0 += kTile) {
      const int y1 = std::min(h, y0 + kTile), x1 = std::min(w, x0 + kTile);
      for (int x = x0; x < x1; ++x) {
        T* to = dst + size_t(x) * h;
        for (int y = y0; y < y1; ++y) to[y] = src[size_t(y) * w + x];
      }
    }
}

// Bit y % 64 of word y / 64 set where texel y of a column is transparent (alpha 0):
// runs are then found a word at a time, not a texel at a time.
void transparent_rows(const uint32_t* column, int height, std::vector<uint64_t>& words) {
  words.assign(size_t(height + 63) / 64, 0);
  int y = 0;
#ifdef __SSE2__
  const __m128i zero = _mm_setzero_si128();
  for (; y + 4 <= height; y += 4) {  // four rows share a word: 64 is a multiple of 4
    const __m128i alpha = _mm_srli_epi32(_mm_loadu_si128(reinterpret_cast<const __m128i*>(column + y)), 24);
    const int clear = _mm_movemask_ps(_mm_castsi128_ps(_mm_cmpeq_epi32(alpha, zero)));
    words[size_t(y) / 64] |= uint64_t(unsigned(clear)) << (y % 64);
  }
#endif
  for (; y < height; ++y)
    if (!(column[y] >> 24)) words[size_t(y) / 64] |= uint64_t(1) << (y % 64);
}

// The first row from `y` on whose transparent bit is `bit`; `height` if none.
int next_row(const std::vector<uint64_t>& words, int y, int height, bool bit) {
  for (size_t w = size_t(y) / 64; w < words.size(); ++w) {
    uint64_t candidates = bit ? words[w] : ~words[w];
    if (w == size_t(y) / 64) candidates &= ~uint64_t(0) << (y % 64);
    if (candidates) return std::min(height, int(w * 64) + std::countr_zero(candidates));
  }
  return height;
}

}  // namespace

Texture make_texture(const std::string& name, int width, int height, const uint32_t* rgba_rows,
                     const uint8_t* index_rows) {
  std::vector<uint32_t> texels(size_t(width) * height);
  transpose_to_columns(rgba_rows, width, height, texels.data());
  std::vector<uint8_t> indices;
  if (index_rows) {
    indices.resize(texels.size());
    transpose_to_columns(index_rows, width, height, indices.data());
  }
  return make_texture_from_columns(name, width, height, std::move(texels), std::move(indices));
}

namespace {

// A texture's size, indices and either texels or opacity; whether it has holes, and
// (with texels, to be drawn) its runs of opaque texels.
Texture make_texture(std::string name, int width, int height, std::vector<uint32_t> texels, std::vector<uint8_t> indices,
                     std::vector<uint8_t> opaque) {
  Texture t;
  t.name = std::move(name);
  t.width = width;
  t.height = height;
  t.pow2_width = std::has_single_bit(static_cast<unsigned>(width));
  t.pow2_height = std::has_single_bit(static_cast<unsigned>(height));
  t.texels = std::move(texels);
  t.indices = std::move(indices);
  t.opaque = std::move(opaque);
  if (t.texels.empty()) {  // only written: the writer needs to know of holes, not where they are
    t.holes = std::memchr(t.opaque.data(), 0, t.opaque.size()) != nullptr;
    return t;
  }
  static_assert(limits::kMaxTextureSize <= UINT16_MAX, "a run's rows are 16-bit");
  t.run_start.reserve(size_t(width) + 1);
  std::vector<uint64_t> transparent;
  for (int x = 0; x < width; ++x) {
    t.run_start.push_back(uint32_t(t.runs.size()));
    transparent_rows(t.column(x), height, transparent);
    for (int y = 0; y < height;) {
      const int first = next_row(transparent, y, height, false);
      if (first == height) break;
      y = next_row(transparent, first, height, true);
      t.runs.push_back({uint16_t(first), uint16_t(y)});
      if (first > 0 || y < height) t.holes = true;
    }
    if (t.runs.size() == t.run_start.back()) t.holes = true;  // a column with no opaque texel
  }
  t.run_start.push_back(uint32_t(t.runs.size()));
  if (!t.holes) {  // one run a column, top to bottom: no posts to keep
    std::vector<uint32_t>().swap(t.run_start);
    std::vector<Texture::Run>().swap(t.runs);
  }
  return t;
}

}  // namespace

Texture make_texture_from_columns(std::string name, int width, int height, std::vector<uint32_t> texels,
                                  std::vector<uint8_t> indices) {
  return make_texture(std::move(name), width, height, std::move(texels), std::move(indices), {});
}

Texture make_texture_without_colours(std::string name, int width, int height, std::vector<uint8_t> indices,
                                     std::vector<uint8_t> opaque) {
  return make_texture(std::move(name), width, height, {}, std::move(indices), std::move(opaque));
}

namespace {

// Each sprite frame's reach: the farthest any of its pictures extends sideways from its thing.
void measure_sprites(Level& level) {
  for (SpriteFrame& f : level.sprite_frames) {
    f.reach = 0;
    for (int r = 0; r < kRotations; ++r) {
      const SpriteImage& img = level.sprite_images[size_t(f.image[r])];
      const int width = level.textures[size_t(img.texture)].width;
      f.reach = std::max({f.reach, double(std::abs(img.left)), double(std::abs(width - img.left))});
    }
  }
}

}  // namespace

void finalize(Level& level) {
  derive_geometry(level);
  derive_shading(level);
  place_in_sectors(level);
}

namespace {

// The index of the palette colour nearest to c (the first of equals).
uint8_t nearest_index(const std::vector<uint32_t>& palette, uint32_t c) {
  auto channel = [](uint32_t colour, int shift) { return int(colour >> shift & 0xFF); };
  auto distance = [&](uint32_t p) {
    int sum = 0;
    for (int shift : {0, 8, 16}) sum += (channel(p, shift) - channel(c, shift)) * (channel(p, shift) - channel(c, shift));
    return sum;
  };
  size_t best = 0;
  for (size_t i = 1; i < palette.size(); ++i)
    if (distance(palette[i]) < distance(palette[best])) best = i;
  return uint8_t(best);
}

}  // namespace

void derive_shading(Level& level) {
  level.light_indices.clear();
  level.void_index = level.missing_index = 0;
  if (!level.paletted() || level.palette.size() != limits::kPaletteSize) return;
  level.void_index = nearest_index(level.palette, kVoidColor);
  level.missing_index = nearest_index(level.palette, kMissingColor);
  // A colour's first index (equal colours draw alike), by open addressing: 1024 slots
  // for 256 colours.
  constexpr size_t kSlots = 1024;
  std::array<uint32_t, kSlots> colour{};
  std::array<int16_t, kSlots> index;
  index.fill(-1);
  auto slot_of = [&](uint32_t c) {
    size_t slot = (c * 0x9E3779B1u) >> 22;
    while (index[slot] >= 0 && colour[slot] != c) slot = (slot + 1) % kSlots;
    return slot;
  };
  for (size_t i = 0; i < limits::kPaletteSize; ++i) {
    const size_t slot = slot_of(level.palette[i]);
    if (index[slot] < 0) colour[slot] = level.palette[i], index[slot] = int16_t(i);
  }
  std::vector<uint8_t> indices(level.light_maps.size());
  for (size_t i = 0; i < indices.size(); ++i) {
    const int16_t found = index[slot_of(level.light_maps[i])];
    if (found < 0) return;  // a shade outside the palette: drawn in 32 bits
    indices[i] = uint8_t(found);
  }
  level.light_indices = std::move(indices);
}

void derive_geometry(Level& level) {
  level.bounds = BBox{};
  for (Wall& w : level.walls) {
    w.a = geom::to_world(w.p1);
    w.b = geom::to_world(w.p2);
    w.length = glm::length(w.b - w.a);
    w.contrast = w.p1.y == w.p2.y ? -1 : w.p1.x == w.p2.x ? 1 : 0;
    level.bounds.add(w.a);
    level.bounds.add(w.b);
  }
  for (Fragment& f : level.fragments) {
    const Wall& w = level.walls[f.wall];
    f.p0 = f.t0 == 0 ? w.a : w.at(f.t0);
    f.p1 = f.t1 == 1 ? w.b : w.at(f.t1);
  }
  for (Node& n : level.nodes) {
    const geom::Line l = level.line(n.splitter);
    n.origin = geom::to_world(l.a);
    n.direction = Vec2(double(l.d.x), double(l.d.y)) / geom::kFixedOne;
  }
  for (Leaf& l : level.leaves) {
    l.bbox = BBox{};
    for (uint32_t i = l.first_fragment; i < l.first_fragment + l.fragment_count; ++i) {
      l.bbox.add(level.fragments[i].p0);
      l.bbox.add(level.fragments[i].p1);
    }
  }
  measure_sprites(level);
}

void place_in_sectors(Level& level) {
  static std::atomic<uint64_t> generations{0};
  level.generation = ++generations;
  if (level.leaves.empty()) return;
  // Where every leaf holds one sector (a map of plain segments), so does every point.
  const bool one_sector = std::all_of(level.leaves.begin(), level.leaves.end(),
                                      [&](const Leaf& l) { return l.sector == level.leaves[0].sector; });
  for (Wall& w : level.walls)
    if (w.segment()) w.segment_sector = one_sector ? level.leaves[0].sector : level.sector_at((w.a + w.b) * 0.5);
  for (Thing& t : level.things)
    if (t.sector == kNone) t.sector = level.sector_at(t.pos);
}

State start_state(const Level& level, int skill) {
  State s;
  for (const Sector& sec : level.sectors)
    s.sectors.push_back({sec.floor, sec.ceiling, sec.light, sec.floor_texture, sec.ceiling_texture, sec.special});
  s.textures.reserve(level.walls.size() * 6);
  for (const Wall& w : level.walls)
    for (const Side& side : w.sides) s.textures.insert(s.textures.end(), {side.upper, side.middle, side.lower});
  for (const Wall& w : level.walls) s.specials.push_back(w.special);
  for (size_t i = 0; i < level.things.size(); ++i) {
    const Thing& t = level.things[i];
    if (t.sector == kNone || !(t.flags & doom::skill_bit(skill)) || (t.flags & doom::kThingNotSingle)) continue;
    ShownThing shown;
    shown.pos = t.pos;
    shown.angle = t.angle;
    shown.frame = t.sprite;
    shown.sector = t.sector;
    shown.placed = int32_t(i);
    shown.z = resting_z(level, s, shown.frame, shown.sector);
    s.things.push_back(shown);
  }
  return s;
}

double resting_z(const Level& level, const State& state, int32_t frame, int32_t sector) {
  const SectorState& s = state.sectors[size_t(sector)];
  if (frame == kNone) return s.floor;
  const SpriteFrame& f = level.sprite_frames[size_t(frame)];
  return f.hanging ? s.ceiling - f.drop : s.floor;
}

void rest_things(const Level& level, State& state) {
  for (ShownThing& t : state.things)
    if (t.sector != kNone) t.z = resting_z(level, state, t.frame, t.sector);
}

int32_t find_placed(const State& state, int32_t thing) {
  for (size_t k = 0; k < state.things.size(); ++k)
    if (state.things[k].placed == thing) return int32_t(k);
  return kNone;
}

void animate_textures(const Level& level, State& state, uint64_t tic) {
  if (level.animations.empty()) return;
  if (state.shown_textures.empty()) {
    state.shown_textures.resize(level.textures.size());
    for (size_t t = 0; t < level.textures.size(); ++t) state.shown_textures[t] = int32_t(t);
  }
  for (const doom::TextureAnimation& a : level.animations) {
    const uint64_t n = a.frames.size(), step = tic / uint64_t(a.tics) + uint64_t(a.phase);
    for (uint64_t k = 0; k < n; ++k) state.shown_textures[size_t(a.frames[k])] = a.frames[(step + k) % n];
  }
}

int Level::leaf_at(Vec2 p) const {
  int32_t c = root();
  while (!is_leaf(c)) {
    const Node& n = nodes[c];
    c = n.child[splitter_side(n, p) > 0 ? 1 : 0];
  }
  return leaf_index(c);
}

void ray_cast(const Level& level, Vec2 origin, Vec2 dir,
              const std::function<bool(uint32_t wall, double s, double t)>& visit) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  struct Item {
    int32_t child;
    double lo, hi;
    bool fragments;  // visit this node's fragments rather than its subtree
  };
  struct Hit {
    double s, t;
    uint32_t wall;
  };
  std::vector<Item> stack{{level.root(), 0.0, kInf, false}};
  std::vector<Hit> hits;
  // The hits of fragments [first, first + count), nearest first.
  auto visit_fragments = [&](uint32_t first, uint32_t count) {
    hits.clear();
    for (uint32_t i = first; i < first + count; ++i) {
      const Fragment& f = level.fragments[i];
      const Wall& w = level.walls[f.wall];
      const Vec2 e = w.b - w.a;
      const double den = geom::cross(dir, e);
      if (den == 0) continue;
      const double s = geom::cross(w.a - origin, e) / den;
      const double t = geom::cross(w.a - origin, dir) / den;
      if (s > 0 && t >= f.t0 && t <= f.t1) hits.push_back({s, t, f.wall});
    }
    std::sort(hits.begin(), hits.end(), [](const Hit& a, const Hit& b) { return a.s < b.s || (a.s == b.s && a.wall < b.wall); });
    for (const Hit& h : hits)
      if (!visit(h.wall, h.s, h.t)) return false;
    return true;
  };
  while (!stack.empty()) {
    const Item item = stack.back();
    stack.pop_back();
    if (is_leaf(item.child)) {  // its fragments bound a convex region: at most two hits
      const Leaf& leaf = level.leaves[size_t(leaf_index(item.child))];
      if (!visit_fragments(leaf.first_fragment, leaf.fragment_count)) return;
      continue;
    }
    const Node& n = level.nodes[item.child];
    if (item.fragments) {
      if (!visit_fragments(n.first_fragment, n.fragment_count)) return;
      continue;
    }
    const double side = splitter_side(n, origin);
    const double rate = geom::cross(n.direction, dir);
    const int near = side > 0 || (side == 0 && rate > 0) ? 1 : 0;
    const double s_cross = rate != 0 ? -side / rate : kInf;
    if (!(s_cross > item.lo) || s_cross >= item.hi) {  // no crossing inside this cell's stretch
      const bool beyond = s_cross > 0 && s_cross <= item.lo;
      stack.push_back({n.child[beyond ? 1 - near : near], item.lo, item.hi, false});
      continue;
    }
    stack.push_back({n.child[1 - near], s_cross, item.hi, false});
    stack.push_back({item.child, s_cross, s_cross, true});
    stack.push_back({n.child[near], item.lo, s_cross, false});
  }
}

int sector_at_brute_force(const Level& level, Vec2 p) {
  std::vector<uint8_t> parity(level.sectors.size(), 0);
  for (const Wall& w : level.walls) {
    if (w.segment() || w.sides[0].sector == w.sides[1].sector) continue;
    if ((w.a.y > p.y) == (w.b.y > p.y)) continue;
    const double x = w.a.x + (p.y - w.a.y) * (w.b.x - w.a.x) / (w.b.y - w.a.y);
    if (p.x >= x) continue;
    for (const Side& s : w.sides)
      if (s.sector >= 0) parity[s.sector] ^= 1;
  }
  for (size_t s = 0; s < parity.size(); ++s)
    if (parity[s]) return static_cast<int>(s);
  return level.default_sector;
}

std::vector<Vec2> cell_at(const Level& level, Vec2 p, const BBox& bounds) {
  geom::Polygon poly = geom::box_polygon(bounds);
  int32_t c = level.root();
  while (!is_leaf(c) && !poly.empty()) {
    const Node& n = level.nodes[c];
    const bool back = splitter_side(n, p) > 0;
    poly = geom::clip_polygon(poly, n.origin, n.direction, back ? +1 : -1);
    c = n.child[back ? 1 : 0];
  }
  return poly;
}

std::vector<Chord> node_chords(const Level& level, const BBox& bounds) {
  std::vector<Chord> chords(level.nodes.size());
  std::vector<std::pair<int32_t, geom::Polygon>> stack{{level.root(), geom::box_polygon(bounds)}};
  while (!stack.empty()) {
    auto [child, poly] = std::move(stack.back());
    stack.pop_back();
    if (is_leaf(child)) continue;
    const Node& n = level.nodes[child];
    // The line meets the convex cell in one segment: between its extreme projections
    // among the cell's edge crossings.
    double lo = INFINITY, hi = -INFINITY;
    const double len2 = glm::dot(n.direction, n.direction);
    for (size_t i = 0; i < poly.size(); ++i) {
      const Vec2 p = poly[i], q = poly[(i + 1) % poly.size()];
      const double sp = geom::cross(n.direction, p - n.origin), sq = geom::cross(n.direction, q - n.origin);
      if ((sp > 0) == (sq > 0) && sp != 0 && sq != 0) continue;
      const Vec2 x = sp == sq ? p : p + (q - p) * (sp / (sp - sq));
      const double t = glm::dot(x - n.origin, n.direction) / len2;
      lo = std::min(lo, t);
      hi = std::max(hi, t);
    }
    if (lo < hi) chords[child] = {n.origin + n.direction * lo, n.origin + n.direction * hi, false};
    stack.push_back({n.child[1], geom::clip_polygon(poly, n.origin, n.direction, +1)});
    stack.push_back({n.child[0], geom::clip_polygon(poly, n.origin, n.direction, -1)});
  }
  return chords;
}

std::vector<std::vector<Vec2>> leaf_cells(const Level& level, const BBox& bounds) {
  std::vector<std::vector<Vec2>> cells(level.leaves.size());
  std::vector<std::pair<int32_t, geom::Polygon>> stack{{level.root(), geom::box_polygon(bounds)}};
  while (!stack.empty()) {
    auto [child, poly] = std::move(stack.back());
    stack.pop_back();
    if (is_leaf(child)) {
      cells[leaf_index(child)] = std::move(poly);
      continue;
    }
    const Node& n = level.nodes[child];
    stack.push_back({n.child[1], geom::clip_polygon(poly, n.origin, n.direction, +1)});
    stack.push_back({n.child[0], geom::clip_polygon(poly, n.origin, n.direction, -1)});
  }
  return cells;
}

}  // namespace p3d::level
