#include "engine/render/column_major.h"

#ifdef __SSE2__
#include <emmintrin.h>
#endif

#include "engine/util/cpu.h"

namespace p3d::render {

namespace {

#ifdef __SSE2__
// Sixteen columns' sixteen bytes into sixteen rows.
inline void block_to_rows(const uint8_t* columns, size_t column_stride, uint8_t* rows, size_t row_pitch) {
  __m128i r[16];
#pragma GCC unroll 16
  for (int i = 0; i < 16; ++i)
    r[i] = _mm_loadu_si128(reinterpret_cast<const __m128i*>(columns + size_t(i) * column_stride));
  interleave_16x16(r, [](__m128i a, __m128i b) { return _mm_unpacklo_epi8(a, b); },
                   [](__m128i a, __m128i b) { return _mm_unpackhi_epi8(a, b); });
#pragma GCC unroll 16
  for (int i = 0; i < 16; ++i) _mm_storeu_si128(reinterpret_cast<__m128i*>(rows + size_t(i) * row_pitch), r[i]);
}
#endif

void columns_to_rows_bytewise(const uint8_t* columns, size_t column_stride, uint8_t* rows, size_t row_pitch, int x0,
                              int x1, int y0, int y1) {
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x)
      rows[size_t(y) * row_pitch + size_t(x)] = columns[size_t(x) * column_stride + size_t(y)];
}

}  // namespace

void columns_to_rows(const uint8_t* columns, size_t column_stride, uint8_t* rows, size_t row_pitch, int width,
                     int height) {
  if (width <= 0 || height <= 0) return;  // nothing to turn (and no buffers to point into)
  if (vector_columns()) {
    const int done = columns_to_rows_vbmi(columns, column_stride, rows, row_pitch, width, height);
    columns += size_t(done) * column_stride, rows += done, width -= done;
  }
  int blocked_width = 0, blocked_height = 0;
#ifdef __SSE2__
  blocked_width = width / 16 * 16, blocked_height = height / 16 * 16;
  for (int x = 0; x < blocked_width; x += 16)  // down the columns: their loads in order, the rows' lines in L1
    for (int y = 0; y < blocked_height; y += 16)
      block_to_rows(columns + size_t(x) * column_stride + size_t(y), column_stride,
                    rows + size_t(y) * row_pitch + size_t(x), row_pitch);
#endif
  columns_to_rows_bytewise(columns, column_stride, rows, row_pitch, blocked_width, width, 0, height);
  columns_to_rows_bytewise(columns, column_stride, rows, row_pitch, 0, blocked_width, blocked_height, height);
}

bool vector_columns() {
#ifdef P3D_VBMI_COLUMNS
  return has_avx512_vbmi();
#else
  return false;
#endif
}

#ifndef P3D_VBMI_COLUMNS
// Never called: vector_columns() is false.
void wall_column_vbmi(uint8_t*, int, uint32_t, uint32_t, int, const uint8_t*, const uint8_t*) {}
void wrapped_column_vbmi(uint8_t*, int, uint32_t, uint32_t, int, const uint8_t*, const uint8_t*) {}
void tabled_column_vbmi(uint8_t*, int, const uint8_t*, const uint8_t*, int, const uint8_t*) {}
void flat_row_vbmi(uint8_t*, int, RowCoordinate, RowCoordinate, const uint8_t*, const uint8_t*) {}
int columns_to_rows_vbmi(const uint8_t*, size_t, uint8_t*, size_t, int, int) { return 0; }
#endif

}  // namespace p3d::render
