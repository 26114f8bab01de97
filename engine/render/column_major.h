// A canvas's columns kept column-major while its walls, skies and fills are drawn, on
// processors with AVX-512 VBMI: a wall column's pixels are then adjacent bytes rather
// than a row apart, and 64 of them are drawn with one table look-up (a texture column
// of up to 128 rows, already under its light map, fits in two registers). The columns
// are turned into the frame's rows once, before the flats (rows) are drawn, whose
// texels are lit 64 at a time by the same look-ups. Elsewhere the canvas draws into the
// rows, as turning the columns costs more than scalar loops save.
#pragma once

#include <cstddef>
#include <cstdint>

#include "engine/render/texel_loops.h"

namespace p3d::render {

// Copies `width` columns of `height` bytes, column c at columns + c * column_stride,
// into rows of the frame: row y at rows + y * row_pitch.
void columns_to_rows(const uint8_t* columns, size_t column_stride, uint8_t* rows, size_t row_pitch, int width,
                     int height);

// The 16 x 16 byte transpose of each 128-bit lane of 16 registers: interleaving the
// bytes of registers i and i + 8, four times over, leaves in lane L of register j byte j
// of lane L of every register, in order. SSE2's registers are one lane; AVX-512's four,
// turned at once.
template <typename Vector, typename UnpackLow, typename UnpackHigh>
inline void interleave_16x16(Vector (&r)[16], UnpackLow unpack_low, UnpackHigh unpack_high) {
  Vector t[16];
#pragma GCC unroll 4
  for (int pass = 0; pass < 4; ++pass) {
#pragma GCC unroll 8
    for (int i = 0; i < 8; ++i) t[2 * i] = unpack_low(r[i], r[i + 8]), t[2 * i + 1] = unpack_high(r[i], r[i + 8]);
#pragma GCC unroll 16
    for (int i = 0; i < 16; ++i) r[i] = t[i];
  }
}

// Whether this processor has AVX-512 VBMI, and the loops below are built.
bool vector_columns();

// columns_to_rows for the first width / 64 * 64 columns, 64 at a time (a whole cache
// line of each row written at once); returns how many it turned. Only where
// vector_columns() is true.
int columns_to_rows_vbmi(const uint8_t* columns, size_t column_stride, uint8_t* rows, size_t row_pitch, int width,
                         int height);

// A wall or sky column of fewer rows keeps the scalar loop: the vector loop's set-up
// costs more than it saves. With a short column's texels lit after their look-up,
// 8 rows as the threshold took 0.98-0.99 of the time of 16 (12: 0.99).
constexpr int kVectorColumnRows = 8;

// count adjacent bytes of a wall column: out[i] = light[source[row]], row the bits
// [16, 16 + rows_log2) of v + i * step (modulo 2^32), the column's 2^rows_log2 texels at
// source (rows_log2 <= 8). Only where vector_columns() is true.
void wall_column_vbmi(uint8_t* out, int count, uint32_t v, uint32_t step, int rows_log2, const uint8_t* source,
                      const uint8_t* light);
// The same for a column of any number of rows up to 256 (Crispy's textures of 72 or 96
// rows wrap at their height): row (v + i * step) >> 16 modulo the period rows << 16, v
// and step below it as the canvas reduces them.
void wrapped_column_vbmi(uint8_t* out, int count, uint32_t v, uint32_t step, int rows, const uint8_t* source,
                         const uint8_t* light);
// count adjacent bytes of a column whose texel rows come from a table (the sky's):
// out[i] = light[source[rows[i]]], every row below texels (at most 256).
void tabled_column_vbmi(uint8_t* out, int count, const uint8_t* rows, const uint8_t* source, int texels,
                        const uint8_t* light);

// n pixels of a flat's row, as indexed_row draws them: each texel's index worked out
// and its texel gathered 16 at a time (or, for a 64 x 64 flat's row whose every 64
// pixels lie within sixteen of its columns, looked up in registers holding them), lit
// 64 at a time by table look-ups.
void flat_row_vbmi(uint8_t* out, int n, RowCoordinate u, RowCoordinate v, const uint8_t* indices,
                   const uint8_t* light);

}  // namespace p3d::render
