// The front-to-back BSP renderer (the survey's Algorithm 13, with Doom's sector
// clipping): walk the tree nearest subtree first, draw each node's fragments (on its
// splitter line, between its near and far subtrees) and each leaf's (in one step: they
// bound a convex region, so none hides another but where those seen from behind,
// entering the region, lie in front of the others: those go first) into the columns
// still open, set a column's bit in the W-bit array once it closes, skip any subtree or
// leaf whose bounding box projects onto closed columns only, and stop the walk the
// moment every column is closed. Things met on the way (attached to the
// nodes and leaves the walk reaches) are drawn as sprites at the end, farthest first.
//
// Things move, so they are attached to the tree anew for every frame (attach_things):
// a sprite is a picture facing the viewer and may reach up to its frame's
// SpriteFrame::reach sideways from its thing, across splitters. It attaches to the
// deepest node whose cell holds that whole disc (or to the leaf, if one does), and
// culling boxes grow to cover the discs of their subtree: a subtree (or leaf) is
// skipped only when every column it could touch was closed by walls visited earlier,
// which lie in front of every point of its cell. So culling never hides a sprite pixel.
// Under Doom's rules sprites are clipped by the walls' silhouettes, not by the walk:
// every thing goes to the canvas, and the tree culls by its walls' boxes alone.
//
// The screen is split into column strips, one per thread, each walked alone with its
// own W-bit array (the columns outside it closed from the start), canvas and sprites.
// What a column shows depends only on the walls met in it, front to back, so the
// picture is the same for any split; the statistics are counted as one walk of the
// whole screen would count them (merged_stats), so they are too. The edges between
// strips move frame by frame toward equal times (strip_split.h).
#include <algorithm>
#include <cmath>
#include <utility>

#include "engine/render/draw.h"
#include "engine/render/occlusion.h"
#include "engine/render/renderer.h"
#include "engine/render/strip_split.h"
#include "engine/util/thread_pool.h"

namespace p3d::render {

namespace {

// Strips per frame: one per thread. Every strip walks the tree's first levels, splits
// the planes' rows and projects the things near it, so fewer is cheaper: at the starts
// of five Freedoom maps, one strip on one thread takes 0.94 of four strips' time, and
// two strips balanced by time on two threads 0.93 of four handed out in turn. Each
// strip is a whole number of 64-byte cache lines of pixels wide (16 columns): where
// rows start on a line, two threads never write the same one.
constexpr int kStripAlign = 16;
constexpr int kResolveBands = 8;  // bands of rows the final colour pass is split into

// Ids counted once over a frame's strips: each id's mark holds the number of the frame
// it was last counted in. (Sorting them took 2% of a frame on one thread.)
class DistinctIds {
 public:
  void next_frame() {
    if (++frame_ != 0) return;
    std::fill(marks_.begin(), marks_.end(), 0);  // the count wrapped: no mark may pass for this frame's
    frame_ = 1;
  }
  // Counts id in this frame: true the first time.
  bool add(size_t id) {
    if (id >= marks_.size()) marks_.resize(id + 1, 0);
    if (marks_[id] == frame_) return false;
    marks_[id] = frame_;
    return true;
  }
  bool has(size_t id) const { return id < marks_.size() && marks_[id] == frame_; }

 private:
  std::vector<uint32_t> marks_;
  uint32_t frame_ = 0;
};

class BspFrontToBack final : public Renderer {
 public:
  BspFrontToBack(int threads, bool vector_columns) : pool_(std::max(1, threads)), vector_columns_(vector_columns) {}
  std::string_view name() const override { return "bsp"; }
  using Renderer::render;

