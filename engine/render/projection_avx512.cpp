// WallProjector::hit for eight columns at a time with AVX-512: this file alone is built
// for it (engine/CMakeLists.txt), and the walk calls it only where vector_projection()
// says the processor has it. The same IEEE operations in the same order as the scalar
// hit, lane by lane (no fused multiply-adds: -ffp-contract=off), so the same hits.
// GCC 12's AVX-512 conversions start from a self-initialised "undefined" register, which
// -Wmaybe-uninitialized reports (GCC bug 105593).
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include <immintrin.h>

#include <algorithm>
#include <bit>

#include "engine/render/view.h"

namespace p3d::render {

size_t open_column_hits_avx512(const WallProjector& p, const FragmentSpan& span, const uint64_t* closed, int x0, int x1,
                               RayHits out) {
  const __m512d side0_a = _mm512_set1_pd(p.side0[0]), side0_b = _mm512_set1_pd(p.side0[1]);
  const __m512d dx_a = _mm512_set1_pd(p.side_dx[0]), dx_b = _mm512_set1_pd(p.side_dx[1]);
  const __m512d end0 = _mm512_set1_pd(p.end_depth[0]), end1 = _mm512_set1_pd(p.end_depth[1]);
  const __m512d zero = _mm512_setzero_pd(), half = _mm512_set1_pd(0.5), one = _mm512_set1_pd(1.0);
  const __m512d near = _mm512_set1_pd(kNearDepth), t0 = _mm512_set1_pd(span.t0), t1 = _mm512_set1_pd(span.t1);
  const __m256i lanes = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
  size_t n = 0;
  for (int w = x0 >> 6; w <= x1 >> 6; ++w) {
    const int lo = std::max(x0 - (w << 6), 0), hi = std::min(x1 - (w << 6), 63);
    uint64_t open = ~closed[w] & (~uint64_t{0} >> (63 - hi)) & (~uint64_t{0} << lo);
    for (; open; open &= ~(uint64_t{0xFF} << (std::countr_zero(open) & ~7))) {
      const int group = std::countr_zero(open) & ~7;  // the eight columns from base
      const int base = (w << 6) + group;
      const __mmask8 lanes_open = __mmask8(open >> group);
      const __m256i xs = _mm256_add_epi32(_mm256_set1_epi32(base), lanes);
      const __m512d at = p.lateral ? _mm512_maskz_loadu_pd(lanes_open, p.lateral + base) : _mm512_cvtepi32_pd(xs);
      const __m512d s0 = _mm512_add_pd(side0_a, _mm512_mul_pd(dx_a, at));
      const __m512d s1 = _mm512_add_pd(side0_b, _mm512_mul_pd(dx_b, at));
      const __mmask8 apart = _mm512_cmp_pd_mask(s0, zero, _CMP_LT_OQ) ^ _mm512_cmp_pd_mask(s1, zero, _CMP_LT_OQ);
      const __m512d t = _mm512_div_pd(s0, _mm512_sub_pd(s0, s1));
      const __m512d span_depth = _mm512_sub_pd(end1, end0);
      const __m512d from_start = _mm512_add_pd(end0, _mm512_mul_pd(span_depth, t));
      const __m512d from_end = _mm512_sub_pd(end1, _mm512_mul_pd(span_depth, _mm512_sub_pd(one, t)));
      const __m512d depth = _mm512_mask_blend_pd(_mm512_cmp_pd_mask(t, half, _CMP_LE_OQ), from_end, from_start);
      const __mmask8 below_end =
          span.t1_closed ? _mm512_cmp_pd_mask(t, t1, _CMP_LE_OQ) : _mm512_cmp_pd_mask(t, t1, _CMP_LT_OQ);
      const __mmask8 in_span = _mm512_cmp_pd_mask(t, t0, _CMP_GE_OQ) & below_end;
      const __mmask8 hit = lanes_open & apart & _mm512_cmp_pd_mask(depth, near, _CMP_GT_OQ) & in_span;
      if (!hit) continue;
      _mm256_mask_compressstoreu_epi32(out.x + n, hit, xs);
      _mm512_mask_compressstoreu_pd(out.depth + n, hit, depth);
      _mm512_mask_compressstoreu_pd(out.t + n, hit, t);
      n += size_t(std::popcount(unsigned(hit)));
    }
  }
  return n;
}

}  // namespace p3d::render
