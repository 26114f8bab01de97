// The canvas's column-major columns: turned into rows exactly, and the vector columns
// and flat rows (AVX-512 VBMI) drawing the scalar loops' very bytes.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "engine/render/column_major.h"
#include "engine/render/texel_loops.h"
#include "engine/util/rng.h"

namespace p3d::render {
namespace {

TEST(ColumnMajor, RowsAreTheColumnsTurned) {
  Rng rng(38);
  for (int trial = 0; trial < 300; ++trial) {
    // Past 64 columns: the vector blocks of 64 and the rest beside them.
    const int width = rng.range(0, trial < 150 ? 70 : 200), height = rng.range(0, 70);
    const size_t stride = size_t(height + rng.range(0, 20)), pitch = size_t(width + rng.range(0, 20));
    std::vector<uint8_t> columns(stride * size_t(width));
    for (uint8_t& b : columns) b = uint8_t(rng.next());
    std::vector<uint8_t> rows(pitch * size_t(height), 0xA5);
    columns_to_rows(columns.data(), stride, rows.data(), pitch, width, height);
    const std::string what = std::to_string(width) + " x " + std::to_string(height);
    for (int y = 0; y < height; ++y)
      for (size_t x = 0; x < pitch; ++x) {
        const uint8_t want = x < size_t(width) ? columns[x * stride + size_t(y)] : 0xA5;  // past the width: untouched
        ASSERT_EQ(rows[size_t(y) * pitch + x], want) << what << " at " << x << ", " << y;
      }
  }
}

TEST(ColumnMajor, VectorWallColumnDrawsTheScalarLoopsBytes) {
  if (!vector_columns()) GTEST_SKIP() << "no AVX-512 VBMI on this processor";
  Rng rng(7);
  std::vector<uint8_t> light(256);
  for (uint8_t& b : light) b = uint8_t(rng.next());
  constexpr int kGuard = 64;
  for (int rows_log2 = 0; rows_log2 <= 8; ++rows_log2) {
    const int64_t period = int64_t(1) << (16 + rows_log2);
    std::vector<uint8_t> source(size_t(1) << rows_log2);  // exactly the column: nothing past it is read
    for (int trial = 0; trial < 400; ++trial) {
      for (uint8_t& b : source) b = uint8_t(rng.next());
      const int count = trial < 200 ? rng.range(1, 300) : 64 * rng.range(1, 4) + rng.range(-1, 1);
      // Reduced as the canvas reduces them; the vector loop reads only the row's bits.
      const uint32_t v = uint32_t(rng.below(uint64_t(period))), step = uint32_t(rng.below(uint64_t(period)));
      std::vector<uint8_t> want(static_cast<size_t>(count)), got(static_cast<size_t>(count + 2 * kGuard), 0x5A);
      wrapped_column(want.data(), 1, count, v, step, period, IndexedColumn{source.data(), light.data()});
      wall_column_vbmi(got.data() + kGuard, count, v, step, rows_log2, source.data(), light.data());
      const std::string what = std::to_string(1 << rows_log2) + " rows, " + std::to_string(count) + " pixels";
      for (int i = 0; i < count; ++i) ASSERT_EQ(got[size_t(kGuard + i)], want[size_t(i)]) << what << ", pixel " << i;
      for (int i = 0; i < kGuard; ++i) {
        ASSERT_EQ(got[size_t(i)], 0x5A) << what << ": wrote before the column";
        ASSERT_EQ(got[size_t(kGuard + count + i)], 0x5A) << what << ": wrote past the column";
      }
    }
  }
}

// Columns of any number of rows to 256 (Crispy's textures wrap at their own height):
// the scalar loop's bytes, each pixel's v taken modulo the period.
TEST(ColumnMajor, VectorWrappedColumnDrawsTheScalarLoopsBytes) {
  if (!vector_columns()) GTEST_SKIP() << "no AVX-512 VBMI on this processor";
  Rng rng(10);
  std::vector<uint8_t> light(256);
  for (uint8_t& b : light) b = uint8_t(rng.next());
  constexpr int kGuard = 64;
  for (int rows : {1, 3, 5, 63, 64, 65, 72, 96, 100, 127, 128, 129, 136, 200, 255, 256}) {
    const int64_t period = int64_t(rows) << 16;
    std::vector<uint8_t> source(static_cast<size_t>(rows));  // exactly the column: nothing past it is read
    for (int trial = 0; trial < 300; ++trial) {
      for (uint8_t& b : source) b = uint8_t(rng.next());
      const int count = trial < 150 ? rng.range(1, 300) : 64 * rng.range(1, 4) + rng.range(-1, 1);
      // Below the period, as the canvas reduces them; now and then a step of whole rows,
      // or the largest, so that every pixel wraps.
      const uint32_t v = uint32_t(rng.below(uint64_t(period)));
      const uint32_t step = trial % 10 == 0 ? uint32_t(period - 1)
                            : trial % 10 == 1 ? uint32_t(rng.below(uint64_t(rows))) << 16
                                              : uint32_t(rng.below(uint64_t(period)));
      std::vector<uint8_t> want(static_cast<size_t>(count)), got(static_cast<size_t>(count + 2 * kGuard), 0x5A);
      wrapped_column(want.data(), 1, count, v, step, period, IndexedColumn{source.data(), light.data()});
      wrapped_column_vbmi(got.data() + kGuard, count, v, step, rows, source.data(), light.data());
      const std::string what = std::to_string(rows) + " rows, " + std::to_string(count) + " pixels";
      for (int i = 0; i < count; ++i) ASSERT_EQ(got[size_t(kGuard + i)], want[size_t(i)]) << what << ", pixel " << i;
      for (int i = 0; i < kGuard; ++i) {
        ASSERT_EQ(got[size_t(i)], 0x5A) << what << ": wrote before the column";
        ASSERT_EQ(got[size_t(kGuard + count + i)], 0x5A) << what << ": wrote past the column";
      }
    }
  }
}

TEST(ColumnMajor, TabledColumnLooksUpEachRowsTexel) {
  if (!vector_columns()) GTEST_SKIP() << "no AVX-512 VBMI on this processor";
  Rng rng(8);
  std::vector<uint8_t> light(256);
  for (uint8_t& b : light) b = uint8_t(rng.next());
  for (int texels : {1, 5, 64, 100, 128, 129, 200, 256}) {
    std::vector<uint8_t> source(static_cast<size_t>(texels));  // exactly the column: nothing past it is read
    for (int trial = 0; trial < 200; ++trial) {
      for (uint8_t& b : source) b = uint8_t(rng.next());
      const int count = rng.range(1, 300);
      std::vector<uint8_t> rows(static_cast<size_t>(count));  // exactly the rows asked for
      for (uint8_t& r : rows) r = uint8_t(rng.below(uint64_t(texels)));
      std::vector<uint8_t> got(static_cast<size_t>(count) + 64, 0x5A);
      tabled_column_vbmi(got.data(), count, rows.data(), source.data(), texels, light.data());
      const std::string what = std::to_string(texels) + " texels, " + std::to_string(count) + " pixels";
      for (int i = 0; i < count; ++i) ASSERT_EQ(got[size_t(i)], light[source[rows[size_t(i)]]]) << what << ", pixel " << i;
      for (size_t i = size_t(count); i < got.size(); ++i) ASSERT_EQ(got[i], 0x5A) << what << ": wrote past the column";
    }
  }
}

// A flat's row drawn by the vector loop: indexed_row's bytes, for flats of every
// power-of-two size up to 256 x 256 (only their texels read: the flat is exactly its
// size) starting at any byte of a word (the texels are gathered by words), rows of
// every length to 300, and nothing written past the row.
TEST(ColumnMajor, VectorFlatRowDrawsTheScalarLoopsBytes) {
  if (!vector_columns()) GTEST_SKIP() << "no AVX-512 VBMI on this processor";
  Rng rng(9);
  std::vector<uint8_t> light(256);
  for (uint8_t& b : light) b = uint8_t(rng.next());
  for (int width_log2 = 0; width_log2 <= 8; width_log2 += 2)
    for (int height_log2 = 0; height_log2 <= 8; height_log2 += 2) {
      std::vector<uint8_t> flat(size_t(1) << (width_log2 + height_log2)), skewed(flat.size() + 3);
      for (uint8_t& b : flat) b = uint8_t(rng.next());
      // Column-major, u's texel above v's, as the canvas asks for them.
      const uint32_t u_shift = uint32_t(16 - height_log2), u_mask = ((1u << width_log2) - 1) << height_log2;
      const uint32_t v_mask = (1u << height_log2) - 1;
      for (int trial = 0; trial < 200; ++trial) {
        const int n = trial % 100 < 50 ? rng.range(1, 300) : 64 * rng.range(1, 4) + rng.range(-1, 1);
        // The second hundred step u by a few columns a stretch of 64 pixels, up or down:
        // a 64 x 64 flat's rows within 4, 8 or 16 columns are looked up in registers.
        const int64_t column = int64_t(1) << (u_shift + height_log2);
        const uint32_t u_step = trial < 100 ? uint32_t(rng.next()) : uint32_t(int32_t(rng.range(-17 * column, 17 * column) / 63));
        const RowCoordinate u{uint32_t(rng.next()), u_step, u_shift, u_mask};
        const RowCoordinate v{uint32_t(rng.next()), uint32_t(rng.next()), 16, v_mask};
        const size_t skew = size_t(trial % 4);
        std::fill(skewed.begin(), skewed.end(), uint8_t(rng.next()));
        std::copy(flat.begin(), flat.end(), skewed.begin() + std::ptrdiff_t(skew));
        std::vector<uint8_t> want(static_cast<size_t>(n)), got(static_cast<size_t>(n) + 64, 0x5A);
        indexed_row(want.data(), n, u, v, flat.data(), light.data());
        flat_row_vbmi(got.data(), n, u, v, skewed.data() + skew, light.data());
        const std::string what = std::to_string(1 << width_log2) + " x " + std::to_string(1 << height_log2) + ", " +
                                 std::to_string(n) + " pixels, from byte " + std::to_string(skew);
        for (int i = 0; i < n; ++i) ASSERT_EQ(got[size_t(i)], want[size_t(i)]) << what << ", pixel " << i;
        for (size_t i = size_t(n); i < got.size(); ++i) ASSERT_EQ(got[i], 0x5A) << what << ": wrote past the row";
      }
    }
  // Vanilla's packed position: u bits 26 to 31, v bits 10 to 15 of one coordinate.
  std::vector<uint8_t> flat(64 * 64);
  for (uint8_t& b : flat) b = uint8_t(rng.next());
  for (int trial = 0; trial < 200; ++trial) {
    const int n = rng.range(1, 300);
    const int64_t reach = int64_t(17) << 26;  // up to seventeen columns a stretch, either way
    const int64_t few = (int64_t(rng.below(uint64_t(2 * reach + 1))) - reach) / 63;
    const uint32_t step = trial < 100 ? uint32_t(rng.next()) : uint32_t(int32_t(few));
    const uint32_t position = uint32_t(rng.next());
    const RowCoordinate u{position, step, 20, 63u << 6}, v{position, step, 10, 63u};
    std::vector<uint8_t> want(static_cast<size_t>(n)), got(static_cast<size_t>(n));
    indexed_row(want.data(), n, u, v, flat.data(), light.data());
    flat_row_vbmi(got.data(), n, u, v, flat.data(), light.data());
    ASSERT_EQ(got, want) << "packed, " << n << " pixels, step " << int32_t(step);
  }
}

}  // namespace
}  // namespace p3d::render