  RenderStats render(const level::Level& level, const level::State& state, const Camera& camera, Frame& frame,
                     Probe* probe) override {
    const View view(camera, frame.width, frame.height, level, frame.doom_screen_width);
    const int camera_sector = level.sector_at(camera.pos);
    // The order fragments drew in is one walk's: a probe asking for it gets one strip.
    const bool one_walk = probe && probe->want_order;
    const int count = one_walk ? 1 : pool_.threads();
    if (edges_.size() != size_t(count) + 1 || edges_.back() != view.width) edges_ = even_edges(view.width, count, kStripAlign);
    const int strips = int(edges_.size()) - 1;
    if (strips_.size() < size_t(strips)) strips_.resize(size_t(strips));
    seconds_.assign(size_t(strips), 0.0);
    Canvas::prepare_probe(view, probe);
    Canvas::prepare_frame(level, frame);
    // Under Doom's rules every thing goes to the canvas (walk), so the tree culls by
    // its walls alone; else the things ride on the tree.
    if (view.doom)
      Canvas::project_doom_sprites(level, state, view, projected_);
    else
      attach_things(level, state);
    pool_.run_timed(
        strips,
        [&](int i) {
          Strip& s = strips_[size_t(i)];
          s.x0 = edges_[size_t(i)];
          s.x1 = edges_[size_t(i) + 1];
          s.canvas.allow_vector_columns(vector_columns_);
          s.canvas.begin_strip(level, state, view, frame, camera_sector, probe, s.x0, s.x1,
                               i > 0 ? &strips_[size_t(i) - 1].canvas : nullptr);
          s.order = one_walk ? &probe->order : nullptr;
          walk(level, view, camera, s);
        },
        seconds_);
    // Under Doom's rules a flat's span may begin in a strip to the left: the strips draw
    // their flats and layers once every strip's walk is done (Canvas::finish_strip).
    if (strips_[0].canvas.waiting())
      pool_.run_timed(
          strips,
          [&](int i) {
            Strip& s = strips_[size_t(i)];
            s.canvas.finish_strip();
            s.canvas.count_into(s.stats);
          },
          seconds_);
    balance_edges(edges_, seconds_, kStripAlign);
    // Paletted levels drawn in colours: the strips drew palette indices
    // (Canvas::resolve); the colours are written in bands of whole rows, which the
    // caches fetch as streams.
    if (strips_[0].canvas.drew_indices() && !frame.indexed()) {
      const int bands = std::min(view.height, kResolveBands);
      pool_.run(bands, [&](int band) {
        const int y0 = view.height * band / bands, y1 = view.height * (band + 1) / bands;
        for (int y = y0; y < y1; ++y)
          for (int i = 0; i < strips; ++i) strips_[size_t(i)].canvas.resolve(y, y + 1);
      });
    }
    return merged_stats(level, strips, view.doom != nullptr);
  }

 private:
  struct Item {
    int32_t child;         // a node or a leaf (level::leaf_child)
    bool draw_fragments;   // draw this node's own fragments (its near subtree is done)
  };
  // Things attached to a node or leaf: a range of attached_.
  struct ThingRange {
    uint32_t first = 0, count = 0;
  };
  // One strip's walk: its columns [x0, x1), its scratch, what it counted.
  struct Strip {
    int x0 = 0, x1 = 0;
    Canvas canvas;
    ColumnMask mask;
    std::vector<Item> stack;
    std::vector<uint32_t> facing;      // draw_leaf's scratch
    std::vector<uint32_t>* order = nullptr;
    std::vector<uint32_t> fragments_drawn;
    std::vector<int32_t> entered;  // the nodes and leaves (leaf_child values) walked into
    std::vector<int32_t> hit_x;  // draw_fragment's hits (open_column_hits_avx512's)
    std::vector<double> hit_depth, hit_t;
    std::vector<int> closed;
    RenderStats stats;
    bool vector_projection = false;
  };

