#include <gtest/gtest.h>

#include "engine/geom/geom.h"
#include "engine/geom/polygon.h"
#include "engine/util/rng.h"

namespace p3d::geom {
namespace {

IPoint fx(double x, double y) {
  IPoint p;
  EXPECT_TRUE(to_fixed(x, p.x));
  EXPECT_TRUE(to_fixed(y, p.y));
  return p;
}

TEST(Geom, FixedRoundingAndRange) {
  int64_t v;
  EXPECT_TRUE(to_fixed(1.5, v));
  EXPECT_EQ(v, 384);
  EXPECT_TRUE(to_fixed(-kMaxCoord, v));
  EXPECT_FALSE(to_fixed(kMaxCoord + 1, v));
  EXPECT_FALSE(to_fixed(std::nan(""), v));
  EXPECT_FALSE(to_fixed(INFINITY, v));
  EXPECT_EQ(to_world({256, -512}), Vec2(1, -2));
}

TEST(Geom, OrientSigns) {
  const IPoint a = fx(0, 0), b = fx(10, 0);
  EXPECT_GT(orient(a, b, fx(5, 1)), 0);   // left
  EXPECT_LT(orient(a, b, fx(5, -1)), 0);  // right
  EXPECT_EQ(orient(a, b, fx(-7, 0)), 0);  // collinear, outside the segment
}

TEST(Geom, OrientIsExactAtTheCoordinateLimit) {
  // Nearly collinear points at the extremes of the range: doubles would lose the sign.
  const IPoint a{-kMaxFixed, -kMaxFixed}, b{kMaxFixed, kMaxFixed - 1}, c{kMaxFixed - 1, kMaxFixed - 2};
  const i128 exact = i128(b.x - a.x) * (c.y - a.y) - i128(b.y - a.y) * (c.x - a.x);
  EXPECT_EQ(sign(orient(a, b, c)), sign(exact));
  EXPECT_NE(orient(a, b, c), 0);
}

// The crossing of two lines through a lattice point X lies exactly at X, so its side
// relative to any third line must equal X's own side: an exact oracle.
TEST(Geom, SideOfCrossingMatchesKnownIntersection) {
  Rng rng(7);
  int zero = 0, nonzero = 0;
  for (int i = 0; i < 20000; ++i) {
    const int64_t range = kMaxFixed / 4;
    auto rnd = [&](int64_t r) { return int64_t(rng.below(uint64_t(2 * r + 1))) - r; };
    const IPoint x{rnd(range), rnd(range)};
    const IPoint ds{rnd(1 << 20), rnd(1 << 20)}, dc{rnd(1 << 20), rnd(1 << 20)};
    if (cross(ds, dc) == 0) continue;
    const Line s{{x.x - ds.x, x.y - ds.y}, ds}, c{{x.x + 3 * dc.x, x.y + 3 * dc.y}, dc};
    // Half of the lines l pass through X exactly, the rest miss it by a hair.
    const IPoint dl{rnd(1 << 24), rnd(1 << 24)};
    const IPoint la = i % 2 ? IPoint{x.x - dl.x, x.y - dl.y} : IPoint{x.x - dl.x + rnd(2), x.y - dl.y + rnd(2)};
    const Line l{la, dl};
    if (dl.x == 0 && dl.y == 0) continue;
    const int expected = side_of(l, x);
    EXPECT_EQ(side_of_crossing(l, s, c), expected) << "case " << i;
    (expected == 0 ? zero : nonzero)++;
  }
  EXPECT_GT(zero, 1000);
  EXPECT_GT(nonzero, 1000);
}

TEST(Geom, CrossingParam) {
  const Line s = Line::through(fx(0, 0), fx(10, 0));
  const Line c = Line::through(fx(4, -3), fx(4, 5));
  EXPECT_DOUBLE_EQ(crossing_param(s, c), 0.4);
  EXPECT_TRUE(parallel(s, Line::through(fx(0, 1), fx(3, 1))));
  EXPECT_TRUE(same_line(s, Line::through(fx(20, 0), fx(-5, 0))));
  EXPECT_FALSE(same_line(s, Line::through(fx(0, 1), fx(3, 1))));
}

TEST(Geom, SegmentContacts) {
  auto contact = [](double ax, double ay, double bx, double by, double cx, double cy, double dx, double dy) {
    return segment_contact(fx(ax, ay), fx(bx, by), fx(cx, cy), fx(dx, dy));
  };
  EXPECT_EQ(contact(0, 0, 10, 10, 0, 10, 10, 0), SegmentContact::kCross);
  EXPECT_EQ(contact(0, 0, 10, 0, 10, 0, 10, 5), SegmentContact::kTouch);     // shared end
  EXPECT_EQ(contact(0, 0, 10, 0, 5, 0, 5, 5), SegmentContact::kTouch);       // T-junction
  EXPECT_EQ(contact(0, 0, 10, 0, 5, 1, 5, 5), SegmentContact::kNone);
  EXPECT_EQ(contact(0, 0, 10, 0, 5, 0, 15, 0), SegmentContact::kOverlap);    // collinear overlap
  EXPECT_EQ(contact(0, 0, 10, 0, 10, 0, 15, 0), SegmentContact::kTouch);     // collinear, end to end
  EXPECT_EQ(contact(0, 0, 10, 0, 11, 0, 15, 0), SegmentContact::kNone);      // collinear, apart
  EXPECT_EQ(contact(0, 0, 10, 0, 2, 0, 8, 0), SegmentContact::kOverlap);     // contained
  EXPECT_EQ(contact(0, 0, 0, 10, 0, 3, 0, 7), SegmentContact::kOverlap);     // vertical contained
  // Near-degenerate: a crossing by 1/256 of a unit.
  EXPECT_EQ(contact(0, 0, 1000, 0, 500, -1.0 / 256, 500, 7), SegmentContact::kCross);
  EXPECT_EQ(contact(0, 0, 1000, 1, 500, 0.5, 1500, 1.5), SegmentContact::kOverlap);
}

TEST(Geom, ClipPolygonKeepsTheRightHalf) {
  const Polygon square = box_polygon({{0, 0}, {10, 10}});
  const Polygon left = clip_polygon(square, {5, 0}, {0, 1}, +1);   // keep cross(dir, p - o) >= 0: x <= 5
  const Polygon right = clip_polygon(square, {5, 0}, {0, 1}, -1);
  EXPECT_NEAR(polygon_area(left), 50, 1e-9);
  EXPECT_NEAR(polygon_area(right), 50, 1e-9);
  EXPECT_NEAR(polygon_centroid(left).x, 2.5, 1e-9);
  EXPECT_TRUE(clip_polygon(square, {20, 0}, {0, 1}, -1).empty());
  BBox b;
  b.add({1, 2});
  b.add({-3, 5});
  EXPECT_TRUE(b.contains(Vec2(0, 3)));
  EXPECT_FALSE(b.contains(Vec2(2, 3)));
}

}  // namespace
}  // namespace p3d::geom
