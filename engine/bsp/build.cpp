// BSP construction by auto-partition with exact arithmetic, stopping at convex leaves.
//
// A fragment is a parameter range [t0, t1] of its source wall. Each end is an
// original wall end or the crossing of the wall with an earlier splitter line
// (its "cut"), so the side of every end relative to any splitter is decided
// exactly by geom::side_of / side_of_crossing: no epsilon, no lost or doubled pieces.
//
// Fragments on a splitter's line stay at its node. A cell stops splitting when the
// fragments inside it bound a convex region of one sector (convex.h): it becomes a
// leaf holding them, Doom's subsector (its edges' fragments are its ancestors'). A
// two-sided wall between two sectors never lies inside a leaf: it ends on a node's
// line with a sector either side. So every point of a closed sector is located in a
// leaf of that sector, and every other point gets its leaf's sector (Doom's rule).
//
// Index: Builder::run (the pipeline), split_or_leaf (leaf or splitter), choose_greedy /
// score (strategies), partition (classify + split), make_leaf / edge_sector.
#include "engine/bsp/build.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <numeric>
#include <span>
#include <tuple>

#include "engine/bsp/convex.h"
#include "engine/geom/polygon.h"
#include "engine/util/limits.h"
#include "engine/util/radix_sort.h"
#include "engine/util/rng.h"

namespace p3d::bsp {

using geom::IPoint;
using geom::Line;
using geom::Vec2;

std::optional<Strategy> parse_strategy(const std::string& name) {
  if (name == "first") return Strategy::kFirst;
  if (name == "random") return Strategy::kRandom;
  if (name == "freesplit") return Strategy::kFreeSplit;
  if (name == "greedy") return Strategy::kGreedy;
  return std::nullopt;
}

const char* strategy_name(Strategy s) {
  switch (s) {
    case Strategy::kFirst: return "first";
    case Strategy::kRandom: return "random";
    case Strategy::kFreeSplit: return "freesplit";
    case Strategy::kGreedy: return "greedy";
  }
  return "?";
}

double Stats::random_bound() const { return walls + 2.0 * walls * std::log(std::max<double>(walls, 1)); }

namespace {

// A piece of a wall, with the wall's line at hand: classifying fragments is most of
// the build, and a line looked up by wall index was a cache miss of its own.
struct Frag {
  Line line;  // its wall's
  double t[2];
  uint32_t wall;
  int32_t cut[2];
  uint32_t line_number : 24;  // its wall's line (walls on one line share it; limits::kMaxWalls fits)
  uint32_t on_boundary0 : 1;  // this end lies on an ancestor's splitter line (free-split bookkeeping)
  uint32_t on_boundary1 : 1;
  uint32_t either_side : 1;   // the side facing its cell's region: either, or 0 (a one-sided wall's front)
  uint32_t barrier : 1;       // its wall is a barrier (Builder::barrier)

  int side() const { return either_side ? -1 : 0; }
};
static_assert(limits::kMaxWalls <= (size_t{1} << 24), "a line number fits in Frag::line_number");
static_assert(sizeof(Frag) == 64, "a fragment fills one cache line");

// A convex cell vertex; the edge from it to the next vertex lies on node `node`'s
// line (kNone: the outer box), with the cell on that node's front side or not.
struct CellVertex {
  Vec2 p;
  int32_t node;
  bool front;
};
using Cell = std::vector<CellVertex>;

// A cell still to split. Its fragments lie by value in the builder's stack of them
// (Builder::frags_), the tasks' ranges in the order of the tasks, so the task taken
// holds the last range: partitioning reads them in order and writes each side's in
// order in their place (as quicksort moves keys), where fragments named by index cost
// a cache miss each at every level, and a vector per cell was memory freed and faulted
// in again at every level (a sixth of a million walls' compile, zeroing pages).
struct Task {
  size_t first, count;  // its fragments: frags_[first, first + count)
  Cell cell;
  int32_t parent;  // node index, or kNone for the root
  int slot;        // 0 front, 1 back
  int depth;
};

class Builder {
 public:
  // A source given as `consumable` (the same object as src) loses its walls, vertices
  // and grid once the level holds them: a big map's two copies never coexist for long.
  Builder(const map::Source& src, const Options& opt, map::Source* consumable)
      : src_(src), consumable_(consumable), opt_(opt), rng_(opt.seed) {}

  level::Level run(Stats* stats) {
    copy_source();
    const geom::BBox vertex_bounds = vertex_box();  // before the consumable source loses them
    segments_only_ = std::all_of(out_.walls.begin(), out_.walls.end(), [](const level::Wall& w) { return w.segment(); });
    if (consumable_) {
      std::vector<map::Wall>().swap(consumable_->walls);
      std::vector<map::Vertex>().swap(consumable_->vertices);
    }
    lines_.reserve(out_.walls.size());
    sectors_.reserve(out_.walls.size());
    for (const level::Wall& w : out_.walls) {
      lines_.push_back(w.line());
      // A one-sided wall's back is the default sector (or the void); a plain segment has none.
      sectors_.push_back(w.segment() ? std::array{kNeutral, kNeutral}
                                     : std::array{w.sides[0].sector, w.two_sided() ? w.sides[1].sector : src_.default_sector});
    }
    number_lines();
    std::vector<uint32_t> order(out_.walls.size());
    for (uint32_t i = 0; i < order.size(); ++i) order[i] = i;
    if (opt_.strategy != Strategy::kFirst) rng_.shuffle(order);
    std::vector<Frag> all;
    all.reserve(order.size() + order.size() / 4);  // the build's stack of fragments: room for splits
    for (uint32_t i : order)
      all.push_back({lines_[i], {0.0, 1.0}, i, {level::kNone, level::kNone}, line_of_[i], 0, 0, !one_sided(i), barrier(i)});
    std::vector<uint32_t>().swap(line_of_);    std::vector<uint32_t>().swap(order);
    // Room for a few splits, and for a node per fragment at most: a big map's vectors
    // are not copied as they grow (for a moment, twice their size). Room never
    // written is never given pages.
    const size_t room = all.size() + all.size() / 8;
    out_.fragments.reserve(room);
    out_.nodes.reserve(room);
    out_.leaves.reserve(room + 1);
    pending_ = all.size();
    build_tree(std::move(all), vertex_bounds);
    level::derive_geometry(out_);
    level::derive_shading(out_);
    compute_bounding_boxes();
    resolve_leaves_by_ray_cast();
    level::place_in_sectors(out_);  // in the finished tree, whose leaves all know their sector
    check_player_start();
    if (stats) fill_stats(*stats);
    return std::move(out_);
  }