  void walk(const level::Level& level, const View& view, const Camera& camera, Strip& s) {
    s.mask.reset(view.width);
    s.mask.close_outside(s.x0, s.x1);
    s.vector_projection = vector_columns_ && vector_projection();
    const size_t width = size_t(view.width);  // at most a hit a column
    s.hit_x.resize(width), s.hit_depth.resize(width), s.hit_t.resize(width);
    s.stats = {};
    s.fragments_drawn.clear();
    s.entered.clear();
    if (s.order) s.order->clear();
    s.stack.assign(1, {level.root(), false});
    // Doom's rules clip a sprite by the walls' silhouettes, not by what the walk culls:
    // every thing goes to the canvas, as in the reference (projected once a frame: render).
    const bool every_thing = view.doom != nullptr;
    if (every_thing) s.canvas.add_projected_sprites(projected_, true);
    while (!s.stack.empty() && !s.mask.full()) {
      const Item item = s.stack.back();
      s.stack.pop_back();
      if (item.draw_fragments) {
        const level::Node& node = level.nodes[size_t(item.child)];
        draw_fragments(level, view, node.first_fragment, node.fragment_count, s);
        continue;
      }
      // The culling box covers the fragments and the sprites of the things of the
      // subtree or leaf (attach_things): nothing visible is skipped.
      const bool leaf = level::is_leaf(item.child);
      const geom::BBox& box = cull_box(level, item.child, every_thing);
      if (box.empty()) continue;  // a leaf holding nothing
      const ColumnRange range = columns_of_box(view, box);
      if (range.empty() || s.mask.all_closed(range.x0, range.x1)) continue;
      s.entered.push_back(item.child);
      if (leaf) {
        const int32_t index = level::leaf_index(item.child);
        if (!every_thing) add_sprites(leaf_things_[size_t(index)], s.canvas);
        draw_leaf(level, view, level.leaves[size_t(index)], s);
        continue;
      }
      const level::Node& node = level.nodes[size_t(item.child)];
      if (!every_thing) add_sprites(node_things_[size_t(item.child)], s.canvas);
      const int near = level::splitter_side(node, camera.pos) > 0 ? 1 : 0;
      s.stack.push_back({node.child[1 - near], false});
      s.stack.push_back({item.child, true});
      s.stack.push_back({node.child[near], false});
    }
    s.stats.early_exit = s.mask.full();
    s.canvas.finish();
    s.canvas.count_into(s.stats);
  }

  void add_sprites(const ThingRange& things, Canvas& canvas) const {
    for (uint32_t k = things.first; k < things.first + things.count; ++k) canvas.add_sprite(attached_[k]);
  }

  // Attaches each thing drawn to the deepest node whose cell holds its sprite's disc,
  // or to a leaf; then the culling boxes on its path from the root grow to cover the
  // disc (see the file's head). Things in index order within each node and leaf. The
  // work is the things' and their paths', not the tree's: what the last frame's things
  // changed is put back, and the rest stays as the level's first frame left it.
  void attach_things(const level::Level& level, const level::State& state) {
    if (level.generation == 0 || things_for_ != level.generation) start_level(level);
    for (const int32_t c : touched_) {  // the last frame's things leave
      range_of(c) = {};
      cull_box_of(c) = base_box_of(c);
    }
    touched_.clear();
    owners_.clear();
    for (size_t i = 0; i < state.things.size(); ++i) {
      const level::ShownThing& t = state.things[i];
      if (t.frame == level::kNone || level.leaves.empty()) continue;
      const double reach = level.sprite_frames[size_t(t.frame)].reach;
      const geom::Vec2 low = t.pos - geom::Vec2(reach), high = t.pos + geom::Vec2(reach);
      int32_t c = level.root();
      for (;;) {  // the disc grows every box on the way down, its owner's too
        touched_.push_back(c);
        cull_box_of(c).add(low);
        cull_box_of(c).add(high);
        if (level::is_leaf(c)) break;
        const level::Node& n = level.nodes[size_t(c)];
        const double side = level::splitter_side(n, t.pos) / glm::length(n.direction);  // signed distance, > 0 back
        if (std::fabs(side) <= reach) break;
        c = n.child[side > 0 ? 1 : 0];
      }
      owners_.push_back({c, uint32_t(i)});
    }
    // attached_ holds the things by owner, nodes before leaves, each in index order.
    const auto order = [&](int32_t c) { return level::is_leaf(c) ? level.nodes.size() + size_t(level::leaf_index(c)) : size_t(c); };
    std::stable_sort(owners_.begin(), owners_.end(), [&](const auto& a, const auto& b) { return order(a.first) < order(b.first); });
    attached_.resize(owners_.size());
    for (size_t k = 0; k < owners_.size(); ++k) {
      ThingRange& r = range_of(owners_[k].first);
      if (r.count == 0) r.first = uint32_t(k);
      ++r.count;
      attached_[k] = owners_[k].second;
    }
  }
  // A level's first frame: no thing attached anywhere, and each culling box its
  // subtree's walls' (a node's box and its children's).
  void start_level(const level::Level& level) {
    const size_t nodes = level.nodes.size(), leaves = level.leaves.size();
    node_things_.assign(nodes, {});
    leaf_things_.assign(leaves, {});
    base_leaf_boxes_.resize(leaves);
    for (size_t i = 0; i < leaves; ++i) base_leaf_boxes_[i] = level.leaves[i].bbox;
    base_boxes_.resize(nodes);
    for (size_t i = nodes; i-- > 0;) {  // children come after their parent
      const level::Node& n = level.nodes[i];
      base_boxes_[i] = n.bbox;
      for (int32_t c : n.child) base_boxes_[i].add(base_box_of(c));
    }
    cull_boxes_ = base_boxes_;
    leaf_cull_boxes_ = base_leaf_boxes_;
    touched_.clear();
    things_for_ = level.generation;
  }
  geom::BBox& cull_box_of(int32_t child) {
    return level::is_leaf(child) ? leaf_cull_boxes_[size_t(level::leaf_index(child))] : cull_boxes_[size_t(child)];
  }
  const geom::BBox& base_box_of(int32_t child) const {
    return level::is_leaf(child) ? base_leaf_boxes_[size_t(level::leaf_index(child))] : base_boxes_[size_t(child)];
  }
  const geom::BBox& cull_box(const level::Level& level, int32_t child, bool walls_only) const {
    if (level::is_leaf(child)) {
      const size_t i = size_t(level::leaf_index(child));
      return walls_only ? level.leaves[i].bbox : leaf_cull_boxes_[i];
    }
    return walls_only ? level.nodes[size_t(child)].bbox : cull_boxes_[size_t(child)];
  }
  ThingRange& range_of(int32_t child) {
    return level::is_leaf(child) ? leaf_things_[size_t(level::leaf_index(child))] : node_things_[size_t(child)];
  }

