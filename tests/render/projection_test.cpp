// The walk's projection of open columns eight at a time (AVX-512) against the scalar
// WallProjector::hit and in_fragment: the same hits, in column order, to the bit.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "engine/render/occlusion.h"
#include "engine/render/view.h"
#include "engine/util/rng.h"

namespace p3d::render {
namespace {

struct Hit {
  int32_t x;
  double depth, t;
  bool operator==(const Hit&) const = default;
};

TEST(Projection, VectorHitsAreTheScalarHits) {
  if (!vector_projection()) GTEST_SKIP() << "no AVX-512 on this processor";
  Rng rng(21);
  std::vector<double> lateral(700);
  size_t hits = 0;
  for (int trial = 0; trial < 10000; ++trial) {
    const int width = int(rng.range(1, 700));
    WallProjector p;
    for (int i = 0; i < 2; ++i) {  // mostly each end's ray within or near the screen
      p.side_dx[i] = rng.uniform(-10, 10);
      p.side0[i] = trial % 4 == 3 ? rng.uniform(-2000, 2000) : -p.side_dx[i] * rng.uniform(-100, width + 100.0);
      p.end_depth[i] = rng.uniform(-20, 500);
    }
    if (trial % 7 == 0) p.side0[0] = 0, p.side_dx[0] = 0;  // an end on every ray: t = 0
    // t = 0.5 exactly, where the depth's two sums may part in the last bit
    if (trial % 11 == 0) p.side0[1] = -p.side0[0], p.side_dx[1] = -p.side_dx[0];
    if (trial % 2) {  // Doom's rays: a column's own lateral offset
      for (int x = 0; x < width; ++x) lateral[size_t(x)] = (x - width / 2) * rng.uniform(0.9, 1.1);
      p.lateral = lateral.data();
    }
    const double t0 = trial % 5 == 0 ? 0 : rng.uniform(-0.2, 0.8);
    const FragmentSpan span{t0, trial % 5 == 1 ? 1 : rng.uniform(t0, 1.2), trial % 3 != 0};
    ColumnMask mask;
    mask.reset(width);
    for (int k = int(rng.below(uint64_t(width) + 1)); k > 0; --k) mask.close(int(rng.below(uint64_t(width))));
    const int x0 = int(rng.below(uint64_t(width))), x1 = x0 + int(rng.below(uint64_t(width - x0)));

    std::vector<Hit> want;
    mask.for_each_open(x0, x1, [&](int x) {
      double depth, t;
      if (p.hit(x, depth, t) && t >= span.t0 && (span.t1_closed ? t <= span.t1 : t < span.t1))
        want.push_back({x, depth, t});
    });
    std::vector<int32_t> xs(static_cast<size_t>(width));
    std::vector<double> depths(static_cast<size_t>(width)), ts(static_cast<size_t>(width));
    const size_t n = open_column_hits_avx512(p, span, mask.words(), x0, x1, {xs.data(), depths.data(), ts.data()});
    std::vector<Hit> got;
    for (size_t k = 0; k < n; ++k) got.push_back({xs[k], depths[k], ts[k]});
    ASSERT_EQ(got, want) << "trial " << trial << ", columns [" << x0 << ", " << x1 << "] of " << width;
    hits += n;
  }
  EXPECT_GT(hits, size_t(60000));  // rays that meet the segment, and many that do not
}

}  // namespace
}  // namespace p3d::render