 private:
  // ---- source -> level records -------------------------------------------
  // A source picture as the level keeps it; pictures already in columns move out of a
  // consumable source (p is then *consumable) rather than being copied.
  template <typename Picture>  // map::Texture or map::SpriteImage
  static level::Texture level_texture(const Picture& p, Picture* consumable) {
    const int w = p.image.width, h = p.image.height;
    if (!p.opaque.empty()) {  // imported without colours: a level to be written only
      if (consumable)
        return level::make_texture_without_colours(p.name, w, h, std::move(consumable->indices), std::move(consumable->opaque));
      return level::make_texture_without_colours(p.name, w, h, p.indices, p.opaque);
    }
    if (!p.column_major)
      return level::make_texture(p.name, w, h, p.image.pixels.data(), p.indices.empty() ? nullptr : p.indices.data());
    if (consumable)
      return level::make_texture_from_columns(p.name, w, h, std::move(consumable->image.pixels), std::move(consumable->indices));
    return level::make_texture_from_columns(p.name, w, h, p.image.pixels, p.indices);
  }

  void copy_source() {
    out_.title = src_.title;
    out_.palette = src_.palette;
    out_.light_maps = src_.light_maps;
    out_.textures.reserve(src_.textures.size() + src_.sprite_images.size());  // exact sizes: no growth slack
    out_.sectors.reserve(src_.sectors.size());
    out_.walls.reserve(src_.walls.size());
    out_.things.reserve(src_.things.size());
    for (size_t i = 0; i < src_.textures.size(); ++i)
      out_.textures.push_back(level_texture(src_.textures[i], consumable_ ? &consumable_->textures[i] : nullptr));
    auto flat = [](int texture) { return texture == map::kSkyTexture ? level::kSky : texture; };
    for (const map::Sector& s : src_.sectors)
      out_.sectors.push_back(
          {s.name, s.floor, s.ceiling, s.light, flat(s.floor_texture), flat(s.ceiling_texture), s.special, s.tag});
    for (const map::PartOffsets& p : src_.part_offsets) {  // the sides name them by the same index
      level::PartOffsets& out = out_.part_offsets.emplace_back();
      std::copy(std::begin(p.x), std::end(p.x), out.x);
      std::copy(std::begin(p.y), std::end(p.y), out.y);
    }
    for (size_t i = 0; i < src_.walls.size(); ++i) {
      const map::Wall& w = src_.walls[i];
      level::Wall lw;
      lw.p1 = src_.point(w.v1);
      lw.p2 = src_.point(w.v2);
      lw.flags = wall_flags(w);
      lw.source = w.source == map::kNone ? int32_t(i) : w.source;
      lw.special = w.special;
      lw.tag = w.tag;
      lw.sides[0] = side(w.front);
      lw.sides[1] = side(w.back);
      out_.walls.push_back(lw);
    }
    for (size_t k = 0; k < src_.sprite_images.size(); ++k) {
      const map::SpriteImage& i = src_.sprite_images[k];
      out_.sprite_images.push_back({int32_t(out_.textures.size()), i.left, i.top});
      out_.textures.push_back(level_texture(i, consumable_ ? &consumable_->sprite_images[k] : nullptr));
    }
    for (const map::SpriteFrame& f : src_.sprites) {
      level::SpriteFrame lf;
      lf.name = f.name;
      std::copy(std::begin(f.image), std::end(f.image), lf.image);
      std::copy(std::begin(f.flip), std::end(f.flip), lf.flip);
      lf.bright = f.bright;
      lf.hanging = f.hanging;
      lf.drop = f.drop;
      out_.sprite_frames.push_back(lf);
    }
    for (const map::Thing& t : src_.things) out_.things.push_back({t.type, t.pos, t.angle, t.flags, t.sprite, t.sector});
    out_.player_start = src_.player.pos;
    out_.player_angle = src_.player.angle;
    out_.default_sector = src_.default_sector;
    out_.sky_texture = src_.sky_texture;
    out_.animations = src_.animations;
    if (consumable_ && consumable_->grid) {  // moved: 17 bytes a tile, 285 MB at 4096x4096
      map::GridInfo& g = *consumable_->grid;
      out_.grid = level::Grid{g.cols, g.rows, g.cell, std::move(g.solid), std::move(g.faces)};
    } else if (src_.grid) {
      out_.grid = level::Grid{src_.grid->cols, src_.grid->rows, src_.grid->cell, src_.grid->solid, src_.grid->faces};
    }
  }

  static level::Side side(const map::Side& s) {
    return {s.sector, s.upper, s.middle, s.lower, s.x_offset, s.y_offset, s.parts, s.light};
  }

  static uint32_t wall_flags(const map::Wall& w) {
    const std::pair<unsigned, uint32_t> pairs[] = {{map::kUnpegUpper, level::kUnpegUpper}, {map::kUnpegLower, level::kUnpegLower},
                                                   {map::kImpassable, level::kImpassable}, {map::kSecret, level::kSecret},
                                                   {map::kHidden, level::kHidden},         {map::kMapped, level::kMapped}};
    uint32_t flags = w.segment ? uint32_t{level::kSegment} : 0u;
    for (const auto& [from, to] : pairs)
      if (w.flags & from) flags |= to;
    return flags;
  }