  // A node's fragments: on one line, none hides another.
  static void draw_fragments(const level::Level& level, const View& view, uint32_t first, uint32_t count, Strip& s) {
    for (uint32_t i = first; i < first + count; ++i) {
      const level::Wall& wall = level.walls[level.fragments[i].wall];
      const int side = facing_side(wall, view.pos);
      if (side < 0 || !visible_side(wall, side)) continue;  // edge-on, or the back of a one-sided wall
      if (draw_fragment(level, view, i, side, s)) return;
    }
  }

  // A leaf's fragments, in one step: those the camera sees from behind (two-sided walls
  // and segments, where a ray enters the region) first, then those facing it (where a
  // ray leaves it). Within each set none hides another (engine/bsp/convex.h).
  static void draw_leaf(const level::Level& level, const View& view, const level::Leaf& leaf, Strip& s) {
    s.facing.clear();
    for (uint32_t i = leaf.first_fragment; i < leaf.first_fragment + leaf.fragment_count; ++i) {
      const level::Fragment& f = level.fragments[i];
      const level::Wall& wall = level.walls[f.wall];
      const int side = facing_side(wall, view.pos);
      if (side < 0 || !visible_side(wall, side)) continue;
      if (side == f.side) s.facing.push_back(i);
      else if (draw_fragment(level, view, i, side, s)) return;
    }
    for (uint32_t i : s.facing)
      if (draw_fragment(level, view, i, level.fragments[i].side, s)) return;
  }

  // Draws fragment i, seen from `side` of its wall, into the open columns; true once every column is closed.
  static bool draw_fragment(const level::Level& level, const View& view, uint32_t i, int side, Strip& s) {
    const level::Fragment& f = level.fragments[i];
    const level::Wall& wall = level.walls[f.wall];
    const ColumnRange range = columns_of_segment(view, f.p0, f.p1);
    if (range.empty()) return false;
    const WallProjector projector(view, wall.a, wall.b);
    // The open columns' hits, then drawn together.
    size_t n = 0;
    if (s.vector_projection) {
      n = open_column_hits_avx512(projector, span_of(f), s.mask.words(), range.x0, range.x1,
                                  {s.hit_x.data(), s.hit_depth.data(), s.hit_t.data()});
    } else {
      s.mask.for_each_open(range.x0, range.x1, [&](int x) {
        double depth, t;
        if (projector.hit(x, depth, t) && in_fragment(f, t)) s.hit_x[n] = x, s.hit_depth[n] = depth, s.hit_t[n] = t, ++n;
      });
    }
    s.closed.clear();
    const Canvas::WallHits hits{f.wall, side, int32_t(i), {s.hit_x.data(), n}, s.hit_depth.data(), s.hit_t.data()};
    s.canvas.draw_walls(hits, s.closed);
    for (const int x : s.closed) s.mask.close(x);
    if (n > 0) {
      s.fragments_drawn.push_back(i);
      if (s.order) s.order->push_back(i);
    }
    return s.mask.full();
  }

