// PNG encoding: each row filtered by whichever of PNG's five filters leaves the
// smallest sum of absolute differences (libpng's heuristic), the rows deflated in one
// zlib stream by libdeflate. An opaque image is written as RGB, else RGBA. The bytes
// depend only on the pixels: captures are reproducible on any thread count.
#include <libdeflate.h>

#include <cstdlib>
#include <cstring>
#include <memory>

#include "engine/image/image.h"
#include "engine/util/error.h"

namespace p3d::image {

namespace {

// Level 1-12; 2 writes files smaller than stb_image_write's at a fifth of its time
// (bench: README, "Capture speed").
constexpr int kDeflateLevel = 2;

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

// One row, filtered into out[0] (the filter type) and out[1..stride]; `up` is the row
// above (zeros for the first). Each filter is a loop of its own, without branches, so
// the compiler vectorises it.
void filter_row(const uint8_t* row, const uint8_t* up, size_t stride, size_t channels, uint8_t* scratch, uint8_t* out) {
  uint8_t* filtered[5];
  for (int f = 0; f < 5; ++f) filtered[f] = scratch + size_t(f) * stride;
  const auto filter = [&](size_t x, int a, int b, int c) {  // a: left, b: up, c: up-left
    const int pa = std::abs(b - c), pb = std::abs(a - c), pc = std::abs(a + b - 2 * c);
    const int paeth = pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
    filtered[0][x] = row[x];
    filtered[1][x] = uint8_t(row[x] - a);
    filtered[2][x] = uint8_t(row[x] - b);
    filtered[3][x] = uint8_t(row[x] - ((a + b) >> 1));
    filtered[4][x] = uint8_t(row[x] - paeth);
  };
  for (size_t x = 0; x < channels; ++x) filter(x, 0, up[x], 0);
  for (size_t x = channels; x < stride; ++x) filter(x, row[x - channels], up[x], up[x - channels]);
  int best = 0;
  uint64_t best_cost = UINT64_MAX;
  for (int f = 0; f < 5; ++f) {
    uint64_t cost = 0;  // each byte as a signed difference's magnitude
    for (size_t x = 0; x < stride; ++x) cost += uint64_t(std::abs(int(int8_t(filtered[f][x]))));
    if (cost < best_cost) best = f, best_cost = cost;
  }
  out[0] = uint8_t(best);
  std::memcpy(out + 1, filtered[best], stride);
}

struct CompressorFree {
  void operator()(libdeflate_compressor* c) const { libdeflate_free_compressor(c); }
};

}  // namespace

std::vector<uint8_t> encode_png(const Image& image) {
  if (image.width <= 0 || image.height <= 0) throw Error("cannot encode an empty image as PNG");
  bool opaque = true;
  for (uint32_t p : image.pixels) opaque = opaque && (p >> 24) == 255;
  const int channels = opaque ? 3 : 4;
  const size_t stride = size_t(image.width) * channels;

  std::vector<uint8_t> rows(size_t(image.height) * stride);  // pixels as bytes, R G B (A)
  for (size_t i = 0; i < image.pixels.size(); ++i) {
    const uint32_t p = image.pixels[i];
    uint8_t* o = &rows[i * channels];
    o[0] = uint8_t(p), o[1] = uint8_t(p >> 8), o[2] = uint8_t(p >> 16);
    if (channels == 4) o[3] = uint8_t(p >> 24);
  }
  std::vector<uint8_t> filtered(size_t(image.height) * (stride + 1)), scratch(5 * stride), zeros(stride);
  for (int y = 0; y < image.height; ++y)
    filter_row(&rows[size_t(y) * stride], y ? &rows[size_t(y - 1) * stride] : zeros.data(), stride, size_t(channels),
               scratch.data(), &filtered[size_t(y) * (stride + 1)]);

  thread_local std::unique_ptr<libdeflate_compressor, CompressorFree> compressor(libdeflate_alloc_compressor(kDeflateLevel));
  if (!compressor) throw Error("cannot encode PNG: out of memory");
  std::vector<uint8_t> deflated(libdeflate_zlib_compress_bound(compressor.get(), filtered.size()));
  deflated.resize(
      libdeflate_zlib_compress(compressor.get(), filtered.data(), filtered.size(), deflated.data(), deflated.size()));
  if (deflated.empty()) throw Error("cannot encode PNG");

  std::vector<uint8_t> out = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  std::vector<uint8_t> header;
  put32(header, uint32_t(image.width));
  put32(header, uint32_t(image.height));
  header.insert(header.end(), {8, uint8_t(opaque ? 2 : 6), 0, 0, 0});  // 8 bits, RGB or RGBA, deflate, adaptive, no interlace
  chunk(out, "IHDR", header);
  chunk(out, "IDAT", deflated);
  chunk(out, "IEND", {});
  return out;
}

}  // namespace p3d::image
