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

// A 256-byte table in four registers, looked up 64 bytes at a time: bit 7 of an index
// picks the pair. Named registers rather than an array: GCC kept an array's on the stack.
struct Table256 {
  __m512i a, b, c, d;
  static Table256 load(const uint8_t* table) {
    return {_mm512_loadu_si512(table), _mm512_loadu_si512(table + 64), _mm512_loadu_si512(table + 128),
            _mm512_loadu_si512(table + 192)};
  }
  __m512i operator()(__m512i index) const {
    const __m512i low = _mm512_permutex2var_epi8(a, index, b), high = _mm512_permutex2var_epi8(c, index, d);
    return _mm512_mask_blend_epi8(_mm512_movepi8_mask(index), low, high);
  }
};

// A texture column of up to 256 texels already under its light, in registers:
// texels(r) = light[source[r]].
struct LitColumn {
  Table256 texels;
  bool wide;  // more than 128 texels: the look-up reads bit 7 too

  LitColumn(const uint8_t* source, int count, const uint8_t* light) : wide(count > 128) {
    const Table256 light_table = Table256::load(light);
    auto part = [&](int i) {  // past the column's texels: zeros, never looked up
      return count > 64 * i ? light_table(load_first(source + 64 * i, count - 64 * i)) : _mm512_setzero_si512();
    };
    texels.a = part(0), texels.b = part(1);
    texels.c = wide ? part(2) : _mm512_setzero_si512(), texels.d = wide ? part(3) : _mm512_setzero_si512();
  }
  // 64 pixels from their texel rows (below the count).
  __m512i operator()(__m512i rows) const {
    return wide ? texels(rows) : _mm512_permutex2var_epi8(texels.a, rows, texels.b);  // bit 7 unread
  }
};

// Byte 2 of each 32-bit lane of two registers (a texel row, bits 16 to 23 of a 16.16
// coordinate): the permute that gathers 64 pixels' rows from four registers of v.
alignas(64) constexpr uint8_t kByte2[64] = {
    2,  6,  10, 14, 18, 22, 26, 30, 34, 38, 42, 46, 50, 54, 58, 62, 66, 70, 74, 78, 82, 86,
    90, 94, 98, 102, 106, 110, 114, 118, 122, 126, 2, 6, 10, 14, 18, 22, 26, 30, 34, 38, 42, 46,
    50, 54, 58, 62, 66, 70, 74, 78, 82, 86, 90, 94, 98, 102, 106, 110, 114, 118, 122, 126};

// Each 32-bit lane its own index.
inline __m512i lanes16() { return _mm512_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15); }

// count adjacent bytes of a wall column from its 16.16 coordinates: pixel i's in lane
// i % 16 of vs[i / 16]. Each 64 pixels' texel rows are the coordinates' bytes 2 (bits
// 16 to 23), gathered from the four registers into one, passed through `rows` and
// looked up by `column`; then `advance` moves every register on by 64 pixels.
template <typename Column, typename Rows, typename Advance>
inline void stepped_column(uint8_t* out, int count, const Column& column, __m512i (&vs)[4], Rows rows,
                           Advance advance) {
  const __m512i row_bytes = _mm512_load_si512(kByte2);
  auto pixels = [&] {
    const __m512i low = _mm512_permutex2var_epi8(vs[0], row_bytes, vs[1]);
    const __m512i high = _mm512_permutex2var_epi8(vs[2], row_bytes, vs[3]);
    return column(rows(_mm512_mask_blend_epi8(~__mmask64(0) << 32, low, high)));
  };
  int i = 0;
  for (; i + 64 <= count; i += 64) {
    _mm512_storeu_si512(out + i, pixels());
    for (__m512i& x : vs) x = advance(x);
  }
  if (i < count) _mm512_mask_storeu_epi8(out + i, first_bytes(count - i), pixels());
}

