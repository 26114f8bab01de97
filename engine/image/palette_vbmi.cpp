// resolve_palette 64 pixels at a time with AVX-512 VBMI: this file alone is built for it
// (engine/CMakeLists.txt), and resolve_palette calls it only where vector_palette() says
// the processor has it. The palette is four tables of 256 bytes, one per byte of its
// colours, each looked up in four registers by byte permutes; the four bytes of each
// pixel are then interleaved into its colour.
// GCC 12's AVX-512 permutes and shuffles start from a self-initialised "undefined"
// register, which -Wmaybe-uninitialized and -Wuninitialized report (GCC bug 105593).
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#pragma GCC diagnostic ignored "-Wuninitialized"
#endif
#include <immintrin.h>

#include <array>

#include "engine/image/palette.h"

namespace p3d::image {

namespace {

inline __mmask64 first_bytes(int n) { return n >= 64 ? ~__mmask64(0) : (__mmask64(1) << n) - 1; }
inline __mmask16 first_lanes(int n) { return n >= 16 ? __mmask16(0xFFFF) : n <= 0 ? 0 : __mmask16((1u << n) - 1); }

// The interleaves below work within each 16-byte lane: lane L's bytes 4j to 4j + 3 end
// up as register j's lanes 4L to 4L + 3. So the indices are first moved there from
// pixels 16j + 4L to 16j + 4L + 3, and register j holds pixels 16j to 16j + 15 in order.
constexpr std::array<uint8_t, 64> kSpread = [] {
  std::array<uint8_t, 64> spread{};
  for (int lane = 0; lane < 4; ++lane)
    for (int j = 0; j < 4; ++j)
      for (int k = 0; k < 4; ++k) spread[size_t(16 * lane + 4 * j + k)] = uint8_t(16 * j + 4 * lane + k);
  return spread;
}();

// A 256-byte table in four registers: bit 7 of an index picks the pair.
struct Table256 {
  __m512i a, b, c, d;
  __m512i operator()(__m512i index, __mmask64 high) const {
    return _mm512_mask_blend_epi8(high, _mm512_permutex2var_epi8(a, index, b), _mm512_permutex2var_epi8(c, index, d));
  }
};

// Byte p of every colour: dword i's byte p is byte 4i + p of the palette, gathered 32
// at a time from two registers of colours by a byte permute.
Table256 palette_bytes(const uint32_t* palette, int p) {
  alignas(64) uint8_t pick[64];
  for (int i = 0; i < 64; ++i) pick[i] = uint8_t(4 * (i & 31) + p);
  const __m512i picks = _mm512_load_si512(pick);
  auto load = [&](int at) { return _mm512_loadu_si512(palette + at); };
  auto quarter = [&](int q) {  // colours 64q to 64q + 63
    const __m512i low = _mm512_permutex2var_epi8(load(64 * q), picks, load(64 * q + 16));
    const __m512i high = _mm512_permutex2var_epi8(load(64 * q + 32), picks, load(64 * q + 48));
    return _mm512_shuffle_i64x2(low, high, 0x44);  // the low halves of both
  };
  return {quarter(0), quarter(1), quarter(2), quarter(3)};
}

}  // namespace

void resolve_palette_vbmi(const uint8_t* indices, size_t index_pitch, uint32_t* pixels, size_t pixel_pitch, int width,
                          int rows, const uint32_t* palette) {
  const Table256 byte0 = palette_bytes(palette, 0), byte1 = palette_bytes(palette, 1);
  const Table256 byte2 = palette_bytes(palette, 2), byte3 = palette_bytes(palette, 3);
  const __m512i spread = _mm512_loadu_si512(kSpread.data());
  for (int y = 0; y < rows; ++y, indices += index_pitch, pixels += pixel_pitch) {
    for (int x = 0; x < width; x += 64) {
      const int n = width - x;
      const __m512i index = _mm512_permutexvar_epi8(spread, _mm512_maskz_loadu_epi8(first_bytes(n), indices + x));
      const __mmask64 high = _mm512_movepi8_mask(index);
      const __m512i p0 = byte0(index, high), p1 = byte1(index, high), p2 = byte2(index, high), p3 = byte3(index, high);
      const __m512i low01 = _mm512_unpacklo_epi8(p0, p1), high01 = _mm512_unpackhi_epi8(p0, p1);
      const __m512i low23 = _mm512_unpacklo_epi8(p2, p3), high23 = _mm512_unpackhi_epi8(p2, p3);
      const __m512i colours[4] = {_mm512_unpacklo_epi16(low01, low23), _mm512_unpackhi_epi16(low01, low23),
                                  _mm512_unpacklo_epi16(high01, high23), _mm512_unpackhi_epi16(high01, high23)};
      uint32_t* out = pixels + x;
      if (n >= 64) {
        for (int j = 0; j < 4; ++j) _mm512_storeu_si512(out + 16 * j, colours[j]);
      } else {
        for (int j = 0; j < 4; ++j) _mm512_mask_storeu_epi32(out + 16 * j, first_lanes(n - 16 * j), colours[j]);
      }
    }
  }
}

}  // namespace p3d::image
