// PNG's row filters: a byte at a time (short rows, processors without SSE2), else
// sixteen (SSE2) or thirty-two (AVX2, png_filters_avx2.cpp) at a time. Every width costs
// the same sample (the first sixteen bytes of every 32 after a pixel's first), so it
// chooses the same filters and writes the same bytes; Paeth alone (paeth_row) the same.
#include "engine/image/png_filters.h"

#include <algorithm>
#include <cstdlib>

#include "engine/util/cpu.h"

#ifdef __SSE2__
#include <emmintrin.h>

#include "engine/image/png_filter_lanes.h"
#endif

namespace p3d::image {

#ifdef P3D_AVX2_FILTERS
// png_filters_avx2.cpp, built for AVX2: called only where the processor has it.
namespace avx2 {
size_t cost_steps(const uint8_t* row, const uint8_t* up, size_t channels, size_t stride, size_t x, uint32_t* cost,
                  uint8_t* out);
void apply(int type, const uint8_t* row, const uint8_t* up, size_t channels, size_t stride, uint8_t* out);
}  // namespace avx2
#endif

namespace {

// A filtered byte's weight in libpng's heuristic: its magnitude as a signed difference.
inline uint32_t magnitude(uint8_t v) { return v < 128 ? v : 256u - v; }

// PNG's Paeth predictor.
inline uint8_t paeth(int a, int b, int c) {  // a: left, b: up, c: up-left
  const int pa = std::abs(b - c), pb = std::abs(a - c), pc = std::abs(a + b - 2 * c);
  return uint8_t(pa <= pb && pa <= pc ? a : pb <= pc ? b : c);
}

// PNG's five filters of one byte, given its left (a), up (b) and up-left (c) neighbours.
inline uint8_t filtered_byte(int type, int r, int a, int b, int c) {
  switch (type) {
    case 0: return uint8_t(r);
    case 1: return uint8_t(r - a);
    case 2: return uint8_t(r - b);
    case 3: return uint8_t(r - ((a + b) >> 1));
    default: return uint8_t(r - paeth(a, b, c));
  }
}

// Byte x of a row's neighbours: left, up and up-left (0 off the row's start).
struct Neighbours {
  int a, b, c;
};
inline Neighbours neighbours(const uint8_t* row, const uint8_t* up, size_t channels, size_t x) {
  return x < channels ? Neighbours{0, up[x], 0} : Neighbours{row[x - channels], up[x], up[x - channels]};
}

#ifdef __SSE2__
struct Sse2 {
  using V = __m128i;
  static constexpr size_t kBytes = 16;
  static V load(const uint8_t* p) { return _mm_loadu_si128(reinterpret_cast<const __m128i*>(p)); }
  static void store(uint8_t* p, V v) { _mm_storeu_si128(reinterpret_cast<__m128i*>(p), v); }
  static V zero() { return _mm_setzero_si128(); }
  static V set1(uint8_t v) { return _mm_set1_epi8(char(v)); }
  static V sub(V x, V y) { return _mm_sub_epi8(x, y); }
  static V subs(V x, V y) { return _mm_subs_epu8(x, y); }
  static V adds(V x, V y) { return _mm_adds_epu8(x, y); }
  static V avg(V x, V y) { return _mm_avg_epu8(x, y); }
  static V min(V x, V y) { return _mm_min_epu8(x, y); }
  static V eq(V x, V y) { return _mm_cmpeq_epi8(x, y); }
  static V bit_and(V x, V y) { return _mm_and_si128(x, y); }
  static V select(V mask, V yes, V no) { return _mm_or_si128(_mm_and_si128(mask, yes), _mm_andnot_si128(mask, no)); }
  static V bit_or(V x, V y) { return _mm_or_si128(x, y); }
  static V bit_xor(V x, V y) { return _mm_xor_si128(x, y); }
  static V sad(V x, V y) { return _mm_sad_epu8(x, y); }
  static V add64(V x, V y) { return _mm_add_epi64(x, y); }
  static V load_spread(const uint8_t* p) { return load(p); }  // a vector holds one sixteen
  static void store_spread(uint8_t* p, V v) { store(p, v); }
  static uint32_t total(V sums) {
    return uint32_t(_mm_cvtsi128_si32(sums) + _mm_cvtsi128_si32(_mm_srli_si128(sums, 8)));
  }
};

// The costs over the sample of bytes [channels, stride) (stride >= channels + 16),
// Paeth's bytes written to out on the way: it wins most rows of a frame (seven in ten
// at 1920x1080), and a row it wins needs no second pass.
void cost_row(const uint8_t* row, const uint8_t* up, size_t channels, size_t stride, uint32_t* cost, uint8_t* out,
              bool avx2) {
  size_t x = channels;
#ifdef P3D_AVX2_FILTERS
  if (avx2) x = avx2::cost_steps(row, up, channels, stride, x, cost, out);
#else
  (void)avx2;
#endif
  x = lanes::cost_steps<Sse2>(row, up, channels, stride, x, cost, out);
  if (x + 16 <= stride) {  // a last sampled sixteen
    lanes::Costs<Sse2> last;
    Sse2::store(out + x, last.add(lanes::Pixels<Sse2>::at(row, up, channels, x)));
    last.add_into(cost);
    x += 16;
  }
  if (x < stride)  // the last bytes' Paeth, overlapping the ones before
    Sse2::store(out + stride - 16, lanes::Pixels<Sse2>::at(row, up, channels, stride - 16).filtered(kPaethFilter));
}
#endif

}  // namespace

FilterLanes widest_filter_lanes() {
#ifdef P3D_AVX2_FILTERS
  if (has_avx2()) return FilterLanes::kThirtyTwo;
#endif
#ifdef __SSE2__
  return FilterLanes::kSixteen;
#else
  return FilterLanes::kOne;
#endif
}

// The filter is the one whose bytes' magnitudes sum least (the first of equals); only
// its bytes are written. A row of sixteen bytes or more after its first pixel is costed
// over a sample, the first sixteen of every 32, at every width (so a PNG is the same
// bytes on processors without SSE2 too). The sample takes half the work and chooses
// nearly as well: a Doom frame's PNG 9% faster to make and 0.3-1% bigger (a quarter of
// the row: 1-2% bigger for 5% more).
void filter_row(const uint8_t* row, const uint8_t* up, size_t stride, size_t channels, uint8_t* out,
                FilterLanes lanes) {
  uint32_t cost[5] = {0, 0, 0, 0, 0};  // a row is at most 2^31 / 128 bytes (PNG's width limit times 4)
  const auto cost_bytes = [&](size_t from, size_t to) {
    for (size_t x = from; x < to; ++x) {
      const auto [a, b, c] = neighbours(row, up, channels, x);
      for (int type = 0; type < 5; ++type) cost[type] += magnitude(filtered_byte(type, row[x], a, b, c));
    }
  };
  const bool sampled = stride >= channels + 16;
  bool vector = false, widest = false;
#ifdef __SSE2__
  vector = sampled && lanes != FilterLanes::kOne;
  widest = vector && lanes == FilterLanes::kThirtyTwo && stride >= channels + 32;
#endif
  uint8_t* bytes = out + 1;
  if (!sampled) {
    cost_bytes(0, stride);
  } else {
    cost_bytes(0, channels);  // a pixel's first bytes have no left neighbour
#ifdef __SSE2__
    if (vector) cost_row(row, up, channels, stride, cost, bytes, widest);
#endif
    if (!vector)
      for (size_t x = channels; x + 16 <= stride; x += 32) cost_bytes(x, x + 16);
  }
  const int best = int(std::min_element(cost, cost + 5) - cost);
  out[0] = uint8_t(best);
  const size_t one_at_a_time = vector ? channels : stride;
  for (size_t x = 0; x < one_at_a_time; ++x) {
    const auto [a, b, c] = neighbours(row, up, channels, x);
    bytes[x] = filtered_byte(best, row[x], a, b, c);
  }
  if (!vector || best == kPaethFilter) return;  // Paeth's bytes are there
#ifdef P3D_AVX2_FILTERS
  if (widest) return avx2::apply(best, row, up, channels, stride, bytes);
#endif
#ifdef __SSE2__
  lanes::apply<Sse2>(best, row, up, channels, stride, bytes);
#endif
}

void paeth_row(const uint8_t* row, const uint8_t* up, size_t stride, size_t channels, uint8_t* out,
               FilterLanes lanes) {
  out[0] = uint8_t(kPaethFilter);
  uint8_t* bytes = out + 1;
  bool vector = false, widest = false;
#ifdef __SSE2__
  vector = lanes != FilterLanes::kOne && stride >= channels + 16;
  widest = vector && lanes == FilterLanes::kThirtyTwo && stride >= channels + 32;
#endif
  for (size_t x = 0; x < (vector ? channels : stride); ++x) {  // a pixel's first bytes have no left neighbour
    const auto [a, b, c] = neighbours(row, up, channels, x);
    bytes[x] = filtered_byte(kPaethFilter, row[x], a, b, c);
  }
  if (!vector) return;
#ifdef P3D_AVX2_FILTERS
  if (widest) return avx2::apply(kPaethFilter, row, up, channels, stride, bytes);
#else
  (void)widest;
#endif
#ifdef __SSE2__
  lanes::apply<Sse2>(kPaethFilter, row, up, channels, stride, bytes);
#endif
}

}  // namespace p3d::image