// n rows (at most 16) of 64 columns into the frame's rows: register i holds columns i,
// 16 + i, 32 + i and 48 + i in its four 128-bit lanes; the 16 x 16 interleave, done in
// every lane at once, leaves row j's 64 bytes in register j. Out of line: inlined in
// its loop, GCC kept the 64 load addresses apart, on the stack.
[[gnu::noinline]] void rows_of_64_columns(const uint8_t* columns, size_t column_stride, uint8_t* rows, size_t row_pitch,
                                         int n) {
  const __mmask64 first = first_bytes(n);  // of each lane: nothing read past the column
  __m512i r[16];
  const size_t lane1 = 16 * column_stride, lane2 = 2 * lane1, lane3 = 3 * lane1;
  const uint8_t* c = columns;
#pragma GCC unroll 16
  for (int i = 0; i < 16; ++i, c += column_stride) {  // lane L loaded to its own bytes, 16 L on
    r[i] = _mm512_maskz_loadu_epi8(first, c);
    r[i] = _mm512_mask_loadu_epi8(r[i], first << 16, c + lane1 - 16);
    r[i] = _mm512_mask_loadu_epi8(r[i], first << 32, c + lane2 - 32);
    r[i] = _mm512_mask_loadu_epi8(r[i], first << 48, c + lane3 - 48);
  }
  interleave_16x16(r, [](__m512i a, __m512i b) { return _mm512_unpacklo_epi8(a, b); },
                   [](__m512i a, __m512i b) { return _mm512_unpackhi_epi8(a, b); });
  if (n == 16) {
#pragma GCC unroll 16
    for (int j = 0; j < 16; ++j, rows += row_pitch) _mm512_storeu_si512(rows, r[j]);
  } else {
    for (int j = 0; j < n; ++j, rows += row_pitch) _mm512_storeu_si512(rows, r[j]);
  }
}

}  // namespace

namespace {

// wall_column_vbmi for a column of 128 texels (Full) or of 64 or fewer: each pixel's
// texel looked up in the column's one or two registers, then lit, where a longer column
// lights its texels first. A column of a pixel or two per texel row lights fewer bytes
// this way, and skips lighting the texels it never shows.
template <bool Full>
void lit_after_lookup(uint8_t* out, int count, uint32_t v, uint32_t step, int rows_log2, const uint8_t* source,
                      const uint8_t* light) {
  __m512i vs[4];
  vs[0] = _mm512_add_epi32(_mm512_set1_epi32(int(v)), _mm512_mullo_epi32(lanes16(), _mm512_set1_epi32(int(step))));
  const __m512i step16 = _mm512_set1_epi32(int(step * 16)), step64 = _mm512_set1_epi32(int(step * 64));
  for (int i = 1; i < 4; ++i) vs[i] = _mm512_add_epi32(vs[i - 1], step16);
  const __m512i low = Full ? _mm512_loadu_si512(source) : load_first(source, 1 << rows_log2);
  const __m512i high = Full ? _mm512_loadu_si512(source + 64) : _mm512_setzero_si512();
  const __m512i row_mask = _mm512_set1_epi8(char((1 << rows_log2) - 1));
  const Table256 lit = Table256::load(light);
  auto masked = [&](__m512i texel_rows) { return Full ? texel_rows : _mm512_and_si512(texel_rows, row_mask); };
  auto lit_texels = [&](__m512i rows) {
    return lit(Full ? _mm512_permutex2var_epi8(low, rows, high) : _mm512_permutexvar_epi8(rows, low));
  };
  stepped_column(out, count, lit_texels, vs, masked, [&](__m512i x) { return _mm512_add_epi32(x, step64); });
}

}  // namespace