  // Walls on one line share a number (line_of_): a line's direction in lowest terms,
  // pointing right (or up), and its offset, exact. The numbers only tell lines apart:
  // walls are grouped by a hash of their line's key, radix-sorted (a sort of the keys
  // was a fortieth of compiling a million walls), and a group that holds more than one
  // key (a collision) is sorted by key.
  void number_lines() {
    using Key = std::array<int64_t, 3>;  // dx, dy, offset
    std::vector<Key> keys(lines_.size());
    std::vector<std::pair<uint32_t, uint32_t>> by_hash(lines_.size());  // (hash, wall)
    for (uint32_t w = 0; w < lines_.size(); ++w) {
      int64_t dx = lines_[w].d.x, dy = lines_[w].d.y;
      const int64_t g = std::gcd(dx, dy);
      dx /= g, dy /= g;
      if (dx < 0 || (dx == 0 && dy < 0)) dx = -dx, dy = -dy;
      keys[w] = {dx, dy, dx * lines_[w].a.y - dy * lines_[w].a.x};
      uint64_t h = 0;
      for (const int64_t part : keys[w]) h = mix64(h ^ uint64_t(part));
      by_hash[w] = {uint32_t(h >> 32), w};  // 32 bits: three radix passes, and a collision costs only a sort
    }
    radix_sort_by_key(by_hash);
    line_of_.resize(lines_.size());
    uint32_t line = 0;
    for (size_t begin = 0; begin < by_hash.size();) {
      size_t end = begin + 1;
      while (end < by_hash.size() && by_hash[end].first == by_hash[begin].first) ++end;
      const auto key_of = [&](const std::pair<uint32_t, uint32_t>& e) -> const Key& { return keys[e.second]; };
      if (end - begin > 1 && std::any_of(by_hash.begin() + ptrdiff_t(begin), by_hash.begin() + ptrdiff_t(end),
                                         [&](const auto& e) { return key_of(e) != key_of(by_hash[begin]); }))
        std::sort(by_hash.begin() + ptrdiff_t(begin), by_hash.begin() + ptrdiff_t(end),
                  [&](const auto& a, const auto& b) { return key_of(a) < key_of(b); });
      line_of_[by_hash[begin].second] = line;
      for (size_t i = begin + 1; i < end; ++i) {
        if (key_of(by_hash[i]) != key_of(by_hash[i - 1])) ++line;
        line_of_[by_hash[i].second] = line;
      }
      ++line;
      begin = end;
    }
  }

  // ---- the tree ------------------------------------------------------------
  geom::BBox vertex_box() const {
    geom::BBox box;
    for (const map::Vertex& v : src_.vertices) box.add(geom::to_world(v.pos));
    return box;
  }

  void build_tree(std::vector<Frag> all, geom::BBox box) {
    const double margin = 64 + 0.01 * std::max(box.max.x - box.min.x, box.max.y - box.min.y);
    box.min -= Vec2(margin);
    box.max += Vec2(margin);
    Cell root;
    for (Vec2 p : geom::box_polygon(box)) root.push_back({p, level::kNone, false});

    frags_ = std::move(all);
    std::vector<Task> stack;
    stack.push_back({0, frags_.size(), std::move(root), level::kNone, 0, 0});
    while (!stack.empty()) {
      Task task = std::move(stack.back());
      stack.pop_back();
      max_depth_ = std::max<size_t>(max_depth_, task.depth);
      const std::optional<Splitter> splitter = split_or_leaf(task);
      if (!splitter) {
        frags_.resize(task.first);  // the leaf holds them now
        continue;
      }
      const int32_t node = static_cast<int32_t>(out_.nodes.size());
      link(task, node);
      out_.nodes.push_back({});
      out_.nodes[node].splitter = splitter->line;
      if (splitter->spans) ++free_splits_;  // it cannot cut anything: free
      const size_t backs = partition(task.first, int32_t(splitter->line), node);
      const size_t fronts = frags_.size() - task.first - backs;
      release_stack_room();

      const Line& l = lines_[splitter->line];
      stack.push_back({task.first, backs, clip(task.cell, l, node, false), node, 1, task.depth + 1});
      stack.push_back({task.first + backs, fronts, clip(task.cell, l, node, true), node, 0, task.depth + 1});
    }
    std::vector<Frag>().swap(frags_);
    front_side_.reset(), front_room_ = 0;
  }

  // The stack of fragments shrinks as leaves take them: once it holds under a quarter
  // of its room, it moves to room for twice what it holds, and the memory left goes
  // back for the tree's records to take; so does partition's scratch once no cell
  // left is as big as a quarter of it.
  void release_stack_room() {
    constexpr size_t kSmall = size_t{1} << 16;
    if (front_room_ > kSmall && frags_.size() * 4 < front_room_) front_side_.reset(), front_room_ = 0;
    if (frags_.capacity() < kSmall || frags_.size() * 4 > frags_.capacity()) return;
    std::vector<Frag> smaller;
    smaller.reserve(frags_.size() * 2);
    smaller.assign(frags_.begin(), frags_.end());
    frags_.swap(smaller);
  }

  std::span<const Frag> frags_of(const Task& task) const { return {frags_.data() + task.first, task.count}; }

  void link(const Task& task, int32_t child) {
    if (task.parent != level::kNone) out_.nodes[task.parent].child[task.slot] = child;
  }

  // Fragments on the splitter's line stay at its node (partition hands them over in order).
  void place_on_node(int32_t node, const Frag& f) {
    level::Node& n = out_.nodes[node];
    if (n.fragment_count++ == 0) n.first_fragment = static_cast<uint32_t>(out_.fragments.size());
    out_.fragments.push_back({f.wall, {f.cut[0], f.cut[1]}, f.t[0], f.t[1], 0});
    shortest_ = std::min(shortest_, (f.t[1] - f.t[0]) * length(f.line));
  }

  void count_placed(size_t fragments) {
    placed_ += fragments;
    pending_ -= fragments;
    if (opt_.progress && placed_ >= next_progress_) {
      next_progress_ = placed_ + 65536;
      opt_.progress(double(placed_) / double(placed_ + pending_));
    }
  }

  static constexpr size_t kNoFragment = SIZE_MAX;
  static constexpr size_t kTestFirst = 48;  // cells this small are tested for a leaf before a search

  // A node's line: a line number (lines_), and whether a fragment on it spans the cell.
  struct Splitter {
    uint32_t line;
    bool spans = false;
  };

  // Greedy's choice: the sampled candidate of least cost, and whether the sample shows
  // fragments on both sides of it (else it only takes its line's fragments off the cell).
  struct Choice {
    size_t fragment = kNoFragment;
    bool divides = false;
    bool any_divides = false;  // some candidate scored did
    size_t progress = 0;       // sampled fragments it takes from the bigger side's cell (on its line, or beyond)
  };

