// PNG's row filters thirty-two bytes at a time: this file alone is built for AVX2
// (engine/CMakeLists.txt), and png_filters.cpp calls it only where the processor has
// AVX2. It instantiates the loops for its own operations only, so nothing built here
// stands in for the SSE2 code.
#include <immintrin.h>

#include "engine/image/png_filter_lanes.h"

namespace p3d::image::avx2 {

namespace {

struct Avx2 {
  using V = __m256i;
  static constexpr size_t kBytes = 32;
  static V load(const uint8_t* p) { return _mm256_loadu_si256(reinterpret_cast<const __m256i*>(p)); }
  static void store(uint8_t* p, V v) { _mm256_storeu_si256(reinterpret_cast<__m256i*>(p), v); }
  static V zero() { return _mm256_setzero_si256(); }
  static V set1(uint8_t v) { return _mm256_set1_epi8(char(v)); }
  static V sub(V x, V y) { return _mm256_sub_epi8(x, y); }
  static V subs(V x, V y) { return _mm256_subs_epu8(x, y); }
  static V adds(V x, V y) { return _mm256_adds_epu8(x, y); }
  static V avg(V x, V y) { return _mm256_avg_epu8(x, y); }
  static V min(V x, V y) { return _mm256_min_epu8(x, y); }
  static V eq(V x, V y) { return _mm256_cmpeq_epi8(x, y); }
  static V bit_and(V x, V y) { return _mm256_and_si256(x, y); }
  static V select(V mask, V yes, V no) { return _mm256_blendv_epi8(no, yes, mask); }  // mask bytes all 0 or all 1
  static V bit_or(V x, V y) { return _mm256_or_si256(x, y); }
  static V bit_xor(V x, V y) { return _mm256_xor_si256(x, y); }
  static V sad(V x, V y) { return _mm256_sad_epu8(x, y); }
  static V add64(V x, V y) { return _mm256_add_epi64(x, y); }
  // Two sixteens 32 bytes apart in one vector: two steps' samples, or their other halves.
  static V load_spread(const uint8_t* p) {
    return _mm256_inserti128_si256(_mm256_castsi128_si256(_mm_loadu_si128(reinterpret_cast<const __m128i*>(p))),
                                   _mm_loadu_si128(reinterpret_cast<const __m128i*>(p + 32)), 1);
  }
  static void store_spread(uint8_t* p, V v) {
    _mm_storeu_si128(reinterpret_cast<__m128i*>(p), _mm256_castsi256_si128(v));
    _mm_storeu_si128(reinterpret_cast<__m128i*>(p + 32), _mm256_extracti128_si256(v, 1));
  }
  static uint32_t total(V sums) {
    const __m128i s = _mm_add_epi64(_mm256_castsi256_si128(sums), _mm256_extracti128_si256(sums, 1));
    return uint32_t(_mm_cvtsi128_si32(s) + _mm_cvtsi128_si32(_mm_srli_si128(s, 8)));
  }
};

}  // namespace

size_t cost_steps(const uint8_t* row, const uint8_t* up, size_t channels, size_t stride, size_t x, uint32_t* cost,
                  uint8_t* out) {
  return lanes::cost_steps<Avx2>(row, up, channels, stride, x, cost, out);
}

void apply(int type, const uint8_t* row, const uint8_t* up, size_t channels, size_t stride, uint8_t* out) {
  lanes::apply<Avx2>(type, row, up, channels, stride, out);
}

}  // namespace p3d::image::avx2