void wall_column_vbmi(uint8_t* out, int count, uint32_t v, uint32_t step, int rows_log2, const uint8_t* source,
                      const uint8_t* light) {
  if (count <= 192 && rows_log2 <= 7) {
    if (rows_log2 == 7) return lit_after_lookup<true>(out, count, v, step, rows_log2, source, light);
    return lit_after_lookup<false>(out, count, v, step, rows_log2, source, light);
  }
  __m512i vs[4];
  vs[0] = _mm512_add_epi32(_mm512_set1_epi32(int(v)), _mm512_mullo_epi32(lanes16(), _mm512_set1_epi32(int(step))));
  const __m512i step16 = _mm512_set1_epi32(int(step * 16)), step64 = _mm512_set1_epi32(int(step * 64));
  for (int i = 1; i < 4; ++i) vs[i] = _mm512_add_epi32(vs[i - 1], step16);
  const __m512i row_mask = _mm512_set1_epi8(char((1 << rows_log2) - 1));
  auto masked = [&](__m512i texel_rows) {  // 128 rows or more: the look-up reads only the bits it needs
    return rows_log2 < 7 ? _mm512_and_si512(texel_rows, row_mask) : texel_rows;
  };
  stepped_column(out, count, LitColumn(source, 1 << rows_log2, light), vs, masked,
                 [&](__m512i x) { return _mm512_add_epi32(x, step64); });
}

void wrapped_column_vbmi(uint8_t* out, int count, uint32_t v, uint32_t step, int rows, const uint8_t* source,
                         const uint8_t* light) {
  // Each lane's v is kept below the period: a step of 16 or 64 pixels is taken modulo it
  // first, so one subtraction wraps a sum.
  const uint32_t period = uint32_t(rows) << 16;
  const __m512i periods = _mm512_set1_epi32(int(period));
  auto wrap = [&](__m512i sum) {  // below two periods
    return _mm512_mask_sub_epi32(sum, _mm512_cmpge_epu32_mask(sum, periods), sum, periods);
  };
  // v + lane * step is below 16 periods (each term below one): 8, 4, 2 and 1 periods off.
  __m512i vs[4];
  vs[0] = _mm512_add_epi32(_mm512_set1_epi32(int(v)), _mm512_mullo_epi32(lanes16(), _mm512_set1_epi32(int(step))));
  for (uint32_t k = 8; k >= 1; k /= 2) {
    const __m512i off = _mm512_set1_epi32(int(k * period));
    vs[0] = _mm512_mask_sub_epi32(vs[0], _mm512_cmpge_epu32_mask(vs[0], off), vs[0], off);
  }
  const __m512i step16 = _mm512_set1_epi32(int(uint64_t(step) * 16 % period));
  const __m512i step64 = _mm512_set1_epi32(int(uint64_t(step) * 64 % period));
  for (int i = 1; i < 4; ++i) vs[i] = wrap(_mm512_add_epi32(vs[i - 1], step16));
  auto as_is = [](__m512i texel_rows) { return texel_rows; };  // below the height, so below 256
  stepped_column(out, count, LitColumn(source, rows, light), vs, as_is,
                 [&](__m512i x) { return wrap(_mm512_add_epi32(x, step64)); });
}

int columns_to_rows_vbmi(const uint8_t* columns, size_t column_stride, uint8_t* rows, size_t row_pitch, int width,
                         int height) {
  const int blocked = width / 64 * 64;
  for (int x = 0; x < blocked; x += 64) {  // down the columns: each column's line read four times while in L1
    auto turn = [&](int y, int n) {
      rows_of_64_columns(columns + size_t(x) * column_stride + size_t(y), column_stride,
                         rows + size_t(y) * row_pitch + size_t(x), row_pitch, n);
    };
    int y = 0;
    for (; y + 16 <= height; y += 16) turn(y, 16);
    if (y < height) turn(y, height - y);
  }
  return blocked;
}

void tabled_column_vbmi(uint8_t* out, int count, const uint8_t* rows, const uint8_t* source, int texels,
                        const uint8_t* light) {
  const LitColumn column(source, texels, light);
  int i = 0;
  for (; i + 64 <= count; i += 64) _mm512_storeu_si512(out + i, column(_mm512_loadu_si512(rows + i)));
  if (i < count) _mm512_mask_storeu_epi8(out + i, first_bytes(count - i), column(load_first(rows + i, count - i)));
}

