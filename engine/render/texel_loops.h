// The inner loops of walls and flats, shared by our rules (draw.cpp) and Doom's
// (draw_doom.cpp): texel sources (a texture column under a light map), the rows of a
// column stepping through a texture that repeats vertically, and a flat's row.
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>

#ifdef __SSE2__
#include <emmintrin.h>
#endif

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

// Hides what a value is from the optimiser, which would otherwise rewrite an
// expression in it (a register, no instruction).
template <typename T>
inline void opaque(T& value) {
#if defined(__GNUC__)
  asm("" : "+r"(value));
#endif
}

// Rows y0..y1 of a column whose texel row is (v >> 16) mod period, v stepping by step.
// v and step are already reduced modulo period, so one subtraction keeps v in range.
// A power-of-two period (at most 2^32, as textures are at most 4096 high) divides
// 2^32: v may then wrap in 32 bits and the row be masked.
template <typename Pixel, typename Source>
inline void wrapped_column(Pixel* out, size_t pitch, int count, int64_t v, int64_t step, int64_t period,
                           const Source texel) {  // by value: the stores, bytes, may alias a referenced one
  if ((period & (period - 1)) == 0) {
    // The row is bits [16, 16 + k) of v for 2^k rows. Shifted to the top of 32 bits, v
    // wraps alike and a row is one shift, with no mask.
    const int k = std::countr_zero(uint64_t(period)) - 16, drop = 16 - k;
    const uint32_t step32 = uint32_t(step) << drop;
    uint32_t v32 = uint32_t(v) << drop;
    const auto row = [k](uint32_t at) { return size_t(uint64_t(at) >> (32 - k)); };  // k = 0: row 0
    // Unrolled, a wall being most of a frame: each of four rows from v32 by its own
    // offset (not a chain of additions) and the loop ended by the pointer, 6 instructions
    // a pixel (7.25 before).
    uint32_t step2 = 2 * step32, step3 = 3 * step32;
    const uint32_t step4 = 4 * step32;
    opaque(step2), opaque(step3);  // else the compiler chains the rows again: v + 2s as (v + s) + s
    const size_t pitch2 = 2 * pitch, pitch3 = 3 * pitch, pitch4 = 4 * pitch;
    Pixel* const end4 = out + size_t(count / 4) * pitch4;
    for (; out != end4; out += pitch4, v32 += step4) {
      out[0] = texel(row(v32));
      out[pitch] = texel(row(v32 + step32));
      out[pitch2] = texel(row(v32 + step2));
      out[pitch3] = texel(row(v32 + step3));
    }
    for (unsigned i = unsigned(count) % 4; i > 0; --i, out += pitch, v32 += step32) *out = texel(row(v32));
    return;
  }
  for (int i = 0; i < count; ++i, out += pitch) {
    *out = texel(size_t(v >> 16));
    v += step;
    if (v >= period) v -= period;
  }
}

// A coordinate of a flat's row stepping modulo 2^32, and its part of the texel index:
// (value >> shift) & mask.
struct RowCoordinate {
  uint32_t value, step, shift, mask;
};

// n pixels of a flat's row in palette indices, texel index u's part | v's part: four
// pixels at a time in SSE2's 32-bit lanes, which a flat's rows spend half their
// instructions on.
inline void indexed_row(uint8_t* out, int n, RowCoordinate u, RowCoordinate v, const uint8_t* indices,
                        const uint8_t* light_map) {
  int i = 0;
#ifdef __SSE2__
  const __m128i u_shift = _mm_cvtsi32_si128(int(u.shift)), v_shift = _mm_cvtsi32_si128(int(v.shift));
  const __m128i u_mask = _mm_set1_epi32(int(u.mask)), v_mask = _mm_set1_epi32(int(v.mask));
  const __m128i du4 = _mm_set1_epi32(int(4 * u.step)), dv4 = _mm_set1_epi32(int(4 * v.step));
  __m128i uu = _mm_setr_epi32(int(u.value), int(u.value + u.step), int(u.value + 2 * u.step), int(u.value + 3 * u.step));
  __m128i vv = _mm_setr_epi32(int(v.value), int(v.value + v.step), int(v.value + 2 * v.step), int(v.value + 3 * v.step));
  for (; i + 4 <= n; i += 4) {
    const __m128i texels =
        _mm_or_si128(_mm_and_si128(_mm_srl_epi32(uu, u_shift), u_mask), _mm_and_si128(_mm_srl_epi32(vv, v_shift), v_mask));
    const uint64_t low = uint64_t(_mm_cvtsi128_si64(texels));
    const uint64_t high = uint64_t(_mm_cvtsi128_si64(_mm_unpackhi_epi64(texels, texels)));
    out[i] = light_map[indices[uint32_t(low)]];
    out[i + 1] = light_map[indices[low >> 32]];
    out[i + 2] = light_map[indices[uint32_t(high)]];
    out[i + 3] = light_map[indices[high >> 32]];
    uu = _mm_add_epi32(uu, du4);
    vv = _mm_add_epi32(vv, dv4);
  }
  u.value += uint32_t(i) * u.step, v.value += uint32_t(i) * v.step;
#endif
  for (; i < n; ++i, u.value += u.step, v.value += v.step)
    out[i] = light_map[indices[((u.value >> u.shift) & u.mask) | ((v.value >> v.shift) & v.mask)]];
}

}  // namespace p3d::render
