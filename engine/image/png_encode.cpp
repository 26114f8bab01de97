// PNG encoding: each row filtered by whichever of PNG's five filters leaves the
// smallest sum of absolute differences (libpng's heuristic), the rows deflated in one
// zlib stream: as runs and literals (deflate_runs.h), or by libdeflate's search. An
// opaque image is written as RGB, else RGBA; an 8-bit frame as palette indices. The
// bytes depend only on the pixels: captures are reproducible on any thread count.
#include <libdeflate.h>

#ifdef __SSE2__
#include <emmintrin.h>
#endif

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <memory>

#include "engine/image/deflate_runs.h"
#include "engine/image/image.h"
#include "engine/util/error.h"

namespace p3d::image {

namespace {

// PngDeflate::kSearch's level, 1-12: 1 writes files 3% larger than level 2's at 0.6 of
// its deflate instructions (docs/benchmarks.md, "Threads and captures").
constexpr int kDeflateLevel = 1;

void put32(std::vector<uint8_t>& out, uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(uint8_t(v >> shift));
}

void chunk(std::vector<uint8_t>& out, const char type[4], std::span<const uint8_t> data) {
  put32(out, uint32_t(data.size()));
  const size_t start = out.size();
  out.insert(out.end(), type, type + 4);
  out.insert(out.end(), data.begin(), data.end());
  put32(out, libdeflate_crc32(0, out.data() + start, data.size() + 4));
}

// A filtered byte's weight in libpng's heuristic: its magnitude as a signed difference.
inline uint32_t magnitude(uint8_t v) { return v < 128 ? v : 256u - v; }

// PNG's Paeth predictor.
inline uint8_t paeth(int a, int b, int c) {  // a: left, b: up, c: up-left
  const int pa = std::abs(b - c), pb = std::abs(a - c), pc = std::abs(a + b - 2 * c);
  return uint8_t(pa <= pb && pa <= pc ? a : pb <= pc ? b : c);
}

// PNG's five filters of one byte, given its left (a), up (b) and up-left (c) neighbours:
// None, Sub, Up, Average and Paeth, numbered as in the file.
constexpr int kPaeth = 4;
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
// Sixteen bytes at a time (SSE2 is part of x86-64). Paeth's distances stay in bytes:
// pa = |b - c| and pb = |a - c| as unsigned differences, and pc = |(a - c) + (b - c)|
// their sum (saturated: 255 still orders after both) where a and b lie on one side of
// c, else the difference of the two.
struct Sixteen {
  __m128i r, a, b, c;
  Sixteen(const uint8_t* row, const uint8_t* up, size_t channels, size_t x) {
    const auto load = [](const uint8_t* p) { return _mm_loadu_si128(reinterpret_cast<const __m128i*>(p)); };
    r = load(row + x), a = load(row + x - channels), b = load(up + x), c = load(up + x - channels);
  }
  __m128i filtered(int type) const {
    switch (type) {
      case 0: return r;
      case 1: return _mm_sub_epi8(r, a);
      case 2: return _mm_sub_epi8(r, b);
      case 3: return _mm_sub_epi8(r, average());
      default: return _mm_sub_epi8(r, paeth_predictor());
    }
  }
  // (a + b) >> 1 without overflow: avg rounds up, so take off the carry of a ^ b.
  __m128i average() const {
    return _mm_sub_epi8(_mm_avg_epu8(a, b), _mm_and_si128(_mm_xor_si128(a, b), _mm_set1_epi8(1)));
  }
  __m128i paeth_predictor() const {
    const auto distance = [](__m128i x, __m128i y) { return _mm_or_si128(_mm_subs_epu8(x, y), _mm_subs_epu8(y, x)); };
    const auto at_most = [](__m128i x, __m128i y) { return _mm_cmpeq_epi8(_mm_min_epu8(x, y), x); };  // unsigned x <= y
    const auto choose = [](__m128i mask, __m128i yes, __m128i no) {
      return _mm_or_si128(_mm_and_si128(mask, yes), _mm_andnot_si128(mask, no));
    };
    const __m128i pa = distance(b, c), pb = distance(a, c);
    const __m128i one_side = _mm_cmpeq_epi8(at_most(c, a), at_most(c, b));
    const __m128i pc = choose(one_side, _mm_adds_epu8(pa, pb), distance(pa, pb));
    return choose(_mm_and_si128(at_most(pa, pb), at_most(pa, pc)), a, choose(at_most(pb, pc), b, c));
  }
};

// The summed magnitudes of the five filters over a sample of bytes [channels, stride)
// of a row (stride >= channels + 16), added to cost: every other sixteen bytes, by
// psadbw against 128 (|v ^ 128 - 128| is the magnitude of v as a signed byte). The
// sample takes half the work and chooses nearly as well: a Doom frame's PNG takes 9%
// less time and is 0.3-1% bigger (a quarter of the row: 1-2% bigger for 5% more).
// Paeth wins most rows of a frame (seven in ten at 1920x1080): every byte of it is
// written to out on the way, so that a row it wins needs no second pass.
void filter_costs_sse2(const uint8_t* row, const uint8_t* up, size_t channels, size_t stride, uint32_t* cost,
                       uint8_t* out) {
  const __m128i zero = _mm_setzero_si128(), bias = _mm_set1_epi8(char(0x80));
  __m128i sums[5] = {zero, zero, zero, zero, zero};
  const auto store_paeth = [&](size_t x, __m128i filtered) {
    _mm_storeu_si128(reinterpret_cast<__m128i*>(out + x), filtered);
  };
  const auto sample = [&](size_t x) {
    const Sixteen s(row, up, channels, x);
    const __m128i f[5] = {s.r, _mm_sub_epi8(s.r, s.a), _mm_sub_epi8(s.r, s.b), _mm_sub_epi8(s.r, s.average()),
                          _mm_sub_epi8(s.r, s.paeth_predictor())};
    for (int i = 0; i < 5; ++i) sums[i] = _mm_add_epi64(sums[i], _mm_sad_epu8(_mm_xor_si128(f[i], bias), bias));
    store_paeth(x, f[kPaeth]);
  };
  size_t x = channels;
  for (; x + 32 <= stride; x += 32) {
    sample(x);
    store_paeth(x + 16, Sixteen(row, up, channels, x + 16).filtered(kPaeth));
  }
  if (x + 16 <= stride) sample(x), x += 16;
  if (x < stride) store_paeth(stride - 16, Sixteen(row, up, channels, stride - 16).filtered(kPaeth));  // overlapping
  for (int i = 0; i < 5; ++i) cost[i] += uint32_t(_mm_cvtsi128_si32(sums[i]) + _mm_cvtsi128_si32(_mm_srli_si128(sums[i], 8)));
}

// Bytes [channels, stride) of a row filtered by `type` into out (stride >= channels + 16).
void apply_filter_sse2(int type, const uint8_t* row, const uint8_t* up, size_t channels, size_t stride, uint8_t* out) {
  const auto store = [&](size_t x) {
    _mm_storeu_si128(reinterpret_cast<__m128i*>(out + x), Sixteen(row, up, channels, x).filtered(type));
  };
  size_t x = channels;
  for (; x + 16 <= stride; x += 16) store(x);
  if (x < stride) store(stride - 16);  // the same bytes again where they overlap
}
#endif

// One row, filtered into out[0] (the filter type) and out[1..stride]; `up` is the row
// above (zeros for the first). The filter is the one whose bytes' magnitudes sum least
// (the first of equals; over a sample of a long row's bytes); only its bytes are written.
void filter_row(const uint8_t* row, const uint8_t* up, size_t stride, size_t channels, uint8_t* out) {
  uint32_t cost[5] = {0, 0, 0, 0, 0};  // a row is at most 2^31 / 128 bytes (PNG's width limit times 4)
  bool wide = false;
#ifdef __SSE2__
  wide = stride >= channels + 16;
#endif
  for (size_t x = 0; x < (wide ? channels : stride); ++x) {
    const auto [a, b, c] = neighbours(row, up, channels, x);
    for (int type = 0; type < 5; ++type) cost[type] += magnitude(filtered_byte(type, row[x], a, b, c));
  }
#ifdef __SSE2__
  if (wide) filter_costs_sse2(row, up, channels, stride, cost, out + 1);
#endif
  const int best = int(std::min_element(cost, cost + 5) - cost);
  out[0] = uint8_t(best);
  uint8_t* bytes = out + 1;
  for (size_t x = 0; x < (wide ? channels : stride); ++x) {
    const auto [a, b, c] = neighbours(row, up, channels, x);
    bytes[x] = filtered_byte(best, row[x], a, b, c);
  }
#ifdef __SSE2__
  if (wide && best != kPaeth) apply_filter_sse2(best, row, up, channels, stride, bytes);  // Paeth's are there
#endif
}

struct CompressorFree {
  void operator()(libdeflate_compressor* c) const { libdeflate_free_compressor(c); }
};

}  // namespace

namespace {

// The PNG of `height` rows of `stride` bytes each (`channels` bytes a pixel), with its
// colour type and the chunks that go before the pixels (a palette).
std::vector<uint8_t> encode_rows(int width, int height, const uint8_t* rows, size_t channels, uint8_t colour_type,
                                 const std::vector<std::pair<const char*, std::vector<uint8_t>>>& before_pixels,
                                 PngDeflate how) {
  const size_t stride = size_t(width) * channels;
  thread_local std::vector<uint8_t> filtered, zeros, deflated;
  filtered.resize(size_t(height) * (stride + 1));
  zeros.assign(stride, 0);
  for (int y = 0; y < height; ++y)
    filter_row(rows + size_t(y) * stride, y ? rows + size_t(y - 1) * stride : zeros.data(), stride, channels,
               &filtered[size_t(y) * (stride + 1)]);

  size_t deflated_size = 0;
  if (how == PngDeflate::kRuns) {
    deflated.clear();
    deflate_runs(filtered, deflated);
    deflated_size = deflated.size();
  } else {
    thread_local std::unique_ptr<libdeflate_compressor, CompressorFree> compressor(libdeflate_alloc_compressor(kDeflateLevel));
    if (!compressor) throw Error("cannot encode PNG: out of memory");
    deflated.resize(libdeflate_zlib_compress_bound(compressor.get(), filtered.size()));
    deflated_size = libdeflate_zlib_compress(compressor.get(), filtered.data(), filtered.size(), deflated.data(), deflated.size());
    if (deflated_size == 0) throw Error("cannot encode PNG");
  }

  std::vector<uint8_t> out = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  out.reserve(1100 + deflated_size);
  std::vector<uint8_t> header;
  put32(header, uint32_t(width));
  put32(header, uint32_t(height));
  header.insert(header.end(), {8, colour_type, 0, 0, 0});  // 8 bits, deflate, adaptive filters, no interlace
  chunk(out, "IHDR", header);
  for (const auto& [type, data] : before_pixels) chunk(out, type, data);
  chunk(out, "IDAT", std::span(deflated.data(), deflated_size));
  chunk(out, "IEND", {});
  return out;
}

}  // namespace

std::vector<uint8_t> encode_png(const Image& image, PngDeflate how) {
  if (image.width <= 0 || image.height <= 0) throw Error("cannot encode an empty image as PNG");
  uint32_t all = ~0u;  // the bits set in every pixel: opaque when all of alpha's are
  for (const uint32_t p : image.pixels) all &= p;
  const bool opaque = (all >> 24) == 255;
  const size_t channels = opaque ? 3 : 4;
  // Buffers kept from frame to frame: fresh ones of this size cost a page fault per 4 KB.
  thread_local std::vector<uint8_t> rows;
  rows.resize(image.pixels.size() * channels + 1);  // pixels as bytes, R G B (A); one byte of room
  if (channels == 4) {
    std::memcpy(rows.data(), image.pixels.data(), image.pixels.size() * 4);  // R, G, B, A in memory already
  } else {  // each pixel's four bytes stored 3 apart, its alpha overwritten by the next one's red
    uint8_t* o = rows.data();
    for (const uint32_t p : image.pixels) std::memcpy(o, &p, 4), o += 3;
  }
  return encode_rows(image.width, image.height, rows.data(), channels, opaque ? 2 : 6, {}, how);  // RGB or RGBA
}

std::vector<uint8_t> encode_png(int width, int height, std::span<const uint8_t> indices, std::span<const uint32_t> palette,
                                PngDeflate how) {
  if (width <= 0 || height <= 0) throw Error("cannot encode an empty image as PNG");
  if (indices.size() != size_t(width) * size_t(height) || palette.empty() || palette.size() > 256)
    throw Error("cannot encode PNG: the indices do not fill the image, or the palette is not 1 to 256 colours");
  std::vector<uint8_t> colours, alphas;
  for (const uint32_t c : palette) colours.insert(colours.end(), {uint8_t(red(c)), uint8_t(green(c)), uint8_t(blue(c))});
  if (!std::all_of(palette.begin(), palette.end(), [](uint32_t c) { return c >> 24 == 255; }))
    for (const uint32_t c : palette) alphas.push_back(uint8_t(c >> 24));
  if (palette.size() < 256)  // else every byte is a colour of it
    for (const uint8_t i : indices)
      if (i >= palette.size()) throw Error("cannot encode PNG: an index outside the palette");
  std::vector<std::pair<const char*, std::vector<uint8_t>>> chunks{{"PLTE", std::move(colours)}};
  if (!alphas.empty()) chunks.push_back({"tRNS", std::move(alphas)});
  return encode_rows(width, height, indices.data(), 1, 3, chunks, how);
}

}  // namespace p3d::image