  // Makes the task's cell a leaf (returning nothing) when its fragments bound a convex
  // region of one sector; otherwise returns the line to split it along.
  std::optional<Splitter> split_or_leaf(Task& task) {
    const std::span<const Frag> frags = frags_of(task);
    if (frags.empty()) {
      make_leaf(task, level::kNone);
      return std::nullopt;
    }
    auto along = [&](size_t i) { return Splitter{frags[i].wall, spans_cell(frags[i])}; };
    const bool greedy = opt_.strategy == Strategy::kGreedy;
    // Big cells are rarely leaves: a splitter the sample proves to divide the cell
    // spares the exact test and the look at every fragment's sectors (a cache miss
    // each). Small ones are tested first (cheaper than a search). A wall's line that
    // leaves one side nearly empty gives way to a free line that halves the cell.
    const bool test_first = !greedy || frags.size() <= kTestFirst;
    Choice chosen;
    if (!test_first) {
      chosen = choose_greedy(frags);
      if (chosen.divides && !lopsided(chosen, frags.size())) return along(chosen.fragment);
      if (chosen.divides) return free_or(along(chosen.fragment));
    }
    const Sectors sectors = cell_sectors(frags);
    const bool one_sector = sectors.other == kNoFragment && sectors.barrier == kNoFragment;
    if (greedy && test_first && !one_sector) {
      chosen = choose_greedy(frags);
      if (chosen.divides && !lopsided(chosen, frags.size())) return along(chosen.fragment);
      if (chosen.divides) return free_or(along(chosen.fragment));
    }
    const ConvexTest convex = convex_region(FragPieces{frags, *this}, convex_sides_, convex_order_);
    if (convex.convex && one_sector) {
      make_leaf(task, sectors.sector);
      return std::nullopt;
    }
    if (!greedy) {
      const size_t pick = choose_simple(frags);
      if (divides(frags, pick)) return along(pick);
    } else if (chosen.fragment == kNoFragment) {
      chosen = choose_greedy(frags);
    }
    // No candidate halves the cell: most walls' lines peel a few walls off it (a nearly
    // convex room; an arc of walls between two sectors, which each need a node), each
    // split passing over the rest. A free line, if one halves it.
    if (greedy && lopsided(chosen, frags.size()))
      if (const std::optional<uint32_t> line = choose_free()) return Splitter{*line};
    // The best candidate, though it only peels its line's fragments off the cell, if it
    // beat one that divides it.
    if (chosen.fragment != kNoFragment && (chosen.divides || chosen.any_divides)) return along(chosen.fragment);
    if (!convex.convex) return along(convex.witness);
    // Convex, but a two-sided wall between two sectors lies inside the cell, or its
    // walls face more than one sector (an unclosed sector): split along such a wall,
    // which the node takes, the others all on one side (as ZDBSP shoves a seg behind).
    return along(sectors.barrier != kNoFragment ? sectors.barrier : sectors.other);
  }

  // Whether the greedy choice leaves its bigger side's cell (in the sample) with all
  // but a small share of the fragments, in a cell big enough for a free line to pay.
  bool lopsided(const Choice& c, size_t fragments) const {
    if (fragments < size_t(opt_.free_min_fragments)) return false;
    return double(c.progress) < opt_.free_lopsided * double(sample_.size());
  }

  std::optional<Splitter> free_or(Splitter fallback) {
    if (const std::optional<uint32_t> line = choose_free()) return Splitter{*line};
    return fallback;
  }

  // ---- sectors -------------------------------------------------------------
  static constexpr int32_t kNeutral = -3;  // a plain segment: stands in whatever sector surrounds it

  bool one_sided(uint32_t wall) const { return !out_.walls[wall].segment() && !out_.walls[wall].two_sided(); }
  // A two-sided wall between two sectors (or a one-sided one with the default sector
  // behind): no leaf may hold it, so it ends on a node's line with a sector either side.
  bool barrier(uint32_t wall) const {
    const auto& s = sectors_[wall];
    return s[0] != kNeutral && s[1] != level::kNone && s[0] != s[1];
  }

  // The sector a cell's fragments face (their sides' but a barrier's are the same; a
  // one-sided wall faces its front's), with a fragment facing another and a barrier.
  struct Sectors {
    int32_t sector = level::kNone;  // kNone: only plain segments
    size_t other = kNoFragment;
    size_t barrier = kNoFragment;
  };
  Sectors cell_sectors(std::span<const Frag> frags) const {
    Sectors out;
    for (size_t i = 0; i < frags.size(); ++i) {
      const uint32_t w = frags[i].wall;
      if (frags[i].barrier) {
        if (out.barrier == kNoFragment) out.barrier = i;
        continue;
      }
      const int32_t s = sectors_[w][0];
      if (s == kNeutral) continue;
      if (out.sector == level::kNone) out.sector = s;
      else if (s != out.sector && out.other == kNoFragment) out.other = i;
    }
    return out;
  }

  // The cell's fragments for convex_region.
  struct FragPieces {
    std::span<const Frag> frags;
    const Builder& builder;
    size_t size() const { return frags.size(); }
    const Line& line(size_t i) const { return frags[i].line; }
    int side(size_t i) const { return frags[i].side(); }
    int end_side(size_t i, int k, const Line& l) const { return builder.end_side(frags[i], k, l); }
  };

  // ---- splitter choice -----------------------------------------------------
  static bool spans_cell(const Frag& f) { return f.on_boundary0 && f.on_boundary1; }

  // first, random, freesplit: the first fragment (a spanning one for freesplit, if any).
  size_t choose_simple(std::span<const Frag> frags) const {
    if (opt_.strategy == Strategy::kFreeSplit)
      for (size_t i = 0; i < frags.size(); ++i)
        if (spans_cell(frags[i])) return i;
    return 0;
  }

  // Whether fragment c's line leaves fragments on both of its sides (or c is a barrier,
  // which must become a splitter anyway).
  bool divides(std::span<const Frag> frags, size_t c) const {
    if (frags[c].barrier) return true;
    const Line& l = frags[c].line;
    bool front = false, back = false;
    for (const Frag& f : frags) {
      const int s0 = end_side(f, 0, l), s1 = end_side(f, 1, l);
      front |= s0 < 0 || s1 < 0;
      back |= s0 > 0 || s1 > 0;
      if (front && back) return true;
    }
    return false;
  }

