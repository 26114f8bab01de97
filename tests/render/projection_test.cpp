// The walk's projection of open columns eight at a time (AVX-512) against the scalar
// WallProjector::hit and in_fragment: the same hits, in column order, to the bit.
#include <gtest/gtest.h>

#include <algorithm>
#include <climits>
#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

#include "engine/play/angle.h"
#include "engine/render/doom_rules.h"
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

// Doom's wall scales eight at a time, their sines gathered: doom::scale_at's, to the
// bit, for random segs, views and columns (the division in doubles, saturated quotients,
// the clamps), at Crispy's and vanilla's widths; and for raw quotients chosen just below
// whole numbers.
TEST(Projection, VectorScalesAreScaleAt) {
  if (!vector_projection()) GTEST_SKIP() << "no AVX-512 on this processor";
  Rng rng(22);
  size_t clamped = 0, saturated = 0;
  for (const auto& [width, height] : {std::pair{640, 400}, std::pair{320, 200}, std::pair{1920, 1080}}) {
    const doom::Tables& t = doom::tables(width, height);
    for (int trial = 0; trial < 3000; ++trial) {
      doom::Seg seg;
      seg.normal = doom::Angle(rng.next());
      // Distances near and far (down to zero and negative: a seg seen edge-on or behind).
      seg.distance = trial % 3 == 0 ? doom::Fixed(rng.next()) : doom::Fixed(rng.below(uint64_t(1) << (10 + trial % 20)));
      const doom::Angle view_angle = doom::Angle(rng.next());
      const doom::Fixed max_scale = trial % 8 == 0   ? doom::Fixed(rng.range(1, 512))  // below 256: the clamps' order
                                    : trial % 4 == 0 ? doom::Fixed(rng.range(1, 1 << 30))
                                                     : 64 * doom::kFracUnit;
      // A run's columns, in order: mostly neighbours (loaded), some apart (gathered).
      std::vector<int32_t> xs{int32_t(rng.below(uint64_t(width)))};
      for (size_t k = 1, n = size_t(rng.range(1, 40)); k < n; ++k) {
        const int32_t x = xs.back() + 1 + (rng.below(4) == 0 ? int32_t(rng.below(6)) : 0);
        if (x >= width) break;
        xs.push_back(x);
      }
      const size_t n = xs.size();
      std::vector<doom::Fixed> sine_view(n), sine_seg(n), got(n + 8, 0x5A5A5A5A);
      for (size_t k = 0; k < n; ++k) {
        const doom::ScaleSines sines = doom::scale_sines(t, seg, view_angle, xs[k]);
        sine_view[k] = sines.view, sine_seg[k] = sines.seg;
      }
      doom_scales_avx512(xs.data(), n, doom::seg_sines(t, seg, view_angle), t.projection, seg.distance, max_scale,
                         got.data());
      for (size_t k = 0; k < n; ++k) {
        const doom::Fixed want = doom::scale_at(t, seg, view_angle, xs[k], max_scale);
        ASSERT_EQ(got[k], want) << width << " columns, trial " << trial << ", x " << xs[k];
        clamped += want == max_scale || want == 256;
        const doom::Fixed num = play::fixed_mul(t.projection, sine_seg[k]);
        const doom::Fixed den = play::fixed_mul(seg.distance, sine_view[k]);
        saturated += den > (num >> doom::kFracBits) && (std::abs(int64_t(num)) >> 14) >= std::abs(int64_t(den));
      }
      for (size_t k = n; k < n + 8; ++k) ASSERT_EQ(got[k], 0x5A5A5A5A) << "wrote past the columns";
    }
  }
  EXPECT_GT(clamped, size_t(1000));  // every branch of scale_at taken
  EXPECT_GT(saturated, size_t(10));

  // Sines of one: the products are the projection and the distance themselves, so the
  // quotient (num << 16) / den can be put just below (or above) a whole number, where a
  // division in doubles could round across it.
  const doom::Fixed one = doom::kFracUnit;
  const doom::Angle straight = 0;
  const int32_t column = 0;
  const doom::SegSines ones{&one, &straight, &one, 0};
  for (int trial = 0; trial < 200000; ++trial) {
    const doom::Fixed den = doom::Fixed(rng.range(1 << 16, INT32_MAX)) * (trial % 2 ? 1 : -1);
    const int64_t whole = int64_t(rng.range(1, 1 << 14)) * (trial % 4 < 2 ? 1 : -1);
    const int64_t dividend = whole * den + (trial % 3 == 0 ? 1 : -1);  // one off a multiple of den
    const doom::Fixed num = doom::Fixed(std::clamp<int64_t>(dividend >> 16, INT32_MIN, INT32_MAX));
    doom::Fixed got[8];
    doom_scales_avx512(&column, 1, ones, num, den, INT32_MAX, got);
    const doom::Fixed want = doom::scale_from_sines(num, {doom::kFracUnit, doom::kFracUnit}, den, INT32_MAX);
    ASSERT_EQ(got[0], want) << "num " << num << ", den " << den;
  }
}

