// The painter's algorithm on the BSP (de Berg's PaintersAlgorithm): walk the tree
// far subtree first and paint every visible fragment over whatever is behind it: a
// node's between its far and near subtrees, a leaf's those facing the camera (on the
// far side of its region) first, then those seen from behind (on its near side).
// No occlusion array, so everything in the view cone is drawn: its overdraw is
// what the front-to-back renderer saves. Only boxes outside the view cone are skipped.
#include <algorithm>

#include "engine/render/draw.h"
#include "engine/render/renderer.h"

namespace p3d::render {

namespace {

class Painter final : public Renderer {
 public:
  std::string_view name() const override { return "painter"; }
  using Renderer::render;

  RenderStats render(const level::Level& level, const level::State& state, const Camera& camera, Frame& frame,
                     Probe* probe) override {
    const View view(camera, frame.width, frame.height, level, frame.doom_screen_width);
    const int camera_sector = level.sector_at(camera.pos);
    canvas_.begin(level, state, view, frame, camera_sector, probe);
    canvas_.draw_directly();  // it paints over its own pixels
    painted_.assign(view.width, false);
    column_hits_.resize(view.width);
    for (auto& hits : column_hits_) hits.clear();
    order_ = probe && probe->want_order ? &probe->order : nullptr;
    if (order_) order_->clear();
    RenderStats stats;

    stack_.assign(1, {level.root(), false});
    while (!stack_.empty()) {
      const Item item = stack_.back();
      stack_.pop_back();
      if (level::is_leaf(item.child)) {
        paint_leaf(level, view, level.leaves[size_t(level::leaf_index(item.child))], stats);
        continue;
      }
      const level::Node& node = level.nodes[size_t(item.child)];
      if (item.draw_fragments) {
        for (uint32_t i = node.first_fragment; i < node.first_fragment + node.fragment_count; ++i) {
          const level::Wall& wall = level.walls[level.fragments[i].wall];
          const int side = facing_side(wall, view.pos);
          if (side >= 0 && visible_side(wall, side)) paint_fragment(level, view, i, side, stats);
        }
        continue;
      }
      if (columns_of_box(view, node.bbox).empty()) {  // outside the view cone: not occlusion
        ++stats.subtrees_culled;
        continue;
      }
      ++stats.nodes_visited;
      const int near = level::splitter_side(node, camera.pos) > 0 ? 1 : 0;
      stack_.push_back({node.child[near], false});  // last: nearest paints over everything
      stack_.push_back({item.child, true});
      stack_.push_back({node.child[1 - near], false});
    }
    for (int x = 0; x < view.width; ++x)
      if (!painted_[x]) canvas_.paint_background(x, camera_sector);
    // Masked textures and sprites are layers over the walls: the replay tells each
    // column's open rows at every depth, then they go on farthest first.
    replay_front_to_back(view.width);
    for (uint32_t i = 0; i < state.things.size(); ++i) canvas_.add_sprite(i);
    canvas_.draw_layers();

    canvas_.count_into(stats);
    return stats;
  }

 private:
  // Far to near: the fragments facing the camera (where rays leave the leaf's region),
  // then those seen from behind (where they enter it).
  void paint_leaf(const level::Level& level, const View& view, const level::Leaf& leaf, RenderStats& stats) {
    for (int pass = 0; pass < 2; ++pass)
      for (uint32_t i = leaf.first_fragment; i < leaf.first_fragment + leaf.fragment_count; ++i) {
        const level::Fragment& f = level.fragments[i];
        const level::Wall& wall = level.walls[f.wall];
        const int side = facing_side(wall, view.pos);
        if (side < 0 || !visible_side(wall, side) || (side == f.side) != (pass == 0)) continue;
        paint_fragment(level, view, i, side, stats);
      }
  }

  void paint_fragment(const level::Level& level, const View& view, uint32_t i, int side, RenderStats& stats) {
    const level::Fragment& f = level.fragments[i];
    const level::Wall& wall = level.walls[f.wall];
    const ColumnRange range = columns_of_segment(view, f.p0, f.p1);
    if (range.empty()) return;
    const WallProjector projector(view, wall.a, wall.b);
    bool drew = false;
    for (int x = range.x0; x <= range.x1; ++x) {
      double depth, t;
      if (!projector.hit(x, depth, t) || !in_fragment(f, t)) continue;
      const WallHit hit{f.wall, side, depth, t, int32_t(i)};
      if (!painted_[x]) {  // the farthest hit of this column: first the view beyond it
        painted_[x] = true;
        if (wall.two_sided()) canvas_.paint_background(x, wall.sides[1 - side].sector);
      }
      canvas_.paint_wall(x, hit);
      column_hits_[x].push_back(hit);
      drew = true;
    }
    stats.fragments_drawn += drew;
    if (drew && order_) order_->push_back(i);
  }

  // The painter's hits arrive far to near; replaying them near to far through the
  // canvas's clipping (no pixels) finds what each column saw at every depth.
  void replay_front_to_back(int width) {
    for (int x = 0; x < width; ++x)
      for (auto it = column_hits_[x].rbegin(); it != column_hits_[x].rend(); ++it)
        if (canvas_.clip_wall(x, *it)) break;
  }

  Canvas canvas_;
  struct Item {
    int32_t child;        // a node or a leaf (level::leaf_child)
    bool draw_fragments;  // paint this node's own fragments
  };
  std::vector<Item> stack_;
  std::vector<bool> painted_;
  std::vector<std::vector<WallHit>> column_hits_;
  std::vector<uint32_t>* order_ = nullptr;
};

}  // namespace

std::unique_ptr<Renderer> make_painter() { return std::make_unique<Painter>(); }

}  // namespace p3d::render