  // The statistics of one walk over the whole screen. A node, a fragment or a sprite
  // counts once however many strips met it: one walk enters a node where it has a
  // column still open, that is where some strip does (a node's columns hold its
  // children's). A subtree is culled where its node was entered but it was not: its
  // box projects onto closed (or no) columns, or every column closed first. The walk
  // exits early when every column closes, that is when every strip's does.
  RenderStats merged_stats(const level::Level& level, int strips, bool walls_only) {
    RenderStats total;
    total.early_exit = true;
    fragments_.next_frame();
    things_.next_frame();
    entered_.next_frame();
    expanded_.next_frame();
    const auto tree_id = [&](int32_t child) {  // nodes, then leaves
      return level::is_leaf(child) ? level.nodes.size() + size_t(level::leaf_index(child)) : size_t(child);
    };
    for (int i = 0; i < strips; ++i) {
      const Strip& s = strips_[size_t(i)];
      for (const int32_t child : s.entered)
        if (entered_.add(tree_id(child)) && !level::is_leaf(child)) ++total.nodes_visited;
      for (const uint32_t f : s.fragments_drawn) total.fragments_drawn += fragments_.add(f);
      for (const uint32_t t : s.canvas.things_drawn()) total.sprites_drawn += things_.add(t);
      total.columns_closed += s.stats.columns_closed;
      total.pixels_written += s.stats.pixels_written;
      total.masked_pixels += s.stats.masked_pixels;
      total.sprite_pixels += s.stats.sprite_pixels;
      total.early_exit = total.early_exit && s.stats.early_exit;
    }
    const auto culled = [&](int32_t child) {
      return !cull_box(level, child, walls_only).empty() && !entered_.has(tree_id(child));
    };
    total.subtrees_culled = culled(level.root());
    for (int i = 0; i < strips; ++i)
      for (const int32_t child : strips_[size_t(i)].entered)
        if (!level::is_leaf(child) && expanded_.add(tree_id(child)))  // each node once
          for (const int32_t c : level.nodes[size_t(child)].child) total.subtrees_culled += culled(c);
    return total;
  }

  ThreadPool pool_;
  bool vector_columns_;  // RendererOptions::vector_columns
  std::vector<Strip> strips_;
  // This frame's things on the tree (attach_things): per node and leaf a range of
  // attached_ (indices in state.things), and per node and leaf its culling box.
  std::vector<ThingRange> node_things_, leaf_things_;
  std::vector<uint32_t> attached_;
  std::vector<Canvas::Sprite> projected_;  // Doom's rules: every thing's sprite, projected once a frame
  std::vector<geom::BBox> cull_boxes_, leaf_cull_boxes_;
  // The boxes without things, the level's generation they are for, and what this
  // frame's things changed (nodes and leaf_child values, to be put back).
  std::vector<geom::BBox> base_boxes_, base_leaf_boxes_;
  uint64_t things_for_ = 0;
  std::vector<int32_t> touched_;
  std::vector<std::pair<int32_t, uint32_t>> owners_;  // attach_things' scratch: (node or leaf_child, thing)
  DistinctIds fragments_, things_, entered_, expanded_;  // merged_stats' scratch
  std::vector<int> edges_;        // the strips' columns: strip i is [edges_[i], edges_[i + 1])
  std::vector<double> seconds_;   // what each strip took this frame
};

}  // namespace

std::unique_ptr<Renderer> make_bsp_front_to_back(int threads, bool vector_columns) {
  return std::make_unique<BspFrontToBack>(threads, vector_columns);
}

}  // namespace p3d::render
