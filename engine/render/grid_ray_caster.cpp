// The Wolfenstein-style grid ray caster ("dda"): one ray per column, walked cell
// by cell with Amanatides & Woo's traversal (exactly the cells the ray crosses,
// no fixed-step marching). The first step from an empty cell into a solid one
// names the wall on that face; its depth and texture come from the same
// WallProjector and Canvas as every other renderer, so on a grid map the picture
// is the BSP renderer's.
#include <cmath>
#include <limits>

#include "engine/render/draw.h"
#include "engine/render/renderer.h"

namespace p3d::render {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

class GridRayCaster final : public Renderer {
 public:
  std::string_view name() const override { return "dda"; }
  using Renderer::render;
  bool supports(const level::Level& level) const override { return level.grid.has_value(); }
  std::string_view needs() const override { return "a .grid tile map"; }

  RenderStats render(const level::Level& level, const level::State& state, const Camera& camera, Frame& frame,
                     Probe* probe) override {
    const View view(camera, frame.width, frame.height, level, frame.doom_screen_width);
    canvas_.begin(level, state, view, frame, level.sector_at(camera.pos), probe);
    RenderStats stats;
    if (level.grid)
      for (int x = 0; x < view.width; ++x) stats.add_ray(cast(level, *level.grid, view, x));
    for (uint32_t i = 0; i < state.things.size(); ++i) canvas_.add_sprite(i);
    canvas_.finish();
    canvas_.resolve(0, view.height);
    canvas_.count_into(stats);
    return stats;
  }

 private:
  // Walks column x's ray through the grid until a wall closes the column; returns the cells stepped.
  uint64_t cast(const level::Level& level, const level::Grid& g, const View& view, int x) {
    const Vec2 dir = view.ray(x);  // the point at parameter s is pos + dir * s
    const Vec2 p = view.pos / g.cell;
    // A camera outside the grid starts where the ray enters it (outside counts as solid).
    double s = 0;
    if (!g.inside(int(std::floor(p.x)), int(std::floor(p.y)))) {
      s = entry_param(p, dir / g.cell, g);
      if (s == kInf) return 0;
    }
    const Vec2 start = p + dir / g.cell * s;
    int c = std::clamp(int(std::floor(start.x)), 0, g.cols - 1);
    int r = std::clamp(int(std::floor(start.y)), 0, g.rows - 1);
    const int step_c = dir.x > 0 ? 1 : -1, step_r = dir.y > 0 ? 1 : -1;
    // Parameters of the next vertical and horizontal grid line, and of one cell, along the ray.
    const double delta_c = dir.x != 0 ? g.cell / std::fabs(dir.x) : kInf;
    const double delta_r = dir.y != 0 ? g.cell / std::fabs(dir.y) : kInf;
    double next_c = dir.x != 0 ? ((c + (step_c > 0)) * g.cell - view.pos.x) / dir.x : kInf;
    double next_r = dir.y != 0 ? ((r + (step_r > 0)) * g.cell - view.pos.y) / dir.y : kInf;
    bool was_empty = s == 0 && !g.is_solid(c, r);  // entering from outside: came from solid
    if (s > 0 && !g.is_solid(c, r) && probe_entry(level, g, view, x, c, r, start)) return 1;

    uint64_t steps = 0;
    for (;;) {
      ++steps;
      const int from_c = c, from_r = r;
      int face;
      if (next_c < next_r) {
        c += step_c;
        next_c += delta_c;
        face = step_c > 0 ? level::Grid::kEast : level::Grid::kWest;
      } else {
        r += step_r;
        next_r += delta_r;
        face = step_r > 0 ? level::Grid::kNorth : level::Grid::kSouth;
      }
      const bool solid = g.is_solid(c, r);
      if (was_empty && solid && draw(level, view, x, g.face(from_c, from_r, face))) return steps;
      was_empty = !solid;
      if (!g.inside(c, r) && leaving(g, c, r, step_c, step_r, dir)) return steps;
    }
  }

  // Draws the wall if the ray truly meets it in front of the camera; true when that closes the column.
  bool draw(const level::Level& level, const View& view, int x, int32_t wall) {
    const level::Wall& w = level.walls[wall];
    const int side = facing_side(w, view.pos);
    double depth, t;
    if (side != 0 || !WallProjector(view, w.a, w.b).hit(x, depth, t)) return false;
    return canvas_.draw_wall(x, {uint32_t(wall), side, depth, t});
  }

  // A camera outside the grid whose ray enters an empty border cell meets the border wall there.
  bool probe_entry(const level::Level& level, const level::Grid& g, const View& view, int x, int c, int r, Vec2 at) {
    const double fx = at.x - c, fy = at.y - r;  // position inside the cell, 0..1
    const int face = fx <= 1e-9 ? level::Grid::kWest : fx >= 1 - 1e-9 ? level::Grid::kEast
                   : fy <= 1e-9 ? level::Grid::kSouth : level::Grid::kNorth;
    const int32_t wall = g.face(c, r, face);
    return wall != level::kNone && draw(level, view, x, wall);
  }

  static bool leaving(const level::Grid& g, int c, int r, int step_c, int step_r, Vec2 dir) {
    const bool out_c = (c < 0 && (step_c < 0 || dir.x == 0)) || (c >= g.cols && (step_c > 0 || dir.x == 0));
    const bool out_r = (r < 0 && (step_r < 0 || dir.y == 0)) || (r >= g.rows && (step_r > 0 || dir.y == 0));
    return out_c || out_r;
  }

  // Parameter where the ray p + d s (in cells) enters the grid box, or infinity.
  static double entry_param(Vec2 p, Vec2 d, const level::Grid& g) {
    double lo = 0, hi = kInf;
    const double size[2] = {double(g.cols), double(g.rows)};
    for (int axis = 0; axis < 2; ++axis) {
      const double o = p[axis], v = d[axis];
      if (v == 0) {
        if (o < 0 || o > size[axis]) return kInf;
        continue;
      }
      double a = (0 - o) / v, b = (size[axis] - o) / v;
      if (a > b) std::swap(a, b);
      lo = std::max(lo, a);
      hi = std::min(hi, b);
    }
    return lo <= hi ? lo : kInf;
  }

  Canvas canvas_;
};

}  // namespace

std::unique_ptr<Renderer> make_grid_ray_caster() { return std::make_unique<GridRayCaster>(); }

}  // namespace p3d::render
