// The inner loop of a wall column, shared by our rules (draw.cpp) and Doom's
// (draw_doom.cpp): texel sources (a texture column under a light map) and the rows of
// a column stepping through a texture that repeats vertically.
#pragma once

#include <cstddef>
#include <cstdint>

namespace p3d::render {

// An RGBA colour under light multiplier m (256: full bright).
inline uint32_t shade(uint32_t c, uint32_t m) {
  const uint32_t rb = ((c & 0xFF00FFu) * m >> 8) & 0xFF00FFu;
  const uint32_t g = ((c & 0x00FF00u) * m >> 8) & 0x00FF00u;
  return rb | g | 0xFF000000u;
}

// One texture column under one light map: paletted levels look the texel's index up
// in the light map (Doom's colormap, in 32-bit), RGBA levels multiply.
struct PalettedColumn {
  const uint8_t* indices;
  const uint32_t* light_map;
  uint32_t operator()(size_t v) const { return light_map[indices[v]]; }
};
// The same under an index light map (Doom's COLORMAP): a palette index.
struct IndexedColumn {
  const uint8_t* indices;
  const uint8_t* light_map;
  uint8_t operator()(size_t v) const { return light_map[indices[v]]; }
};
struct RgbaColumn {
  const uint32_t* texels;
  uint32_t multiplier;
  uint32_t operator()(size_t v) const { return shade(texels[v], multiplier); }
};

// Rows y0..y1 of a column whose texel row is (v >> 16) mod period, v stepping by step.
// v and step are already reduced modulo period, so one subtraction keeps v in range.
// A power-of-two period (at most 2^32, as textures are at most 4096 high) divides
// 2^32: v may then wrap in 32 bits and the row be masked.
template <typename Pixel, typename Source>
inline void wrapped_column(Pixel* out, size_t pitch, int count, int64_t v, int64_t step, int64_t period,
                           const Source& texel) {
  if ((period & (period - 1)) == 0) {
    const uint32_t row_mask = uint32_t((period >> 16) - 1);
    const uint32_t step32 = uint32_t(step);
    uint32_t v32 = uint32_t(v);
    int i = 0;
    for (; i + 4 <= count; i += 4, out += 4 * pitch, v32 += 4 * step32) {  // unrolled: a wall is most of a frame
      out[0] = texel((v32 >> 16) & row_mask);
      out[pitch] = texel(((v32 + step32) >> 16) & row_mask);
      out[2 * pitch] = texel(((v32 + 2 * step32) >> 16) & row_mask);
      out[3 * pitch] = texel(((v32 + 3 * step32) >> 16) & row_mask);
    }
    for (; i < count; ++i, out += pitch, v32 += step32) *out = texel((v32 >> 16) & row_mask);
    return;
  }
  for (int i = 0; i < count; ++i, out += pitch) {
    *out = texel(size_t(v >> 16));
    v += step;
    if (v >= period) v -= period;
  }
}

}  // namespace p3d::render
