// Sphere tracing over the wall segments of any level (the survey's Algorithms 8
// and 9): march each column's ray forward by the distance to the nearest wall,
// which can never overshoot one; once within epsilon of a wall, test the walls
// that close exactly (the hybrid of distance fields and exact segment tests).
//
// Two distance queries: "sphere-naive" measures every wall at every step; "sphere"
// keeps a uniform grid whose cells list the walls within one cell of them and,
// for empty cells, a conservative lower bound on the distance (a breadth-first
// ring count). Both report the steps they take.
//
// Steps are over-relaxed (Keinert et al.'s enhanced sphere tracing) with a fallback
// that keeps them safe. A ray passes through two-sided walls (drawn, then ignored: a ray crosses a line
// once), stops at solid ones, ignores close walls it misses (grazing along them,
// or passing their ends), gives up after the step limit and stops when it leaves
// the level's box moving away.
#include <algorithm>
#include <cmath>
#include <deque>

#include "engine/render/draw.h"
#include "engine/render/renderer.h"

namespace p3d::render {

namespace {

using geom::segment_distance;

double box_distance(Vec2 p, const geom::BBox& b) {
  const double dx = std::max({b.min.x - p.x, 0.0, p.x - b.max.x});
  const double dy = std::max({b.min.y - p.y, 0.0, p.y - b.max.y});
  return std::sqrt(dx * dx + dy * dy);
}

// Uniform grid over the level: per cell, the walls within `margin` of it, or a
// lower bound on the distance to any wall when there are none.
class DistanceGrid {
 public:
  void build(const level::Level& level) {
    box_ = level.bounds;
    const double w = std::max(box_.max.x - box_.min.x, 1.0), h = std::max(box_.max.y - box_.min.y, 1.0);
    cell_ = std::clamp(std::sqrt(w * h / (4.0 * std::max<size_t>(level.walls.size(), 1))), 4.0, 4096.0);
    margin_ = cell_;
    cols_ = int(w / cell_) + 1;
    rows_ = int(h / cell_) + 1;
    const size_t cells = size_t(cols_) * rows_;
    std::vector<std::vector<uint32_t>> lists(cells);
    for (uint32_t i = 0; i < level.walls.size(); ++i) add_wall(level.walls[i], i, lists);
    start_.assign(cells + 1, 0);
    walls_.clear();
    for (size_t c = 0; c < cells; ++c) {
      walls_.insert(walls_.end(), lists[c].begin(), lists[c].end());
      start_[c + 1] = uint32_t(walls_.size());
    }
    compute_lower_bounds();
  }

  // A lower bound on the distance from p to the nearest wall not in `ignored`, and
  // the walls closer than eps (exactly measured) in `near`.
  template <typename Ignored>
  double distance(const level::Level& level, Vec2 p, double eps, const Ignored& ignored, std::vector<uint32_t>& near) const {
    near.clear();
    const int c = int(std::floor((p.x - box_.min.x) / cell_)), r = int(std::floor((p.y - box_.min.y) / cell_));
    if (c < 0 || r < 0 || c >= cols_ || r >= rows_) return std::max(box_distance(p, box_), 0.0);
    const size_t cell = size_t(r) * cols_ + c;
    if (start_[cell] == start_[cell + 1]) return lower_bound_[cell];
    double best = margin_;  // walls not listed here are at least this far
    for (uint32_t k = start_[cell]; k < start_[cell + 1]; ++k) {
      const uint32_t i = walls_[k];
      if (ignored(i)) continue;
      const double d = segment_distance(p, level.walls[i].a, level.walls[i].b);
      if (d < eps) near.push_back(i);
      best = std::min(best, d);
    }
    return best;
  }

 private:
  void add_wall(const level::Wall& w, uint32_t index, std::vector<std::vector<uint32_t>>& lists) const {
    const int c0 = std::max(0, int((std::min(w.a.x, w.b.x) - margin_ - box_.min.x) / cell_));
    const int c1 = std::min(cols_ - 1, int((std::max(w.a.x, w.b.x) + margin_ - box_.min.x) / cell_));
    const int r0 = std::max(0, int((std::min(w.a.y, w.b.y) - margin_ - box_.min.y) / cell_));
    const int r1 = std::min(rows_ - 1, int((std::max(w.a.y, w.b.y) + margin_ - box_.min.y) / cell_));
    for (int r = r0; r <= r1; ++r)
      for (int c = c0; c <= c1; ++c) {
        // Within margin of the cell: the distance from the cell's centre minus its half diagonal.
        const Vec2 centre = box_.min + Vec2((c + 0.5) * cell_, (r + 0.5) * cell_);
        if (segment_distance(centre, w.a, w.b) <= margin_ + cell_ * M_SQRT1_2 + 1e-9)
          lists[size_t(r) * cols_ + c].push_back(index);
      }
  }

  // Breadth-first over 8-neighbours from listed cells: an empty cell k rings from the
  // nearest listed one has no wall within (k - 1) cells + margin of any of its points.
  void compute_lower_bounds() {
    const size_t cells = size_t(cols_) * rows_;
    std::vector<int> ring(cells, -1);
    std::deque<size_t> queue;
    for (size_t c = 0; c < cells; ++c)
      if (start_[c] != start_[c + 1]) ring[c] = 0, queue.push_back(c);
    while (!queue.empty()) {
      const size_t c = queue.front();
      queue.pop_front();
      const int cx = int(c % cols_), cy = int(c / cols_);
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int nx = cx + dx, ny = cy + dy;
          if (nx < 0 || ny < 0 || nx >= cols_ || ny >= rows_) continue;
          const size_t n = size_t(ny) * cols_ + nx;
          if (ring[n] < 0) ring[n] = ring[c] + 1, queue.push_back(n);
        }
    }
    lower_bound_.assign(cells, 0);
    for (size_t c = 0; c < cells; ++c)
      lower_bound_[c] = ring[c] > 0 ? (ring[c] - 1) * cell_ + margin_ : ring[c] < 0 ? INFINITY : 0;
  }

