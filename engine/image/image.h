// RGBA8 images (row-major, one uint32 per pixel laid out R,G,B,A in memory),
// PNG encoding/decoding through stb, and image comparison.
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace p3d::image {

// Packs a colour so that its bytes in memory are R, G, B, A (little-endian host).
constexpr uint32_t rgba(uint32_t r, uint32_t g, uint32_t b, uint32_t a = 255) {
  return r | (g << 8) | (b << 16) | (a << 24);
}
constexpr uint32_t red(uint32_t c) { return c & 0xFF; }
constexpr uint32_t green(uint32_t c) { return (c >> 8) & 0xFF; }
constexpr uint32_t blue(uint32_t c) { return (c >> 16) & 0xFF; }

struct Image {
  int width = 0, height = 0;
  std::vector<uint32_t> pixels;

  Image() = default;
  Image(int w, int h, uint32_t fill = rgba(0, 0, 0)) : width(w), height(h), pixels(size_t(w) * h, fill) {}
  uint32_t& at(int x, int y) { return pixels[size_t(y) * width + x]; }
  uint32_t at(int x, int y) const { return pixels[size_t(y) * width + x]; }
};

// Decodes a PNG (any channel count) to RGBA8; throws Error("<what>: ...") on bad data.
Image decode_png(std::span<const uint8_t> bytes, const std::string& what);
Image load_png(const std::filesystem::path& path);
// How hard encode_png squeezes a PNG, on zlib's scale of levels (docs/benchmarks.md,
// "Threads and captures", has each level's time and bytes): 0 stores the rows as they
// are, unfiltered (the fastest: a frame's PNG in a sixth to two thirds of its render's
// time, at 4 to 12 times level 1's bytes); 1, the default, filters each row (a palette
// image's by Paeth alone) and deflates it as runs and literals (deflate_runs.h); 2 to
// 12 filter each row by the least sum of differences, then deflate with libdeflate's
// search for matches at that level, in 3 to 430 times level 1's time:
// level 2's 8-bit frames a tenth bigger than level 1's, level 12's the smallest (9-26%
// smaller).
constexpr int kPngStored = 0, kPngRuns = 1, kPngDefaultLevel = kPngRuns, kPngMaxLevel = 12;
// Throws Error for a level outside [0, kPngMaxLevel].
std::vector<uint8_t> encode_png(const Image& image, int level = kPngDefaultLevel);
// A paletted PNG: indices (row-major, width x height) into palette (1 to 256 colours,
// RGBA; a tRNS chunk only when one is not opaque). Throws Error on a mismatch.
std::vector<uint8_t> encode_png(int width, int height, std::span<const uint8_t> indices, std::span<const uint32_t> palette,
                                int level = kPngDefaultLevel);
void save_png(const Image& image, const std::filesystem::path& path);  // atomic

struct Difference {
  size_t differing_pixels = 0;  // pixels where some channel differs by more than the tolerance
  int max_channel_delta = 0;
  double fraction(const Image& a) const { return a.pixels.empty() ? 0 : double(differing_pixels) / a.pixels.size(); }
};
// Images must have the same size.
Difference compare(const Image& a, const Image& b, int channel_tolerance = 0);

// Per-pixel |a - b| as a heat map: black where equal, then blue -> red -> yellow.
Image difference_heat_map(const Image& a, const Image& b);

// A heat map of per-pixel counts (0 = black, 1 = dark blue, ..., max_count and above = white).
Image count_heat_map(int width, int height, std::span<const uint16_t> counts, int max_count);

// Copies src into dst at (x, y), clipped to dst.
void blit(Image& dst, const Image& src, int x, int y);

}  // namespace p3d::image
