// Geometry base shared by the compiler, the loader and the renderers: fixed-point
// map coordinates, exact orientation predicates, bounding boxes.
//
// Map coordinates are stored as integers in 1/256 map unit ("fixed") with
// |x|, |y| <= kMaxCoord map units. That bound makes every predicate below exact:
// differences fit in 31 bits, a cross product of two of them in 62, and the
// crossing predicate (a product of two cross products) in 125 bits of __int128.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

namespace p3d::geom {

__extension__ typedef __int128 i128;  // exact predicates (GCC/Clang)

using Vec2 = glm::dvec2;

constexpr int kFracBits = 8;
constexpr double kFixedOne = 1 << kFracBits;      // fixed units per map unit
constexpr double kMaxCoord = 1 << 21;             // map units: 2,097,152
constexpr int64_t kMaxFixed = int64_t{1} << 29;   // kMaxCoord * kFixedOne

struct IPoint {
  int64_t x = 0, y = 0;
  friend bool operator==(const IPoint&, const IPoint&) = default;
};

inline Vec2 to_world(IPoint p) { return {p.x / kFixedOne, p.y / kFixedOne}; }

// Rounds a map coordinate to the fixed grid; false if it is not finite or out of range.
inline bool to_fixed(double v, int64_t& out) {
  if (!std::isfinite(v) || std::fabs(v) > kMaxCoord) return false;
  out = static_cast<int64_t>(std::llround(v * kFixedOne));
  return true;
}

inline double cross(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }

inline int64_t cross(IPoint a, IPoint b) { return a.x * b.y - a.y * b.x; }
inline IPoint sub(IPoint a, IPoint b) { return {a.x - b.x, a.y - b.y}; }

template <typename T>
int sign(T v) {
  return (v > 0) - (v < 0);
}

// > 0 when c is left of the directed line a->b, < 0 when right, 0 when collinear. Exact.
inline int64_t orient(IPoint a, IPoint b, IPoint c) { return cross(sub(b, a), sub(c, a)); }

// A directed line through two fixed points: origin a, direction d = b - a.
struct Line {
  IPoint a, d;
  static Line through(IPoint p, IPoint q) { return {p, sub(q, p)}; }
};

// Sign of the side of point p relative to line l (+1 left, -1 right, 0 on). Exact.
inline int side_of(const Line& l, IPoint p) { return sign(cross(l.d, sub(p, l.a))); }

// Sign of the side, relative to l, of the point where line c crosses line s. Exact.
// With X = s.a + t s.d and t = N / D, N = cross(c.a - s.a, c.d), D = cross(s.d, c.d):
// cross(l.d, X - l.a) * D = cross(l.d, s.a - l.a) * D + N * cross(l.d, s.d).
// Requires s and c not parallel (D != 0).
inline int side_of_crossing(const Line& l, const Line& s, const Line& c) {
  const int64_t D = cross(s.d, c.d);
  const int64_t N = cross(sub(c.a, s.a), c.d);
  const i128 value = i128{cross(l.d, sub(s.a, l.a))} * D + i128{N} * cross(l.d, s.d);
  return sign(value) * sign(D);
}

// Parameter t along s (s.a + t s.d) where c crosses it, rounded to double. Requires D != 0.
inline double crossing_param(const Line& s, const Line& c) {
  const int64_t D = cross(s.d, c.d);
  const int64_t N = cross(sub(c.a, s.a), c.d);
  return static_cast<double>(N) / static_cast<double>(D);
}

// The point of segment a-b nearest to p, and its distance.
inline Vec2 closest_point(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 ab = b - a;
  const double t = std::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.0, 1.0);
  return a + ab * t;
}
inline double segment_distance(Vec2 p, Vec2 a, Vec2 b) { return glm::length(p - closest_point(p, a, b)); }

inline bool parallel(const Line& a, const Line& b) { return cross(a.d, b.d) == 0; }
inline bool same_line(const Line& a, const Line& b) { return parallel(a, b) && side_of(a, b.a) == 0; }

// How two closed segments a1a2 and b1b2 meet. Touching (an endpoint on the other
// segment) is allowed in maps; crossing interiors and collinear overlap are not.
enum class SegmentContact { kNone, kTouch, kCross, kOverlap };
SegmentContact segment_contact(IPoint a1, IPoint a2, IPoint b1, IPoint b2);

struct BBox {
  Vec2 min{std::numeric_limits<double>::infinity()};
  Vec2 max{-std::numeric_limits<double>::infinity()};

  bool empty() const { return min.x > max.x; }
  void add(Vec2 p) {
    min = {std::min(min.x, p.x), std::min(min.y, p.y)};
    max = {std::max(max.x, p.x), std::max(max.y, p.y)};
  }
  void add(const BBox& b) {
    if (!b.empty()) {
      add(b.min);
      add(b.max);
    }
  }
  bool contains(Vec2 p, double margin = 0) const {
    return p.x >= min.x - margin && p.x <= max.x + margin && p.y >= min.y - margin && p.y <= max.y + margin;
  }
  bool contains(const BBox& b) const { return b.empty() || (contains(b.min) && contains(b.max)); }
};

}  // namespace p3d::geom
