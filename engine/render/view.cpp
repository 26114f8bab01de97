#include "engine/render/view.h"

#include <climits>

#include "engine/util/cpu.h"

namespace p3d::render {

namespace {

// Camera-space point: x = lateral (right), y = depth (forward).
Vec2 to_camera(const View& v, Vec2 p) { return {v.lateral_of(p), v.depth_of(p)}; }

// Widens [lo, hi] (in screen x) to whole columns, one extra on each side (more under
// Doom's rules, whose rays stray from the column centres), clamped to the screen.
ColumnRange to_columns(const View& v, double lo, double hi) {
  const int extra = 1 + (v.doom ? v.doom->ray_slack : 0);
  lo = std::clamp(lo, -2.0 - extra, v.width + 2.0 + extra);
  hi = std::clamp(hi, -2.0 - extra, v.width + 2.0 + extra);
  return {std::max(0, static_cast<int>(floor_to_int(lo - 0.5)) - extra),
          std::min(v.width - 1, static_cast<int>(ceil_to_int(hi - 0.5)) + extra)};
}

// Projects a camera-space polygon clipped to depth >= near; empty if nothing is in front.
ColumnRange project(const View& v, const Vec2* pts, int n) {
  double lo = INFINITY, hi = -INFINITY;
  auto add = [&](Vec2 c) {
    const double sx = v.half_w + v.d * c.x / c.y;
    lo = std::min(lo, sx);
    hi = std::max(hi, sx);
  };
  for (int i = 0; i < n; ++i) {
    const Vec2 p = pts[i], q = pts[(i + 1) % n];
    const bool p_in = p.y >= kNearDepth, q_in = q.y >= kNearDepth;
    if (p_in) add(p);
    if (p_in != q_in) add(p + (q - p) * ((kNearDepth - p.y) / (q.y - p.y)));
  }
  if (lo > hi) return {};
  return to_columns(v, lo, hi);
}

}  // namespace

ColumnRange columns_of_segment(const View& v, Vec2 p0, Vec2 p1) {
  const Vec2 pts[2] = {to_camera(v, p0), to_camera(v, p1)};
  return project(v, pts, 2);
}

ColumnRange columns_of_box(const View& v, const geom::BBox& box) {
  if (box.empty()) return {};
  if (box.contains(v.pos, 1)) return {0, v.width - 1};
  const Vec2 pts[4] = {to_camera(v, box.min), to_camera(v, {box.max.x, box.min.y}), to_camera(v, box.max),
                       to_camera(v, {box.min.x, box.max.y})};
  return project(v, pts, 4);
}

bool vector_projection() {
#ifdef P3D_AVX512_PROJECTION
  return has_avx512_vl_dq();
#else
  return false;
#endif
}

void wall_edge_rows(const doom::Fixed* scales, size_t n, const WallEdges& edges) {
  for (int e = 0; e < edges.count; ++e) {
    for (size_t k = 0; k < n; ++k) {
      const int64_t product = (int64_t(edges.world[e]) * scales[k]) >> doom::kFracBits;
      const int64_t edge = edges.crispy ? edges.center - product
                                        : int64_t(play::wrap_sub(doom::Fixed(edges.center), doom::Fixed(product)));
      edges.rows[e][k] = int32_t(std::clamp<int64_t>((edge + edges.round[e]) >> edges.bits, INT_MIN / 2, INT_MAX / 2));
    }
  }
}

#ifndef P3D_AVX512_PROJECTION
// Never called: vector_projection() is false.
size_t open_column_hits_avx512(const WallProjector&, const FragmentSpan&, const uint64_t*, int, int, RayHits) {
  return 0;
}
void doom_scales_avx512(const int32_t*, size_t, const doom::SegSines&, doom::Fixed, doom::Fixed, doom::Fixed,
                        doom::Fixed*) {}
void doom_edge_rows_avx512(const doom::Fixed*, size_t, const WallEdges&) {}
#endif

}  // namespace p3d::render
