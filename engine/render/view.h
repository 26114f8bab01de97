// The projection shared by every renderer, so that they agree to the last bit:
// column x is sampled at x + 0.5, its ray is forward*d + right*((x+0.5) - W/2)
// with d = (W/2) / tan(fov/2); row y is sampled at y + 0.5 below the horizon H/2.
// On a WAD level at a 90-degree view, Doom's rules instead (doom_rules.h): column x
// looks along Doom's xtoviewangle[x], its ray forward*d + right*(d * lateral[x]), and
// the view's position and angle are also kept in Doom's 16.16 and binary angles.
#pragma once

#include <algorithm>
#include <cmath>

#include "engine/render/camera.h"
#include "engine/render/doom_rules.h"
#include "engine/util/rounding.h"

namespace p3d::render {

constexpr double kNearDepth = 1e-3;  // hits closer than this (along forward) are ignored

struct View {
  int width = 0, height = 0;
  Vec2 pos;
  double eye = 0;
  double angle = 0;       // radians
  Vec2 forward, right;    // unit vectors; right is forward turned clockwise
  double d = 1;           // projection distance in pixels
  double half_w = 0, half_h = 0;
  Vec2 ray0;              // ray of column 0; ray(x) = ray0 + right * x (our rules)
  // Doom's rules: the tables of this size, and the view in Doom's numbers; nullptr: ours.
  const doom::Tables* doom = nullptr;
  doom::Fixed fx = 0, fy = 0, fz = 0;  // viewx, viewy, viewz
  doom::Angle fangle = 0;              // viewangle

  View(const Camera& camera, int w, int h) : width(w), height(h), pos(camera.pos), eye(camera.z) {
    angle = std::fmod(camera.angle, 360.0) * (M_PI / 180);  // any angle: the sky's texture column stays in range
    forward = {std::cos(angle), std::sin(angle)};
    right = {forward.y, -forward.x};
    half_w = w * 0.5;
    half_h = h * 0.5;
    d = half_w / std::tan(camera.fov * (M_PI / 360));
    ray0 = forward * d + right * (0.5 - half_w);
  }
  // The view of a level: Doom's rules for a WAD level (its art is paletted) seen over
  // Doom's 90 degrees, within the range Doom's 16.16 holds; ours otherwise.
  View(const Camera& camera, int w, int h, const level::Level& level, int doom_screen_width = 0) : View(camera, w, h) {
    constexpr double kDoomRange = 32000;
    if (!level.paletted() || camera.fov != 90 || w < 2 || h < 2 || std::fabs(camera.pos.x) > kDoomRange ||
        std::fabs(camera.pos.y) > kDoomRange || std::fabs(camera.z) > kDoomRange)
      return;
    doom = &doom::tables(w, h, doom_screen_width);
    fx = doom::to_fixed(camera.pos.x);
    fy = doom::to_fixed(camera.pos.y);
    fz = doom::to_fixed(camera.z);
    fangle = doom::to_angle(camera.angle);
  }

  Vec2 ray(int x) const { return doom ? forward * d + right * (d * doom->lateral[size_t(x)]) : ray0 + right * double(x); }
  double depth_of(Vec2 p) const { return glm::dot(p - pos, forward); }
  double lateral_of(Vec2 p) const { return glm::dot(p - pos, right); }

  // Screen y (continuous, 0 at the top) of height z seen at depth `depth`.
  double screen_y(double z, double depth) const { return half_h - (z - eye) * d / depth; }

  // First row whose centre is at or below screen y, clamped to [0, height].
  int row_at(double y) const {
    const double r = y - 0.5;
    return !(r > 0) ? 0 : r > height ? height : static_cast<int>(ceil_to_int(r));  // NaN: 0
  }
};

// A wall segment as seen from one view: where column x's ray crosses it, for one
// division. Every quantity comes from one end alone (its side of the ray, its
// depth), so walls sharing a vertex agree exactly on whether a ray passes left of
// it, right of it, or through it. A ray through a vertex belongs only to the walls
// that extend to its right (half-open, like rasterization's top-left rule): at a
// room's corner exactly one wall is hit, and no renderer can pick a different one.
// Every renderer hits walls through this, so they agree.
struct WallProjector {
  // cross(ray(x), end - pos) = side0 + side_dx * x (ours), side0 + side_dx * lateral[x]
  // (Doom's rules: side0 is then the forward ray's); < 0: right.
  double side0[2] = {0, 0}, side_dx[2] = {0, 0};
  double end_depth[2] = {0, 0};                   // each end's depth along the view direction
  const double* lateral = nullptr;                // Doom's rules: View::doom->lateral scaled by d

  WallProjector() = default;
  WallProjector(const View& v, Vec2 a, Vec2 b) {
    const Vec2 ends[2] = {a, b};
    const Vec2 base = v.doom ? v.forward * v.d : v.ray0;
    const Vec2 across = v.doom ? v.right * v.d : v.right;
    if (v.doom) lateral = v.doom->lateral.data();
    for (int i = 0; i < 2; ++i) {
      const Vec2 rel = ends[i] - v.pos;
      side0[i] = geom::cross(base, rel);
      side_dx[i] = geom::cross(across, rel);
      end_depth[i] = v.depth_of(ends[i]);
    }
  }