  geom::BBox box_;
  double cell_ = 1, margin_ = 1;
  int cols_ = 0, rows_ = 0;
  std::vector<uint32_t> start_, walls_;
  std::vector<double> lower_bound_;
};

class SphereTracer final : public Renderer {
 public:
  SphereTracer(const RendererOptions& options, bool accelerated)
      : eps_(std::max(options.sphere_epsilon, 1e-6)), omega_(std::clamp(options.sphere_relaxation, 1.0, 1.99)),
        max_steps_(std::max(options.sphere_max_steps, 1)), accelerated_(accelerated) {}

  std::string_view name() const override { return accelerated_ ? "sphere" : "sphere-naive"; }
  using Renderer::render;

  void prepare(const level::Level& level) override {
    if (!accelerated_ || prepared_for_ == level.generation) return;
    grid_.build(level);
    prepared_for_ = level.generation;
  }

  RenderStats render(const level::Level& level, const level::State& state, const Camera& camera, Frame& frame,
                     Probe* probe) override {
    prepare(level);
    const View view(camera, frame.width, frame.height, level, frame.doom_screen_width);
    canvas_.begin(level, state, view, frame, level.sector_at(camera.pos), probe);  // Doom's rule, as every renderer's
    RenderStats stats;
    for (int x = 0; x < view.width; ++x) stats.add_ray(trace(level, view, x));
    for (uint32_t i = 0; i < state.things.size(); ++i) canvas_.add_sprite(i);
    canvas_.finish();
    canvas_.resolve(0, view.height);
    canvas_.count_into(stats);
    return stats;
  }

 private:
  // Marches column x's ray; returns the steps taken.
  uint64_t trace(const level::Level& level, const View& view, int x) {
    const Vec2 ray = view.ray(x);
    const double length = glm::length(ray);
    const Vec2 dir = ray / length;
    const double depth_per_unit = view.d / length;  // forward depth gained per map unit along the ray
    ignored_.clear();
    auto is_ignored = [&](uint32_t w) { return std::find(ignored_.begin(), ignored_.end(), w) != ignored_.end(); };
    double s = 0, omega = omega_, previous_r = 0, step = 0;
    uint64_t steps = 0;
    while (steps < uint64_t(max_steps_)) {
      ++steps;
      const Vec2 p = view.pos + dir * s;
      const double r = distance(level, p, is_ignored);
      // Over-relaxation (Keinert et al. 2014): step omega * r, but if this sphere and
      // the previous one no longer overlap, a wall may lie between: go back to the
      // plain step, take that one unrelaxed, then relax again.
      if (omega > 1 && r + previous_r < step) {
        s -= step * (omega - 1) / omega;
        step = 0;
        previous_r = 0;
        omega = 1;
        continue;
      }
      previous_r = r;
      if (r >= eps_) {
        if (escaping(level.bounds, p, dir)) break;
        step = omega * r;
        s += step;
        omega = omega_;
        continue;
      }
      step = 0;
      // Within epsilon: test the walls this close exactly. One the ray never meets
      // ahead (it passes its end, or runs along it) can be ignored for good.
      WallHit best{0, -1, INFINITY, 0};
      bool found = false;
      for (uint32_t i : near_) {
        const level::Wall& w = level.walls[i];
        double depth, t;
        if (!WallProjector(view, w.a, w.b).hit(x, depth, t) ||
            depth < s * depth_per_unit - 1e-9 * (1 + s)) {
          ignored_.push_back(i);
          continue;
        }
        if (depth < best.depth) best = {i, facing_side(w, view.pos), depth, t}, found = true;
      }
      if (!found) continue;  // every close wall was missed: measure again without them
      ignored_.push_back(best.wall);  // the ray crosses this line once: never again
      s = best.depth / depth_per_unit;
      previous_r = 0;
      if (best.side >= 0 && visible_side(level.walls[best.wall], best.side) && canvas_.draw_wall(x, best)) break;
    }
    return steps;
  }

  template <typename Ignored>
  double distance(const level::Level& level, Vec2 p, const Ignored& ignored) {
    if (accelerated_) return grid_.distance(level, p, eps_, ignored, near_);
    near_.clear();
    double best = INFINITY;
    for (uint32_t i = 0; i < level.walls.size(); ++i) {
      if (ignored(i)) continue;
      const double d = segment_distance(p, level.walls[i].a, level.walls[i].b);
      if (d < eps_) near_.push_back(i);
      best = std::min(best, d);
    }
    return best;
  }

  // Outside the level's box and moving further out along some axis: nothing ahead.
  static bool escaping(const geom::BBox& box, Vec2 p, Vec2 dir) {
    return (p.x < box.min.x && dir.x <= 0) || (p.x > box.max.x && dir.x >= 0) || (p.y < box.min.y && dir.y <= 0) ||
           (p.y > box.max.y && dir.y >= 0);
  }

  double eps_, omega_;
  int max_steps_;
  bool accelerated_;
  DistanceGrid grid_;
  uint64_t prepared_for_ = 0;  // the level generation the grid was built for
  Canvas canvas_;
  std::vector<uint32_t> ignored_, near_;
};

}  // namespace

std::unique_ptr<Renderer> make_sphere_tracer(const RendererOptions& options, bool accelerated) {
  return std::make_unique<SphereTracer>(options, accelerated);
}

}  // namespace p3d::render