  // Greedy: the sampled candidate of least cost, with what the sample shows of it.
  Choice choose_greedy(std::span<const Frag> frags) {
    const size_t m = frags.size();
    const size_t k = std::min<size_t>(m, std::max(1, opt_.greedy_candidates));
    const size_t samples = std::min<size_t>(m, std::max(1, opt_.greedy_sample));
    sample_.resize(samples);
    for (size_t i = 0; i < samples; ++i) {
      const Frag& f = frags[samples == m ? i : rng_.below(m)];
      sample_.set(i, f, f.barrier ? 1.0 : opt_.plain_weight);
    }
    sample_weight_ = 0;
    for (double w : sample_.weight) sample_weight_ += w;

    Choice best;
    double best_cost = INFINITY;
    scored_lines_.clear();
    for (size_t c = 0; c < k; ++c) {
      const size_t candidate = k == m ? c : rng_.below(m);
      const Frag& f = frags[candidate];
      // A line is scored once, whichever of its fragments is drawn.
      if (std::find(scored_lines_.begin(), scored_lines_.end(), f.line_number) != scored_lines_.end()) continue;
      scored_lines_.push_back(f.line_number);
      // The node takes the cell's fragments on its line: as many as the sample shows
      // (all of them when the sample is the cell), counted by line number rather than
      // by a look at every fragment of a big cell.
      const double bonus = opt_.line_weight * double(std::count(sample_.line.begin(), sample_.line.end(), f.line_number));
      Tally tally;
      const std::optional<double> cost = score(f.line, best_cost + bonus, tally);
      if (cost && *cost - bonus < best_cost)
        best_cost = *cost - bonus, best = {candidate, tally.divides, best.any_divides, samples - std::max(tally.front, tally.back)};
      best.any_divides |= cost && tally.divides;
    }
    return best;
  }

  // A free splitter for a cell that every sampled wall's line leaves nearly whole: the
  // best of lines through two of the sampled fragments' vertices (on a nearly convex
  // room a chord cuts nothing) and the vertical and horizontal lines through their
  // median vertex, scored as greedy scores walls. Taken if it divides the sample with
  // at least opt_.free_balance of it on either side and splits no more than half the
  // smaller side's fragments; nothing otherwise. Its line joins lines_ and the level's.
  // Uses the sample choose_greedy drew.
  std::optional<uint32_t> choose_free() {
    const size_t n = sample_.size();
    free_points_.clear();
    for (size_t i = 0; i < n; ++i)
      for (int k = 0; k < 2; ++k)
        if (!(sample_.cut[i] >> k & 1)) free_points_.push_back(sample_.ends[2 * i + k]);
    if (free_points_.size() < 2) return std::nullopt;
    std::vector<Line> candidates;
    for (int axis = 0; axis < 2; ++axis) {  // the vertical, then the horizontal line through the median
      const auto middle = free_points_.begin() + ptrdiff_t(free_points_.size() / 2);
      std::nth_element(free_points_.begin(), middle, free_points_.end(), [axis](IPoint a, IPoint b) {
        return axis == 0 ? std::tie(a.x, a.y) < std::tie(b.x, b.y) : std::tie(a.y, a.x) < std::tie(b.y, b.x);
      });
      // One unit along the axis, towards the origin: both points stay in range.
      constexpr int64_t unit = int64_t{1} << geom::kFracBits;
      const IPoint d = axis == 0 ? IPoint{0, middle->y > 0 ? -unit : unit} : IPoint{middle->x > 0 ? -unit : unit, 0};
      candidates.push_back({*middle, d});
    }
    for (int c = 0; c < opt_.free_candidates; ++c) {
      const IPoint p = free_points_[rng_.below(free_points_.size())], q = free_points_[rng_.below(free_points_.size())];
      if (!(p == q)) candidates.push_back(Line::through(p, q));
    }
    std::optional<Line> best;
    double best_cost = INFINITY;
    for (const Line& l : candidates) {
      Tally tally;
      const std::optional<double> cost = score(l, INFINITY, tally);
      const size_t smaller = std::min(tally.front, tally.back);
      if (!cost || !tally.divides || double(smaller) < opt_.free_balance * double(n) || 2 * tally.splits > smaller) continue;
      if (*cost < best_cost) best_cost = *cost, best = l;
    }
    if (!best) return std::nullopt;
    const uint32_t line = uint32_t(lines_.size());
    lines_.push_back(*best);
    out_.free_lines.push_back({best->a, {best->a.x + best->d.x, best->a.y + best->d.y}});
    return line;
  }

  // The fragments a candidate splitter is scored against, laid out for the scoring
  // loop: each end's point where it is an original wall end (most are), else its
  // rounded point and the fragment itself for the exact crossing test; each wall's
  // length for slivers, measured when first split; its weight in the balance.
  struct Sample {
    std::vector<IPoint> ends;        // 2 per fragment
    std::vector<Vec2> rounded;       // 2 per fragment: a crossing end's point, to within 2^-19 (score's filter)
    std::vector<const Frag*> frags;
    std::vector<uint8_t> cut;        // bit k: end k is a crossing
    std::vector<double> length;      // < 0: not measured yet
    std::vector<double> weight;
    std::vector<uint32_t> line;      // its line's number

    void resize(size_t n) {
      ends.resize(2 * n), rounded.resize(2 * n), frags.resize(n), cut.resize(n), length.resize(n), weight.resize(n),
          line.resize(n);
    }
    size_t size() const { return frags.size(); }
    void set(size_t i, const Frag& f, double w) {
      const IPoint far{f.line.a.x + f.line.d.x, f.line.a.y + f.line.d.y};
      for (int k = 0; k < 2; ++k) {
        ends[2 * i + k] = f.cut[k] != level::kNone ? IPoint{} : f.t[k] == 0 ? f.line.a : far;
        // t is the exact crossing's parameter to within 2^-49 (crossing_param's three
        // roundings, then kept inside), so the point is within 2^-19 of it: |d| <= 2^30.
        if (f.cut[k] != level::kNone)
          rounded[2 * i + k] = Vec2(double(f.line.a.x) + f.t[k] * double(f.line.d.x), double(f.line.a.y) + f.t[k] * double(f.line.d.y));
      }
      cut[i] = uint8_t((f.cut[0] != level::kNone) | (f.cut[1] != level::kNone) << 1);
      frags[i] = &f;
      length[i] = -1;
      weight[i] = w;
      line[i] = f.line_number;
    }
  };