namespace {

// Byte 0 of each 32-bit lane of four registers, in lane order: 64 bytes.
alignas(64) constexpr uint8_t kByte0[64] = {
    0,  4,  8,  12, 16, 20, 24, 28, 32, 36, 40, 44, 48, 52, 56, 60, 64, 68, 72, 76, 80, 84,
    88, 92, 96, 100, 104, 108, 112, 116, 120, 124, 0, 4, 8, 12, 16, 20, 24, 28, 32, 36, 40, 44,
    48, 52, 56, 60, 64, 68, 72, 76, 80, 84, 88, 92, 96, 100, 104, 108, 112, 116, 120, 124};

inline __m512i low_bytes(const __m512i (&d)[4]) {
  const __m512i pick = _mm512_load_si512(kByte0);
  const __m512i low = _mm512_permutex2var_epi8(d[0], pick, d[1]), high = _mm512_permutex2var_epi8(d[2], pick, d[3]);
  return _mm512_mask_blend_epi8(~__mmask64(0) << 32, low, high);
}

// Four columns of a 64 x 64 flat, from column `first` on (wrapping at 64), as a table.
inline Table256 flat_columns(const uint8_t* indices, int first) {
  auto column = [&](int j) { return _mm512_loadu_si512(indices + size_t((first + j) & 63) * 64); };
  return {column(0), column(1), column(2), column(3)};
}

// 64 pixels of a 64 x 64 flat's row whose texels lie in `columns` (4, 8 or 16) neighbouring
// columns from column `first` on: looked up in registers holding those columns. us and
// vs the first sixteen pixels' coordinates, du and dv the steps of sixteen; a pixel's
// column is bits column_shift to column_shift + 5 of its u, its row bits row_shift on of v.
inline __m512i windowed_texels(const uint8_t* indices, int first, int columns, int column_shift, int row_shift,
                               __m512i us, __m512i vs, __m512i du, __m512i dv) {
  const __m128i cs = _mm_cvtsi32_si128(column_shift), rs = _mm_cvtsi32_si128(row_shift);
  const __m512i firsts = _mm512_set1_epi32(first), fifteens = _mm512_set1_epi32(15), rows = _mm512_set1_epi32(63);
  __m512i at[4];  // (column - first) * 64 + row: bits 6 and 7 the column of four, bits 8 and 9 which four
  for (int g = 0; g < 4; ++g, us = _mm512_add_epi32(us, du), vs = _mm512_add_epi32(vs, dv)) {
    const __m512i column = _mm512_and_si512(_mm512_sub_epi32(_mm512_srl_epi32(us, cs), firsts), fifteens);
    at[g] = _mm512_or_si512(_mm512_slli_epi32(column, 6), _mm512_and_si512(_mm512_srl_epi32(vs, rs), rows));
  }
  const __m512i index = low_bytes(at);
  auto lanes_with = [&](int bit) {  // the pixels whose at has the bit: a mask of 64
    const __m512i b = _mm512_set1_epi32(bit);
    return _mm512_kunpackd(_mm512_kunpackw(_mm512_test_epi32_mask(at[3], b), _mm512_test_epi32_mask(at[2], b)),
                           _mm512_kunpackw(_mm512_test_epi32_mask(at[1], b), _mm512_test_epi32_mask(at[0], b)));
  };
  const __m512i near = flat_columns(indices, first)(index);
  if (columns == 4) return near;
  const __mmask64 odd = lanes_with(256);
  const __m512i eight = _mm512_mask_blend_epi8(odd, near, flat_columns(indices, first + 4)(index));
  if (columns == 8) return eight;
  const __m512i far = _mm512_mask_blend_epi8(odd, flat_columns(indices, first + 8)(index),
                                             flat_columns(indices, first + 12)(index));
  return _mm512_mask_blend_epi8(lanes_with(512), eight, far);
}

// How many neighbouring columns of a 64 x 64 flat every 64 pixels of a row lie in (4, 8
// or 16; 0: more, or not such a flat): a near row, or one seen along the flat's columns.
inline int row_window(RowCoordinate u, RowCoordinate v) {
  const int column_shift = int(u.shift) + 6;
  if (u.mask != 63u << 6 || v.mask != 63u || column_shift + 6 > 32) return 0;
  const uint64_t reach = uint64_t(std::abs(int64_t(int32_t(u.step)))) * 63;  // from a stretch's first pixel to its last
  if (reach < uint64_t(3) << column_shift) return 4;
  return reach < uint64_t(7) << column_shift ? 8 : reach < uint64_t(15) << column_shift ? 16 : 0;
}

}  // namespace

