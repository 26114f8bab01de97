// The brute-force reference renderer, the oracle of the tests: for every column,
// hit every wall, sort the hits by distance and hand them to the canvas nearest
// first. No BSP in what it draws; the camera's sector is the level's own (Doom's
// rule, Level::sector_at: the sector of the leaf it stands in, which crossing parity
// cannot tell in an unclosed sector or outside the map).
#include <algorithm>

#include "engine/render/draw.h"
#include "engine/render/renderer.h"

namespace p3d::render {

namespace {

class Reference final : public Renderer {
 public:
  std::string_view name() const override { return "reference"; }
  using Renderer::render;

  RenderStats render(const level::Level& level, const level::State& state, const Camera& camera, Frame& frame,
                     Probe* probe) override {
    const View view(camera, frame.width, frame.height, level, frame.doom_screen_width);
    canvas_.begin(level, state, view, frame, level.sector_at(camera.pos), probe);

    walls_.clear();
    for (uint32_t i = 0; i < level.walls.size(); ++i) {
      const level::Wall& w = level.walls[i];
      const int side = facing_side(w, view.pos);
      if (side >= 0 && visible_side(w, side)) walls_.push_back({i, side, WallProjector(view, w.a, w.b)});
    }
    for (int x = 0; x < view.width; ++x) {
      column_hits_.clear();
      for (const VisibleWall& w : walls_) {
        double depth, t;
        if (w.projector.hit(x, depth, t)) column_hits_.push_back({{w.wall, w.side, depth, t}, w.projector.right_end(x)});
      }
      // Nearest first; two walls met at one point: the one in front just right of it.
      std::sort(column_hits_.begin(), column_hits_.end(), [&](const Hit& a, const Hit& b) {
        if (a.hit.depth != b.hit.depth) return a.hit.depth < b.hit.depth;
        const level::Wall &wa = level.walls[a.hit.wall], &wb = level.walls[b.hit.wall];
        if (hides_to_the_right(wb, b.right_end, wa, a.right_end)) return true;
        if (hides_to_the_right(wa, a.right_end, wb, b.right_end)) return false;
        return a.hit.wall < b.hit.wall;
      });
      for (const Hit& h : column_hits_)
        if (canvas_.draw_wall(x, h.hit)) break;
    }
    for (uint32_t i = 0; i < state.things.size(); ++i) canvas_.add_sprite(i);
    canvas_.finish();
    canvas_.resolve(0, view.height);

    RenderStats stats;
    canvas_.count_into(stats);
    stats.rays = static_cast<uint64_t>(view.width);  // one per column, hitting every wall
    return stats;
  }

 private:
  struct VisibleWall {
    uint32_t wall;
    int side;
    WallProjector projector;
  };
  struct Hit {
    WallHit hit;
    int right_end;  // the wall's end right of the ray
  };
  Canvas canvas_;
  std::vector<VisibleWall> walls_;
  std::vector<Hit> column_hits_;
};

}  // namespace

std::unique_ptr<Renderer> make_reference() { return std::make_unique<Reference>(); }

}  // namespace p3d::render