// A run's wall edges eight columns at a time: R_RenderSegLoop's rows (Crispy's in 64
// bits, vanilla's wrapping in 32), rounded up or down, clamped, for one to four edges of
// random heights, scales and precisions, each written to its own rows and nothing past
// them; the scalar wall_edge_rows alike.
TEST(Projection, VectorEdgeRowsAreTheScalarRows) {
  Rng rng(23);
  for (int trial = 0; trial < 20000; ++trial) {
    const bool crispy = trial % 2 == 0;
    const int bits = crispy ? int(rng.range(4, 16)) : 12;
    WallEdges edges{crispy ? int64_t(rng.range(0, 1 << 20)) << (bits - 4) : int64_t(rng.range(0, 200 << 12)), bits,
                    crispy};
    edges.count = int(rng.range(1, 4));
    const size_t n = size_t(rng.range(1, 30));
    std::vector<doom::Fixed> scales(n);
    for (doom::Fixed& scale : scales) scale = trial % 7 == 0 ? doom::Fixed(rng.next()) : doom::Fixed(rng.range(256, 64 << 16));
    const size_t stride = n + 8;  // each edge's rows, then 8 that must stay untouched
    std::vector<int32_t> vector_rows(4 * stride, 0x5A5A5A5A), scalar_rows = vector_rows;
    for (int e = 0; e < edges.count; ++e) {
      edges.world[e] = doom::Fixed(rng.below(5) == 0 ? rng.next() : rng.range(-(1 << 24), 1 << 24));
      edges.round[e] = rng.below(2) == 0 ? 0 : (int64_t(1) << bits) - 1;
    }
    auto rows_into = [&](std::vector<int32_t>& rows) {
      for (int e = 0; e < edges.count; ++e) edges.rows[e] = rows.data() + size_t(e) * stride;
    };
    rows_into(scalar_rows);
    wall_edge_rows(scales.data(), n, edges);
    if (vector_projection()) {
      rows_into(vector_rows);
      doom_edge_rows_avx512(scales.data(), n, edges);
    }
    for (int e = 0; e < 4; ++e) {
      for (size_t k = 0; k < stride; ++k) {
        int32_t want = 0x5A5A5A5A;  // past the columns, or an edge not asked for
        if (e < edges.count && k < n) {
          const int64_t product = (int64_t(edges.world[e]) * scales[k]) >> doom::kFracBits;
          const int64_t edge = crispy ? edges.center - product
                                      : int64_t(play::wrap_sub(doom::Fixed(edges.center), doom::Fixed(product)));
          want = int32_t(std::clamp<int64_t>((edge + edges.round[e]) >> bits, INT_MIN / 2, INT_MAX / 2));
        }
        ASSERT_EQ(scalar_rows[size_t(e) * stride + k], want) << "trial " << trial << ", edge " << e << ", column " << k;
        if (vector_projection()) {
          ASSERT_EQ(vector_rows[size_t(e) * stride + k], want)
              << "vector, trial " << trial << ", edge " << e << ", column " << k;
        }
      }
    }
  }
}

}  // namespace
}  // namespace p3d::render
