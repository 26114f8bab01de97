// The walk's projection of a wall onto the screen eight columns at a time with AVX-512:
// which open columns its rays hit (WallProjector::hit), and under Doom's rules a run's
// scales and edge rows. This file alone is built for it (engine/CMakeLists.txt), and the
// walk calls it only where vector_projection() says the processor has it. The same
// operations in the same order as the scalar code, lane by lane (no fused
// multiply-adds: -ffp-contract=off), so the same results to the bit. It calls no inline
// function of the engine's headers: one built here could stand in for the generic one.
// GCC 12's AVX-512 conversions start from a self-initialised "undefined" register, which
// -Wmaybe-uninitialized reports (GCC bug 105593).
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include <immintrin.h>

#include <algorithm>
#include <bit>
#include <climits>

#include "engine/render/view.h"

namespace p3d::render {

namespace {

// The first n of eight lanes (all of them from eight on).
inline __mmask8 first_lanes(size_t n) { return n >= 8 ? __mmask8(0xFF) : __mmask8((1u << n) - 1); }

// A 64-bit value's low 32 bits, sign-extended: the Fixed it is cast to.
inline __m512i as_fixed(__m512i v) { return _mm512_cvtepi32_epi64(_mm512_cvtepi64_epi32(v)); }

}  // namespace

size_t open_column_hits_avx512(const WallProjector& p, const FragmentSpan& span, const uint64_t* closed, int x0, int x1,
                               RayHits out) {
  const __m512d side0_a = _mm512_set1_pd(p.side0[0]), side0_b = _mm512_set1_pd(p.side0[1]);
  const __m512d dx_a = _mm512_set1_pd(p.side_dx[0]), dx_b = _mm512_set1_pd(p.side_dx[1]);
  const __m512d end0 = _mm512_set1_pd(p.end_depth[0]), end1 = _mm512_set1_pd(p.end_depth[1]);
  const __m512d span_depth = _mm512_sub_pd(end1, end0);
  const __m512d zero = _mm512_setzero_pd(), half = _mm512_set1_pd(0.5), one = _mm512_set1_pd(1.0);
  const __m512d near = _mm512_set1_pd(kNearDepth), t0 = _mm512_set1_pd(span.t0), t1 = _mm512_set1_pd(span.t1);
  const __m256i lanes = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
  size_t n = 0;
  for (int w = x0 >> 6; w <= x1 >> 6; ++w) {
    const int lo = std::max(x0 - (w << 6), 0), hi = std::min(x1 - (w << 6), 63);  // ColumnMask::range_bits
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

void doom_scales_avx512(const int32_t* xs, size_t n, const doom::SegSines& sines, doom::Fixed projection,
                        doom::Fixed distance, doom::Fixed max_scale, doom::Fixed* out) {
  const __m256i seg_angle = _mm256_set1_epi32(int(sines.seg_angle));
  const __m512i projections = _mm512_set1_epi64(projection), distances = _mm512_set1_epi64(distance);
  const __m512i most = _mm512_set1_epi64(max_scale), least = _mm512_set1_epi64(256);
  const __m512i int_min = _mm512_set1_epi64(INT32_MIN), int_max = _mm512_set1_epi64(INT32_MAX);
  const __m512i zero = _mm512_setzero_si512();
  for (size_t i = 0; i < n; i += 8) {
    const __mmask8 lanes = first_lanes(n - i);
    const __m256i x = _mm256_maskz_loadu_epi32(lanes, xs + i);
    // The lanes' entries of a table by column: eight neighbouring columns' (the
    // commonest) loaded rather than gathered.
    const bool neighbours = lanes == 0xFF && xs[i + 7] - xs[i] == 7;
    auto by_column = [&](const auto* table) {
      return neighbours ? _mm256_loadu_si256(reinterpret_cast<const __m256i*>(table + xs[i]))
                        : _mm256_mmask_i32gather_epi32(x, lanes, x, table, 4);
    };
    const __m256i column_angle = by_column(sines.column_angle), view_sine = by_column(sines.view_sine);
    const __m256i fine = _mm256_srli_epi32(_mm256_add_epi32(seg_angle, column_angle), 19);  // kAngleToFineShift
    const __m512i sinea = _mm512_cvtepi32_epi64(view_sine);
    const __m512i sineb = _mm512_cvtepi32_epi64(_mm256_mmask_i32gather_epi32(x, lanes, fine, sines.fine_sine, 4));
    const __m512i num = as_fixed(_mm512_srai_epi64(_mm512_mullo_epi64(projections, sineb), 16));
    const __m512i den = as_fixed(_mm512_srai_epi64(_mm512_mullo_epi64(distances, sinea), 16));
    const __mmask8 in_front = _mm512_cmpgt_epi64_mask(den, _mm512_srai_epi64(num, 16));
    // fixed_div: saturated where |num| >> 14 >= |den|, else (num << 16) / den truncated.
    const __mmask8 saturated =
        _mm512_cmpge_epi64_mask(_mm512_srai_epi64(_mm512_abs_epi64(num), 14), _mm512_abs_epi64(den));
    const __mmask8 negative = _mm512_cmplt_epi64_mask(_mm512_xor_si512(num, den), zero);
    // The quotient in doubles, truncated, is the integer one: n = num << 16 and den are
    // exact (|n| < 2^47), the division is correctly rounded, so its error is below
    // |n| / |den| * 2^-53 < 1 / |den|, and a quotient that is not a whole number lies at
    // least 1 / |den| from one. (A saturated lane's division may be by zero: unused.)
    const __m512d quotient = _mm512_div_pd(_mm512_cvtepi64_pd(_mm512_slli_epi64(num, 16)), _mm512_cvtepi64_pd(den));
    const __m512i q = _mm512_cvttpd_epi64(quotient);
    const __m512i saturation = _mm512_mask_blend_epi64(negative, int_max, int_min);
    __m512i scale = _mm512_mask_blend_epi64(saturated, as_fixed(q), saturation);
    // Both clamps judged on the quotient, max_scale's applied last: it wins, as in scale_at.
    const __mmask8 above = _mm512_cmpgt_epi64_mask(scale, most), below = _mm512_cmplt_epi64_mask(scale, least);
    scale = _mm512_mask_blend_epi64(below, scale, least);
    scale = _mm512_mask_blend_epi64(above | ~in_front, scale, most);
    _mm256_mask_storeu_epi32(out + i, lanes, _mm512_cvtepi64_epi32(scale));
  }
}

namespace {

// doom_edge_rows_avx512 for Count edges (and Crispy's rules or not): their heights and
// roundings kept in registers from group to group.
template <int Count, bool Crispy>
void edge_rows(const doom::Fixed* scales, size_t n, const WallEdges& edges) {
  const __m512i centers = _mm512_set1_epi64(edges.center);
  const __m512i lowest = _mm512_set1_epi64(INT_MIN / 2), highest = _mm512_set1_epi64(INT_MAX / 2);
  const __m128i shift = _mm_cvtsi32_si128(edges.bits);
  __m512i worlds[Count], rounds[Count];
  for (int e = 0; e < Count; ++e)
    worlds[e] = _mm512_set1_epi64(edges.world[e]), rounds[e] = _mm512_set1_epi64(edges.round[e]);
  for (size_t i = 0; i < n; i += 8) {
    const __mmask8 lanes = first_lanes(n - i);
    const __m512i scale = _mm512_cvtepi32_epi64(_mm256_maskz_loadu_epi32(lanes, scales + i));
    for (int e = 0; e < Count; ++e) {
      const __m512i product = _mm512_srai_epi64(_mm512_mul_epi32(worlds[e], scale), 16);  // signed 32 x 32 bits
      const __m512i edge = Crispy ? _mm512_sub_epi64(centers, product)
                                  : as_fixed(_mm512_sub_epi64(as_fixed(centers), as_fixed(product)));
      const __m512i row = _mm512_sra_epi64(_mm512_add_epi64(edge, rounds[e]), shift);
      const __m512i clamped = _mm512_max_epi64(_mm512_min_epi64(row, highest), lowest);
      _mm256_mask_storeu_epi32(edges.rows[e] + i, lanes, _mm512_cvtepi64_epi32(clamped));
    }
  }
}

template <bool Crispy>
void edge_rows(const doom::Fixed* scales, size_t n, const WallEdges& edges) {
  switch (edges.count) {
    case 1: return edge_rows<1, Crispy>(scales, n, edges);
    case 2: return edge_rows<2, Crispy>(scales, n, edges);
    case 3: return edge_rows<3, Crispy>(scales, n, edges);
    case 4: return edge_rows<4, Crispy>(scales, n, edges);
    default: return;  // none
  }
}

}  // namespace

void doom_edge_rows_avx512(const doom::Fixed* scales, size_t n, const WallEdges& edges) {
  if (edges.crispy) return edge_rows<true>(scales, n, edges);
  edge_rows<false>(scales, n, edges);
}

}  // namespace p3d::render