  // Greedy's cost of splitting along the candidate's line: splits, the imbalance between
  // the sides (barriers weigh most: each ends on a node of its own; walls that are not
  // add to a leaf), slivers, and a peel (no fragment on one side); or nothing once it
  // cannot come under `to_beat`. `divides` tells whether the sample shows fragments on
  // both sides.
  struct Tally {
    bool divides = false;
    size_t front = 0, back = 0, splits = 0;  // sampled fragments on each side (a split one on both), split
  };
  std::optional<double> score(const Line& l, double to_beat, Tally& tally) {
    const size_t n = sample_.size();
    // Hot: the sample's arrays in locals (the stores below cannot move them), and the
    // side of a point as one difference of products less the line's own: exact in 64
    // bits, each term under 2^60 for coordinates within geom::kMaxFixed.
    const IPoint* ends = sample_.ends.data();
    const uint8_t* cut = sample_.cut.data();
    const double* weight = sample_.weight.data();
    const int64_t dx = l.d.x, dy = l.d.y, offset = dx * l.a.y - dy * l.a.x;
    double front = 0, back = 0, left = sample_weight_;
    int64_t splits = 0, slivers = 0;
    size_t fronts = 0, backs = 0;
    for (size_t block = 0; block < n; block += 8) {
      // Stop once this candidate cannot win (the same choice, sooner): splits and
      // slivers only add, and the fragments left can close the imbalance by at most
      // their weight.
      if (block > 0 && opt_.split_weight * double(splits) + opt_.sliver_weight * double(slivers) +
                               opt_.balance_weight * std::max(0.0, std::fabs(front - back) - left) >=
                           to_beat)
        return std::nullopt;
      for (size_t i = block, end = std::min(n, block + 8); i < end; ++i) {
        // Each end's side as a value whose sign tells it (> 0 left, < 0 right).
        int64_t v0 = dx * ends[2 * i].y - dy * ends[2 * i].x - offset;
        int64_t v1 = dx * ends[2 * i + 1].y - dy * ends[2 * i + 1].x - offset;
        if (cut[i]) [[unlikely]] {
          if (cut[i] & 1) v0 = crossing_side(i, 0, l);
          if (cut[i] & 2) v1 = crossing_side(i, 1, l);
        }
        const double w = weight[i];
        left -= w;
        const bool to_front = (v0 | v1) < 0, to_back = v0 > 0 || v1 > 0;
        front += w * double(to_front);  // w or +0: the same sums as adding w where it goes
        back += w * double(to_back);
        fronts += to_front, backs += to_back;
        if (to_front && to_back) [[unlikely]] {  // an end on either side
          ++splits;
          slivers += leaves_sliver(i, l);
        }
      }
    }
    tally = {fronts > 0 && backs > 0, fronts, backs, size_t(splits)};
    return (tally.divides ? 0.0 : opt_.peel_weight) + opt_.split_weight * double(splits) +
           opt_.balance_weight * std::fabs(front - back) + opt_.sliver_weight * double(slivers);
  }

  // The side of sampled fragment i's end k, a crossing, relative to l: in doubles from
  // its rounded point where that cannot be wrong, else exact (geom::side_of_crossing's
  // 128-bit products). The double value's error is under 2^13 fixed units squared:
  // the point's 2^-19 times |l.d| <= 2^30 for each term, and each product's and
  // difference's rounding (values under 2^61); most crossings lie far further from l.
  // (Only the choice of splitter rests on it: partition places every piece exactly.)
  int crossing_side(size_t i, int k, const Line& l) const {
    constexpr double kMargin = 65536;  // 2^16: eight times the error
    const Vec2 p = sample_.rounded[2 * i + k];
    const double v = double(l.d.x) * (p.y - double(l.a.y)) - double(l.d.y) * (p.x - double(l.a.x));
    if (std::fabs(v) > kMargin) return v > 0 ? 1 : -1;
    return end_side(*sample_.frags[i], k, l);
  }

  // Whether l splits sampled fragment i into a piece shorter than kSliverLength.
  [[gnu::noinline]] bool leaves_sliver(size_t i, const Line& l) {
    const Frag& f = *sample_.frags[i];
    const double t = geom::crossing_param(f.line, l);
    double& wall_length = sample_.length[i];
    if (wall_length < 0) wall_length = length(f.line);
    return std::min(t - f.t[0], f.t[1] - t) * wall_length < kSliverLength;
  }

  // ---- exact classification ------------------------------------------------
  int end_side(const Frag& f, int k, const Line& l) const {
    if (f.cut[k] == level::kNone) {
      const Line& w = f.line;
      return geom::side_of(l, f.t[k] == 0 ? w.a : IPoint{w.a.x + w.d.x, w.a.y + w.d.y});
    }
    return geom::side_of_crossing(l, f.line, lines_[f.cut[k]]);
  }