void flat_row_vbmi(uint8_t* out, int n, RowCoordinate u, RowCoordinate v, const uint8_t* indices,
                   const uint8_t* light) {
  const Table256 light_table = Table256::load(light);
  const __m512i lanes = lanes16();
  __m512i us = _mm512_add_epi32(_mm512_set1_epi32(int(u.value)), _mm512_mullo_epi32(lanes, _mm512_set1_epi32(int(u.step))));
  __m512i vs = _mm512_add_epi32(_mm512_set1_epi32(int(v.value)), _mm512_mullo_epi32(lanes, _mm512_set1_epi32(int(v.step))));
  const __m512i du = _mm512_set1_epi32(int(16 * u.step)), dv = _mm512_set1_epi32(int(16 * v.step));
  if (const int columns = row_window(u, v)) {
    // Each stretch's columns from its first pixel's on, or back from it for a step down.
    const int column_shift = int(u.shift) + 6, back = int32_t(u.step) < 0 ? columns - 1 : 0;
    const __m512i du64 = _mm512_slli_epi32(du, 2), dv64 = _mm512_slli_epi32(dv, 2);
    for (int i = 0; i < n; i += 64) {
      const int first = int((u.value + uint32_t(i) * u.step) >> column_shift) - back;
      const __m512i texels = windowed_texels(indices, first & 63, columns, column_shift, int(v.shift), us, vs, du, dv);
      _mm512_mask_storeu_epi8(out + i, first_bytes(std::min(64, n - i)), light_table(texels));
      us = _mm512_add_epi32(us, du64), vs = _mm512_add_epi32(vs, dv64);
    }
    return;
  }
  const __m128i u_shift = _mm_cvtsi32_si128(int(u.shift)), v_shift = _mm_cvtsi32_si128(int(v.shift));
  const __m512i u_mask = _mm512_set1_epi32(int(u.mask)), v_mask = _mm512_set1_epi32(int(v.mask));
  // Each texel gathered with the aligned four bytes that hold it, never a byte outside
  // them, then shifted down to its lane's low byte: `at` counts from the aligned word
  // that holds the first texel.
  const __m512i skews = _mm512_set1_epi32(int(uintptr_t(indices) & 3)), threes = _mm512_set1_epi32(3);
  auto texels_of = [&] {
    const __m512i at = _mm512_add_epi32(_mm512_or_si512(_mm512_and_si512(_mm512_srl_epi32(us, u_shift), u_mask),
                                                        _mm512_and_si512(_mm512_srl_epi32(vs, v_shift), v_mask)),
                                        skews);
    const __m512i word = _mm512_i32gather_epi32(_mm512_sub_epi32(_mm512_andnot_si512(threes, at), skews), indices, 1);
    us = _mm512_add_epi32(us, du), vs = _mm512_add_epi32(vs, dv);
    return _mm512_srlv_epi32(word, _mm512_slli_epi32(_mm512_and_si512(at, threes), 3));
  };
  for (int i = 0; i < n; i += 64) {
    const int count = std::min(64, n - i);
    __m512i texels[4];
    for (int g = 0; g < 4; ++g) texels[g] = 16 * g < count ? texels_of() : _mm512_setzero_si512();
    _mm512_mask_storeu_epi8(out + i, first_bytes(count), light_table(low_bytes(texels)));
  }
}

}  // namespace p3d::render
