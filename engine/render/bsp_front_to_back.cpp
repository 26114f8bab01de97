// The front-to-back BSP renderer (the survey's Algorithm 13, with Doom's sector
// clipping): walk the tree nearest subtree first, draw each node's fragments into
// the columns still open, set a column's bit in the W-bit array once it closes,
// skip any subtree whose bounding box projects onto closed columns only, and stop
// the walk the moment every column is closed. Things met on the way (attached to the
// nodes and leaves the walk reaches) are drawn as sprites at the end, farthest first.
#include "engine/render/draw.h"
#include "engine/render/occlusion.h"
#include "engine/render/renderer.h"

namespace p3d::render {

namespace {

class BspFrontToBack final : public Renderer {
 public:
  std::string_view name() const override { return "bsp"; }
  using Renderer::render;

  RenderStats render(const level::Level& level, const level::State& state, const Camera& camera, Frame& frame,
                     Probe* probe) override {
    const View view(camera, frame.width, frame.height);
    canvas_.begin(level, state, view, frame, level.sector_at(camera.pos), probe);
    order_ = probe && probe->want_order ? &probe->order : nullptr;
    if (order_) order_->clear();
    mask_.reset(view.width);
    RenderStats stats;

    stack_.assign(1, {0, false});
    while (!stack_.empty()) {
      if (mask_.full()) {
        stats.early_exit = true;
        break;
      }
      const Item item = stack_.back();
      stack_.pop_back();
      if (level::is_leaf(item.child)) {
        add_sprites(level, level.leaves[size_t(level::leaf_index(item.child))].things);
        continue;
      }
      const level::Node& node = level.nodes[item.child];
      if (item.draw_fragments) {
        draw_fragments(level, view, node, stats);
        continue;
      }
      // The culling box covers the subtree's fragments and the sprites of its things
      // (see level::finalize): nothing visible is skipped.
      const ColumnRange range = columns_of_box(view, node.cull_box);
      if (range.empty() || mask_.all_closed(range.x0, range.x1)) {
        ++stats.subtrees_culled;
        continue;
      }
      ++stats.nodes_visited;
      add_sprites(level, node.things);
      const int near = level::splitter_side(node, camera.pos) > 0 ? 1 : 0;
      stack_.push_back({node.child[1 - near], false});
      stack_.push_back({item.child, true});
      stack_.push_back({node.child[near], false});
    }
    canvas_.finish();
    canvas_.count_into(stats);
    return stats;
  }

 private:
  struct Item {
    int32_t child;
    bool draw_fragments;  // draw this node's own fragments (its near subtree is done)
  };

  void add_sprites(const level::Level& level, const level::ThingRange& things) {
    for (uint32_t k = things.first; k < things.first + things.count; ++k) canvas_.add_sprite(level.attached_things[k]);
  }

  void draw_fragments(const level::Level& level, const View& view, const level::Node& node, RenderStats& stats) {
    for (uint32_t i = node.first_fragment; i < node.first_fragment + node.fragment_count && !mask_.full(); ++i) {
      const level::Fragment& f = level.fragments[i];
      const level::Wall& wall = level.walls[f.wall];
      const int side = facing_side(wall, view.pos);
      if (side < 0 || !visible_side(wall, side)) continue;  // edge-on, or the back of a one-sided wall
      const ColumnRange range = columns_of_segment(view, f.p0, f.p1);
      if (range.empty()) continue;
      const WallProjector projector(view, wall.a, wall.b);
      bool drew = false;
      mask_.for_each_open(range.x0, range.x1, [&](int x) {
        double depth, t;
        if (!projector.hit(x, depth, t) || !in_fragment(f, t)) return;
        drew = true;
        if (canvas_.draw_wall(x, {f.wall, side, depth, t, int32_t(i)})) mask_.close(x);
      });
      stats.fragments_drawn += drew;
      if (drew && order_) order_->push_back(i);
    }
  }

  Canvas canvas_;
  ColumnMask mask_;
  std::vector<Item> stack_;
  std::vector<uint32_t>* order_ = nullptr;
};

}  // namespace

std::unique_ptr<Renderer> make_bsp_front_to_back() { return std::make_unique<BspFrontToBack>(); }

}  // namespace p3d::render
