// The column loops built for AVX-512 VBMI: this file alone is (engine/CMakeLists.txt),
// and the canvas calls it only where vector_columns() says the processor has it.
// GCC 12's AVX-512 shifts start from a self-initialised "undefined" register, which
// -Wmaybe-uninitialized reports (GCC bug 105593).
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include <immintrin.h>

#include <algorithm>

#include "engine/render/column_major.h"

namespace p3d::render {

namespace {

inline __mmask64 first_bytes(int n) { return n >= 64 ? ~__mmask64(0) : (__mmask64(1) << n) - 1; }

// The first n bytes (at most 64) of a register's load: the bytes past them are not read.
inline __m512i load_first(const uint8_t* p, int n) { return _mm512_maskz_loadu_epi8(first_bytes(n), p); }

// 64 look-ups in a 256-byte table held in four registers: bit 7 picks the pair.
inline __m512i look_up_256(const __m512i table[4], __m512i index) {
  const __m512i low = _mm512_permutex2var_epi8(table[0], index, table[1]);
  const __m512i high = _mm512_permutex2var_epi8(table[2], index, table[3]);
  return _mm512_mask_blend_epi8(_mm512_movepi8_mask(index), low, high);
}

// A 256-byte table (a light map) in four registers.
struct Table256 {
  __m512i part[4];
  explicit Table256(const uint8_t* table) {
    for (int i = 0; i < 4; ++i) part[i] = _mm512_loadu_si512(table + 64 * i);
  }
};

// A texture column of up to 256 texels already under its light, in registers:
// texels[r] = light[source[r]].
struct LitColumn {
  __m512i texels[4];
  bool wide;  // more than 128 texels: the look-up reads bit 7 too

  LitColumn(const uint8_t* source, int count, const uint8_t* light) : wide(count > 128) {
    const Table256 light_table(light);
    for (int i = 0; i < (wide ? 4 : 2); ++i)  // past the column's texels: never looked up
      texels[i] = count > 64 * i ? look_up_256(light_table.part, load_first(source + 64 * i, count - 64 * i))
                                 : _mm512_setzero_si512();
  }
  // 64 pixels from their texel rows (below the count).
  __m512i operator()(__m512i rows) const {
    return wide ? look_up_256(texels, rows) : _mm512_permutex2var_epi8(texels[0], rows, texels[1]);  // bit 7 unread
  }
};

}  // namespace

void wall_column_vbmi(uint8_t* out, int count, uint32_t v, uint32_t step, int rows_log2, const uint8_t* source,
                      const uint8_t* light) {
  const LitColumn column(source, 1 << rows_log2, light);
  // Pixel i's v in lane i % 16 of register i / 16; its row is the v's byte 2 (bits 16
  // to 23), gathered from the four registers into one.
  const __m512i lanes = _mm512_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15);
  const __m512i steps = _mm512_set1_epi32(int(step)), step16 = _mm512_set1_epi32(int(step * 16));
  const __m512i step64 = _mm512_set1_epi32(int(step * 64));
  __m512i vs[4];
  vs[0] = _mm512_add_epi32(_mm512_set1_epi32(int(v)), _mm512_mullo_epi32(lanes, steps));
  for (int i = 1; i < 4; ++i) vs[i] = _mm512_add_epi32(vs[i - 1], step16);
  alignas(64) static constexpr uint8_t kByte2[64] = {
      2,  6,  10, 14, 18, 22, 26, 30, 34, 38, 42, 46, 50, 54, 58, 62, 66, 70, 74, 78, 82, 86,
      90, 94, 98, 102, 106, 110, 114, 118, 122, 126, 2, 6, 10, 14, 18, 22, 26, 30, 34, 38, 42, 46,
      50, 54, 58, 62, 66, 70, 74, 78, 82, 86, 90, 94, 98, 102, 106, 110, 114, 118, 122, 126};
  const __m512i row_bytes = _mm512_load_si512(kByte2);
  const __m512i row_mask = _mm512_set1_epi8(char((1 << rows_log2) - 1));
  auto pixels = [&] {
    const __m512i low = _mm512_permutex2var_epi8(vs[0], row_bytes, vs[1]);
    const __m512i high = _mm512_permutex2var_epi8(vs[2], row_bytes, vs[3]);
    __m512i row = _mm512_mask_blend_epi8(~__mmask64(0) << 32, low, high);
    if (rows_log2 < 7) row = _mm512_and_si512(row, row_mask);
    return column(row);
  };
  int i = 0;
  for (; i + 64 <= count; i += 64) {
    _mm512_storeu_si512(out + i, pixels());
    for (__m512i& x : vs) x = _mm512_add_epi32(x, step64);
  }
  if (i < count) _mm512_mask_storeu_epi8(out + i, first_bytes(count - i), pixels());
}

void tabled_column_vbmi(uint8_t* out, int count, const uint8_t* rows, const uint8_t* source, int texels,
                        const uint8_t* light) {
  const LitColumn column(source, texels, light);
  int i = 0;
  for (; i + 64 <= count; i += 64) _mm512_storeu_si512(out + i, column(_mm512_loadu_si512(rows + i)));
  if (i < count) _mm512_mask_storeu_epi8(out + i, first_bytes(count - i), column(load_first(rows + i, count - i)));
}

void flat_row_vbmi(uint8_t* out, int n, RowCoordinate u, RowCoordinate v, const uint8_t* indices,
                   const uint8_t* light) {
  const Table256 light_table(light);
  const __m512i lanes = _mm512_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15);
  __m512i us = _mm512_add_epi32(_mm512_set1_epi32(int(u.value)), _mm512_mullo_epi32(lanes, _mm512_set1_epi32(int(u.step))));
  __m512i vs = _mm512_add_epi32(_mm512_set1_epi32(int(v.value)), _mm512_mullo_epi32(lanes, _mm512_set1_epi32(int(v.step))));
  const __m512i du = _mm512_set1_epi32(int(16 * u.step)), dv = _mm512_set1_epi32(int(16 * v.step));
  const __m128i u_shift = _mm_cvtsi32_si128(int(u.shift)), v_shift = _mm_cvtsi32_si128(int(v.shift));
  const __m512i u_mask = _mm512_set1_epi32(int(u.mask)), v_mask = _mm512_set1_epi32(int(v.mask));
  alignas(64) uint32_t at[64];
  alignas(64) uint8_t texels[64];
  for (int i = 0; i < n; i += 64) {
    const int count = std::min(64, n - i), groups = (count + 15) / 16;
    for (int g = 0; g < groups; ++g) {
      const __m512i index = _mm512_or_si512(_mm512_and_si512(_mm512_srl_epi32(us, u_shift), u_mask),
                                            _mm512_and_si512(_mm512_srl_epi32(vs, v_shift), v_mask));
      _mm512_store_si512(at + 16 * g, index);
      us = _mm512_add_epi32(us, du), vs = _mm512_add_epi32(vs, dv);
    }
    for (int k = 0; k < groups * 16; k += 4) {  // past count: texels of the flat, never stored
      texels[k] = indices[at[k]], texels[k + 1] = indices[at[k + 1]];
      texels[k + 2] = indices[at[k + 2]], texels[k + 3] = indices[at[k + 3]];
    }
    _mm512_mask_storeu_epi8(out + i, first_bytes(count), look_up_256(light_table.part, _mm512_load_si512(texels)));
  }
}

}  // namespace p3d::render
