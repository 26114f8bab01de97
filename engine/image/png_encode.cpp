// PNG encoding: each row filtered by whichever of PNG's five filters leaves the
// smallest sum of absolute differences (libpng's heuristic, png_filters.h), the rows
// deflated in one zlib stream: as runs and literals (deflate_runs.h), or by
// libdeflate's search. An opaque image is written as RGB, else RGBA; an 8-bit frame as
// palette indices. The bytes depend only on the pixels: captures are reproducible on
// any thread count and any processor.
#include <libdeflate.h>

#include <algorithm>
#include <cstring>
#include <memory>

#include "engine/image/deflate_runs.h"
#include "engine/image/image.h"
#include "engine/image/png_filters.h"
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

struct CompressorFree {
  void operator()(libdeflate_compressor* c) const { libdeflate_free_compressor(c); }
};

// The PNG of `height` rows of `stride` bytes each (`channels` bytes a pixel), with its
// colour type and the chunks that go before the pixels (a palette).
std::vector<uint8_t> encode_rows(int width, int height, const uint8_t* rows, size_t channels, uint8_t colour_type,
                                 const std::vector<std::pair<const char*, std::vector<uint8_t>>>& before_pixels,
                                 PngDeflate how) {
  const size_t stride = size_t(width) * channels;
  thread_local std::vector<uint8_t> filtered, zeros, deflated;
  zeros.assign(stride, 0);
  auto filter = [&](int y, uint8_t* out) {
    filter_row(rows + size_t(y) * stride, y ? rows + size_t(y - 1) * stride : zeros.data(), stride, channels, out);
  };

  size_t deflated_size = 0;
  if (how == PngDeflate::kRuns) {  // each row deflated as it is filtered: the filtered bytes stay in the cache
    deflated.clear();
    DeflateRuns deflater(deflated);
    for (int y = 0; y < height; ++y) {
      filter(y, deflater.room(stride + 1));
      deflater.wrote(stride + 1);
    }
    deflater.finish();
    deflated_size = deflated.size();
  } else {
    filtered.resize(size_t(height) * (stride + 1));
    for (int y = 0; y < height; ++y) filter(y, &filtered[size_t(y) * (stride + 1)]);
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
  // Buffers kept from frame to frame: fresh ones of this size cost a page fault per 4 KB.
  thread_local std::vector<uint8_t> rows;
  const size_t n = image.pixels.size();
  rows.resize(n * 4 + 1);  // pixels as bytes, R G B (A); one byte of room
  // Packed as RGB in the pass that finds whether every pixel is opaque (the bits set in
  // every pixel: opaque when all of alpha's are); else copied again as RGBA. Four
  // pixels go to twelve bytes in two stores (R, G, B, A in memory: little-endian).
  const uint32_t* p = image.pixels.data();
  uint8_t* o = rows.data();
  uint32_t all = ~0u;
  size_t i = 0;
  for (; i + 4 <= n; i += 4, o += 12) {
    const uint32_t a = p[i], b = p[i + 1], c = p[i + 2], d = p[i + 3];
    all &= a & b & c & d;
    const uint64_t first = uint64_t(a & 0xFFFFFF) | uint64_t(b & 0xFFFFFF) << 24 | uint64_t(c) << 48;
    const uint32_t second = (c >> 16 & 0xFF) | (d & 0xFFFFFF) << 8;
    std::memcpy(o, &first, 8), std::memcpy(o + 8, &second, 4);
  }
  for (; i < n; ++i, o += 3) all &= p[i], std::memcpy(o, &p[i], 4);  // its alpha overwritten by the next red
  const bool opaque = (all >> 24) == 255;
  const size_t channels = opaque ? 3 : 4;
  if (!opaque) std::memcpy(rows.data(), p, n * 4);
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
