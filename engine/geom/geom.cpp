#include "engine/geom/geom.h"

namespace p3d::geom {

namespace {

// Position of c along the collinear segment a->b, in units of the dominant axis.
int64_t along(IPoint a, IPoint b, IPoint c) {
  return std::llabs(b.x - a.x) >= std::llabs(b.y - a.y) ? c.x - a.x : c.y - a.y;
}

}  // namespace

SegmentContact segment_contact(IPoint a1, IPoint a2, IPoint b1, IPoint b2) {
  const int o1 = sign(orient(a1, a2, b1));
  const int o2 = sign(orient(a1, a2, b2));
  const int o3 = sign(orient(b1, b2, a1));
  const int o4 = sign(orient(b1, b2, a2));

  if (o1 == 0 && o2 == 0) {  // collinear: compare intervals along the line
    int64_t lo_a = 0, hi_a = along(a1, a2, a2);
    int64_t lo_b = along(a1, a2, b1), hi_b = along(a1, a2, b2);
    if (lo_a > hi_a) std::swap(lo_a, hi_a);
    if (lo_b > hi_b) std::swap(lo_b, hi_b);
    const int64_t overlap = std::min(hi_a, hi_b) - std::max(lo_a, lo_b);
    if (overlap > 0) return SegmentContact::kOverlap;
    return overlap == 0 ? SegmentContact::kTouch : SegmentContact::kNone;
  }
  if (o1 * o2 < 0 && o3 * o4 < 0) return SegmentContact::kCross;

  // An endpoint exactly on the other segment's line: touching if it lies within it.
  auto on_segment = [](IPoint p, IPoint q, IPoint r) {  // r collinear with pq
    return std::min(p.x, q.x) <= r.x && r.x <= std::max(p.x, q.x) && std::min(p.y, q.y) <= r.y &&
           r.y <= std::max(p.y, q.y);
  };
  if ((o1 == 0 && on_segment(a1, a2, b1)) || (o2 == 0 && on_segment(a1, a2, b2)) ||
      (o3 == 0 && on_segment(b1, b2, a1)) || (o4 == 0 && on_segment(b1, b2, a2)))
    return SegmentContact::kTouch;
  return SegmentContact::kNone;
}

}  // namespace p3d::geom