  // The last task's fragments, from frags_[first] on, become the back side's (left of
  // the splitter, side > 0) then the front side's (right, side < 0), each in order;
  // fragments on its line go to the node. Returns the back side's count. In place:
  // a fragment gives the back side one piece at most, written where one was read,
  // while the front side's pieces wait in front_side_ and then follow.
  size_t partition(size_t first, int32_t splitter, int32_t node) {
    const Line& l = lines_[size_t(splitter)];
    const size_t count = frags_.size() - first;
    sides_.resize(count);
    size_t fronts = 0, backs = 0;
    for (size_t k = 0; k < count; ++k) {
      const Frag& f = frags_[first + k];
      const int s0 = end_side(f, 0, l), s1 = end_side(f, 1, l);
      sides_[k] = {int8_t(s0), int8_t(s1)};
      fronts += s0 < 0 || s1 < 0;
      backs += s0 > 0 || s1 > 0;
    }
    if (front_room_ < fronts) front_side_.reset(new Frag[front_room_ = fronts]);  // scratch: left unset
    Frag* const task = frags_.data() + first;
    Frag* back = task;
    Frag* front = front_side_.get();
    for (size_t k = 0; k < count; ++k) {
      Frag f = task[k];
      const auto [s0, s1] = sides_[k];
      if (s0 == 0 && s1 == 0) {
        place_on_node(node, f);
        continue;
      }
      if (s0 == 0) f.on_boundary0 = 1;
      if (s1 == 0) f.on_boundary1 = 1;
      if (s0 <= 0 && s1 <= 0) {
        *front++ = f;
      } else if (s0 >= 0 && s1 >= 0) {
        *back++ = f;
      } else {
        const Frag tail = split(f, splitter);
        *(s0 < 0 ? front : back)++ = f;
        *(s1 < 0 ? front : back)++ = tail;
      }
    }
    frags_.resize(first + backs);
    frags_.insert(frags_.end(), front_side_.get(), front);
    count_placed(out_.nodes[size_t(node)].fragment_count);
    return backs;
  }

  // Cuts f where `cutter`'s line crosses it: f keeps [t0, t], the piece returned gets [t, t1].
  Frag split(Frag& f, int32_t cutter) {
    double t = geom::crossing_param(f.line, lines_[cutter]);
    // The exact crossing is strictly inside; keep the rounded one strictly inside too.
    t = std::clamp(t, std::nextafter(f.t[0], 2.0), std::nextafter(f.t[1], -1.0));
    Frag tail = f;
    f.t[1] = t;
    f.cut[1] = cutter;
    f.on_boundary1 = 1;
    tail.t[0] = t;
    tail.cut[0] = cutter;
    tail.on_boundary0 = 1;
    ++pending_;
    return tail;
  }

  // A fragment's wall's length in map units (from the line it carries: no look-up).
  static double length(const Line& line) {
    const double x = double(line.d.x), y = double(line.d.y);  // far from overflow: std::hypot's care is not needed
    return std::sqrt(x * x + y * y) / geom::kFixedOne;
  }

  // ---- cells and leaves ----------------------------------------------------
  // Sutherland-Hodgman on a tagged convex cell: a vertex's tag describes the edge leaving it.
  static Cell clip(const Cell& cell, const Line& l, int32_t node, bool keep_front) {
    const Vec2 origin = geom::to_world(l.a);
    const Vec2 dir = Vec2(double(l.d.x), double(l.d.y));
    const double keep = keep_front ? -1 : 1;
    Cell out;
    for (size_t i = 0; i < cell.size(); ++i) {
      const CellVertex& p = cell[i];
      const CellVertex& q = cell[(i + 1) % cell.size()];
      const double sp = geom::cross(dir, p.p - origin) * keep, sq = geom::cross(dir, q.p - origin) * keep;
      auto crossing = [&] { return p.p + (q.p - p.p) * (sp / (sp - sq)); };
      if (sp >= 0) {
        out.push_back(p);
        if (sq < 0) {  // leaving the kept side: the next edge runs along the splitter
          if (sp > 0) out.push_back({crossing(), node, keep_front});
          else out.back().node = node, out.back().front = keep_front;
        }
      } else if (sq > 0) {  // entering: the edge from x continues p's edge
        out.push_back({crossing(), p.node, p.front});
      }
    }
    return out.size() >= 3 ? out : Cell{};
  }

  // The task's fragments become the leaf's, facing the sides convex_region chose
  // (convex_sides_). A leaf whose fragments face no sector (it holds none, or plain
  // segments only) takes the sector of a wall along its edges facing it, or failing
  // that (only segments near) one found by a ray cast once the tree is done; in a map
  // of plain segments, the default sector.
  void make_leaf(const Task& task, int32_t sector) {
    const int32_t leaf = static_cast<int32_t>(out_.leaves.size());
    link(task, level::leaf_child(leaf));
    {
      level::Leaf& l = out_.leaves.emplace_back();
      l.sector = sector;
      l.first_fragment = static_cast<uint32_t>(out_.fragments.size());
      l.fragment_count = static_cast<uint32_t>(task.count);
    }
    const std::span<const Frag> frags = frags_of(task);
    for (size_t i = 0; i < frags.size(); ++i) {
      const Frag& f = frags[i];
      out_.fragments.push_back({f.wall, {f.cut[0], f.cut[1]}, f.t[0], f.t[1], convex_sides_[i]});
      shortest_ = std::min(shortest_, (f.t[1] - f.t[0]) * length(f.line));
    }
    count_placed(task.count);
    leaf_depth_sum_ += task.depth;
    if (sector == level::kNone && segments_only_) {
      out_.leaves.back().sector = out_.default_sector;  // a map of plain segments has no other
    } else if (sector == level::kNone && !edge_sector(task.cell, out_.leaves.back().sector)) {
      geom::Polygon poly;
      for (const CellVertex& v : task.cell) poly.push_back(v.p);
      unresolved_.push_back({leaf, poly.empty() ? Vec2(0) : geom::polygon_centroid(poly)});
    }
  }

  // The sector of a wall lying along one of the cell's edges (on an ancestor's line), on
  // its side facing the cell; behind a one-sided wall, its front's (Doom's rule: the
  // void behind a wall is in the sector of the subsector holding its seg), unless
  // another edge's wall faces the cell.
  bool edge_sector(const Cell& cell, int32_t& sector) const {
    int32_t behind = level::kNone;
    for (size_t i = 0; i < cell.size(); ++i) {
      if (cell[i].node == level::kNone) continue;
      const Vec2 mid = (cell[i].p + cell[(i + 1) % cell.size()].p) * 0.5;
      const level::Node& node = out_.nodes[cell[i].node];
      for (uint32_t k = node.first_fragment; k < node.first_fragment + node.fragment_count; ++k) {
        const level::Fragment& f = out_.fragments[k];
        const level::Wall& w = out_.walls[f.wall];
        if (w.segment()) continue;
        const Vec2 a = geom::to_world(w.p1), e = geom::to_world(w.p2) - a;
        const double t = glm::dot(mid - a, e) / glm::dot(e, e);
        const double eps = 1e-9 + 1e-7 / std::sqrt(glm::dot(e, e));
        if (t <= f.t0 + eps || t >= f.t1 - eps) continue;
        const Line& splitter = lines_[node.splitter];
        const bool same_direction = double(splitter.d.x) * e.x + double(splitter.d.y) * e.y > 0;
        const bool on_right_of_wall = cell[i].front == same_direction;
        const int32_t faced = on_right_of_wall ? w.sides[0].sector : w.two_sided() ? w.sides[1].sector : src_.default_sector;
        if (faced != level::kNone) {
          sector = faced;
          return true;
        }
        if (behind == level::kNone) behind = w.sides[0].sector;
      }
    }
    sector = behind;
    return behind != level::kNone;
  }

