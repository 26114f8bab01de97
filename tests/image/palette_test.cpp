// Palette indices into colours: the vector loop's colours are the palette's own, pixel
// for pixel, for rows of every width to 300 (the last stretch of 64 short), any
// pitches and any palette; nothing written past a row; Frame::resolve_colours alike.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "engine/image/frame.h"
#include "engine/image/palette.h"
#include "engine/util/rng.h"

namespace p3d::image {
namespace {

TEST(Palette, VectorColoursAreThePalettes) {
  if (!vector_palette()) GTEST_SKIP() << "no AVX-512 VBMI on this processor";
  Rng rng(31);
  std::vector<uint32_t> palette(256);
  constexpr uint32_t kGuard = 0x5A5A5A5Au;
  for (int trial = 0; trial < 400; ++trial) {
    for (uint32_t& c : palette) c = uint32_t(rng.next());
    const int width = trial < 300 ? trial + 1 : int(rng.range(1, 300)), rows = int(rng.range(1, 4));
    const size_t index_pitch = size_t(width) + rng.below(70), pixel_pitch = size_t(width) + 1 + rng.below(70);
    std::vector<uint8_t> indices(index_pitch * size_t(rows));
    for (uint8_t& i : indices) i = uint8_t(rng.next());
    std::vector<uint32_t> pixels(pixel_pitch * size_t(rows), kGuard);
    resolve_palette_vbmi(indices.data(), index_pitch, pixels.data(), pixel_pitch, width, rows, palette.data());
    for (int y = 0; y < rows; ++y)
      for (size_t x = 0; x < pixel_pitch; ++x) {
        const uint32_t want = x < size_t(width) ? palette[indices[size_t(y) * index_pitch + x]] : kGuard;
        ASSERT_EQ(pixels[size_t(y) * pixel_pitch + x], want)
            << width << " wide, row " << y << ", pixel " << x << (x < size_t(width) ? "" : ": past the row");
      }
  }
}

TEST(Palette, FrameResolvesItsIndices) {
  Rng rng(32);
  Frame frame = Frame::without_pixels(37, 5);
  frame.indices.resize(37 * 5);
  for (uint8_t& i : frame.indices) i = uint8_t(rng.range(0, 15));
  frame.palette.resize(12);  // a short palette: the indices past it black
  for (uint32_t& c : frame.palette) c = uint32_t(rng.next()) | 1u;
  frame.resolve_colours();
  ASSERT_EQ(frame.pixels.size(), frame.indices.size());
  for (size_t i = 0; i < frame.indices.size(); ++i)
    ASSERT_EQ(frame.pixels[i], frame.indices[i] < 12 ? frame.palette[frame.indices[i]] : 0u) << "pixel " << i;
}

}  // namespace
}  // namespace p3d::image