  // Depth (along forward) and wall parameter t (0 at a, 1 at b) where column x's ray
  // crosses the segment; false when it passes beside it, runs along it, or meets it
  // behind the near plane.
  bool hit(int x, double& depth, double& t) const {
    const double at = lateral ? lateral[x] : double(x);
    const double s0 = side0[0] + side_dx[0] * at, s1 = side0[1] + side_dx[1] * at;
    if ((s0 < 0) == (s1 < 0)) return false;  // both ends on one side (an end on the ray counts as left)
    t = s0 / (s0 - s1);
    // Interpolated from the nearer end, so a hit exactly at an end has exactly that end's depth.
    depth = t <= 0.5 ? end_depth[0] + (end_depth[1] - end_depth[0]) * t
                     : end_depth[1] - (end_depth[1] - end_depth[0]) * (1 - t);
    return depth > kNearDepth;
  }

  // Which end lies right of column x's ray (only meaningful for a hit): 0 for a, 1 for b.
  int right_end(int x) const { return side0[0] + side_dx[0] * (lateral ? lateral[x] : double(x)) < 0 ? 0 : 1; }
};

// Whether wall b hides wall a just right of a column's ray, where both are hit at
// the same point (a shared vertex or a crossing). Both extend to the right there
// (see WallProjector); the one turned further towards the camera is in front.
// Exact, on the walls' fixed-point ends: any valid front-to-back order agrees.
inline bool hides_to_the_right(const level::Wall& a, int a_right_end, const level::Wall& b, int b_right_end) {
  const geom::IPoint da = a_right_end == 1 ? geom::sub(a.p2, a.p1) : geom::sub(a.p1, a.p2);
  const geom::IPoint db = b_right_end == 1 ? geom::sub(b.p2, b.p1) : geom::sub(b.p1, b.p2);
  return geom::cross(da, db) < 0;  // b turned clockwise from a: towards the camera
}

// A fragment's share of its wall: [t0, t1], open at an end where a splitter cut it,
// so a hit exactly on a cut belongs to one fragment only.
inline bool in_fragment(const level::Fragment& f, double t) {
  return t >= f.t0 && (f.cut[1] == level::kNone ? t <= f.t1 : t < f.t1);
}

// A fragment's share of its wall as in_fragment takes it: [t0, t1], or [t0, t1) when
// cut at t1.
struct FragmentSpan {
  double t0, t1;
  bool t1_closed;
};
inline FragmentSpan span_of(const level::Fragment& f) { return {f.t0, f.t1, f.cut[1] == level::kNone}; }

// Where the rays of open columns hit: parallel arrays with room for every column asked about.
struct RayHits {
  int32_t* x;
  double* depth;
  double* t;
};
// Whether this processor has AVX-512 (F, VL and DQ), and the loops below are built.
bool vector_projection();
// WallProjector::hit and in_fragment for each column of [x0, x1] whose bit in `closed`
// (ColumnMask's words) is clear, eight at a time: the hits in column order, how many.
// The same hits as the scalar test, to the bit. Only where vector_projection() is true.
size_t open_column_hits_avx512(const WallProjector& p, const FragmentSpan& span, const uint64_t* closed, int x0, int x1,
                               RayHits out);
// doom::scale_at for n columns xs (in increasing order) of one seg, eight at a time: its
// two sines (doom::SegSines) loaded for eight neighbouring columns, else gathered;
// R_ScaleFromGlobalAngle's products, its division (in doubles, which give the integer
// quotient exactly here) and its clamps, the same scales to the bit. Only where
// vector_projection() is true.
void doom_scales_avx512(const int32_t* xs, size_t n, const doom::SegSines& sines, doom::Fixed projection,
                        doom::Fixed distance, doom::Fixed max_scale, doom::Fixed* out);
// Up to four wall edges of one run, each at height world[e] (in the run's fixed point
// of `bits` fraction bits, as center), its rows rounded by round[e] and written to
// rows[e]; Crispy's in 64 bits, vanilla's wrapping in 32.
struct WallEdges {
  int64_t center;
  int bits;
  bool crispy;
  int count = 0;
  doom::Fixed world[4];
  int64_t round[4];
  int32_t* rows[4];
};
// The edges' rows for n columns of scales: center - world * scale >> 16, plus round,
// shifted down by bits and clamped to [INT_MIN / 2, INT_MAX / 2].
void wall_edge_rows(const doom::Fixed* scales, size_t n, const WallEdges& edges);
// The same eight columns at a time, every edge from one load of the scales. Only where
// vector_projection() is true.
void doom_edge_rows_avx512(const doom::Fixed* scales, size_t n, const WallEdges& edges);

// A conservative range of screen columns [x0, x1]; empty when x0 > x1.
struct ColumnRange {
  int x0 = 1, x1 = 0;
  bool empty() const { return x0 > x1; }
};

// Columns whose ray may meet the segment p0-p1 (clipped to the near plane), widened by one.
ColumnRange columns_of_segment(const View& v, Vec2 p0, Vec2 p1);
// Columns whose ray may meet the box; the whole screen when the camera is inside it.
ColumnRange columns_of_box(const View& v, const geom::BBox& box);

// The side of wall w facing the camera: 0 front, 1 back, -1 edge-on.
inline int facing_side(const level::Wall& w, Vec2 pos) {
  const double s = geom::cross(w.b - w.a, pos - w.a);
  return s < 0 ? 0 : s > 0 ? 1 : -1;
}

// Whether the camera may see side `side` of wall w: one-sided walls show only their front.
inline bool visible_side(const level::Wall& w, int side) { return side == 0 || w.segment() || w.two_sided(); }

}  // namespace p3d::render