  // Leaves facing no sector: the first wall a ray from inside meets tells the sector (its
  // front's when the ray meets the back of a one-sided wall). A map of plain segments
  // has none: make_leaf gave each its default sector.
  void resolve_leaves_by_ray_cast() {
    for (const auto& [leaf, inside] : unresolved_) out_.leaves[leaf].sector = ray_cast_sector(inside);
  }

  int32_t ray_cast_sector(Vec2 origin) const {
    for (int attempt = 0; attempt < 16; ++attempt) {
      const double angle = 0.3 + attempt * 2.39996;  // golden-angle steps avoid repeating a bad direction
      const Vec2 dir{std::cos(angle), std::sin(angle)};
      int32_t sector = level::kNone;
      bool ambiguous = false, found = false;
      level::ray_cast(out_, origin, dir, [&](uint32_t wall, double, double t) {
        const level::Wall& w = out_.walls[wall];
        if (t < 1e-9 || t > 1 - 1e-9) {  // through a vertex: the side is unclear, try another ray
          ambiguous = true;
          return false;
        }
        if (w.segment()) return true;
        const bool right = geom::cross(w.b - w.a, origin - w.a) < 0;
        sector = right ? w.sides[0].sector : w.two_sided() ? w.sides[1].sector : src_.default_sector;
        if (sector == level::kNone) sector = w.sides[0].sector;  // behind a one-sided wall (Doom's rule, as edge_sector)
        found = true;
        return false;
      });
      if (ambiguous) continue;
      return found ? sector : out_.default_sector;
    }
    return out_.default_sector;
  }

  // Children come after their parent: each node's box from its fragments' and its children's.
  void compute_bounding_boxes() {
    for (size_t i = out_.nodes.size(); i-- > 0;) {
      level::Node& n = out_.nodes[i];
      n.bbox = geom::BBox{};
      for (uint32_t k = n.first_fragment; k < n.first_fragment + n.fragment_count; ++k) {
        n.bbox.add(out_.fragments[k].p0);
        n.bbox.add(out_.fragments[k].p1);
      }
      for (int32_t c : n.child)
        n.bbox.add(level::is_leaf(c) ? out_.leaves[size_t(level::leaf_index(c))].bbox : out_.nodes[size_t(c)].bbox);
    }
  }

  // A hand-written map's sectors are closed: crossing parity tells whether the start is in one.
  void check_player_start() const {
    if (!opt_.player_must_be_inside || out_.sectors.empty() ||
        level::sector_at_brute_force(out_, out_.player_start) != level::kNone)
      return;
    throw Error(src_.player.loc, "player start is outside every sector");
  }

  void fill_stats(Stats& s) const {
    s.walls = out_.walls.size();
    s.fragments = out_.fragments.size();
    s.splits = s.fragments - s.walls;
    s.nodes = out_.nodes.size();
    s.leaves = out_.leaves.size();
    s.free_splits = free_splits_;
    s.free_lines = out_.free_lines.size();
    s.max_depth = max_depth_;
    s.mean_depth = s.leaves ? double(leaf_depth_sum_) / s.leaves : 0;
    s.shortest_fragment = shortest_;
    s.ray_cast_leaves = unresolved_.size();
    s.segs = 0;
    for (const level::Fragment& f : out_.fragments) s.segs += out_.walls[f.wall].two_sided() ? 2 : 1;
    s.empty_leaves = size_t(std::count_if(out_.leaves.begin(), out_.leaves.end(), [](const level::Leaf& l) { return l.fragment_count == 0; }));
  }

  const map::Source& src_;
  map::Source* consumable_;
  const Options& opt_;
  Rng rng_;
  std::vector<Line> lines_;                       // one per wall, then the free splitters' (line numbers)
  std::vector<std::array<int32_t, 2>> sectors_;   // one per wall: its sides' sectors (kNeutral: a segment)
  std::vector<uint32_t> line_of_;                 // one per wall, until its fragments carry it: its line
  std::vector<uint32_t> scored_lines_;            // choose_greedy's scratch: the lines scored in this cell
  std::vector<IPoint> free_points_;               // choose_free's scratch: the sample's vertices
  Sample sample_;                                 // choose_greedy's scratch
  double sample_weight_ = 0;                      // its fragments' weight in all
  std::vector<Frag> frags_;                       // the pending tasks' fragments (Task)
  std::unique_ptr<Frag[]> front_side_;            // partition's scratch: the front side's pieces
  size_t front_room_ = 0;                         // its size
  std::vector<std::pair<int8_t, int8_t>> sides_;  // partition's scratch: each fragment's end sides
  std::vector<int8_t> convex_sides_;              // convex_region's: each fragment's side facing the region
  std::vector<uint32_t> convex_order_;
  level::Level out_;
  bool segments_only_ = false;
  std::vector<std::pair<int32_t, Vec2>> unresolved_;
  size_t placed_ = 0, pending_ = 0, next_progress_ = 65536;
  size_t free_splits_ = 0, max_depth_ = 0, leaf_depth_sum_ = 0;
  double shortest_ = INFINITY;
};

}  // namespace

level::Level build(const map::Source& source, const Options& options, Stats* stats) {
  map::check_limits(source);
  return Builder(source, options, nullptr).run(stats);
}

level::Level build(map::Source&& source, const Options& options, Stats* stats) {
  map::check_limits(source);
  return Builder(source, options, &source).run(stats);
}

}  // namespace p3d::bsp
