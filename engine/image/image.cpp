#include "engine/image/image.h"

#include <stb_image.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>

#include "engine/util/error.h"
#include "engine/util/file.h"

namespace p3d::image {

namespace {

constexpr int kMaxDimension = 16384;

uint32_t heat(double v) {  // v in [0,1]: black -> blue -> red -> yellow -> white
  v = std::clamp(v, 0.0, 1.0);
  const double stops[5][3] = {{0, 0, 0}, {0, 0, 200}, {220, 0, 0}, {255, 220, 0}, {255, 255, 255}};
  const double f = v * 4;
  const int i = std::min(3, static_cast<int>(f));
  const double t = f - i;
  auto mix = [&](int c) { return static_cast<uint32_t>(stops[i][c] + (stops[i + 1][c] - stops[i][c]) * t + 0.5); };
  return rgba(mix(0), mix(1), mix(2));
}

}  // namespace

Image decode_png(std::span<const uint8_t> bytes, const std::string& what) {
  if (bytes.size() > static_cast<size_t>(std::numeric_limits<int>::max())) throw Error(what + ": file too large");
  static constexpr uint8_t kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  if (bytes.size() < 8 || std::memcmp(bytes.data(), kSignature, 8) != 0) throw Error(what + ": not a PNG image");
  int w = 0, h = 0, channels = 0;
  if (!stbi_info_from_memory(bytes.data(), static_cast<int>(bytes.size()), &w, &h, &channels))
    throw Error(what + ": not a readable image (" + stbi_failure_reason() + ")");
  if (w <= 0 || h <= 0 || w > kMaxDimension || h > kMaxDimension)
    throw Error(what + ": image size " + std::to_string(w) + "x" + std::to_string(h) + " is out of range");
  unsigned char* data = stbi_load_from_memory(bytes.data(), static_cast<int>(bytes.size()), &w, &h, &channels, 4);
  if (!data) throw Error(what + ": cannot decode image (" + stbi_failure_reason() + ")");
  Image img(w, h);
  std::memcpy(img.pixels.data(), data, img.pixels.size() * 4);
  stbi_image_free(data);
  return img;
}

Image load_png(const std::filesystem::path& path) { return decode_png(read_file_bytes(path), path.string()); }

void save_png(const Image& image, const std::filesystem::path& path) {
  write_file_atomically(path, encode_png(image));
}

Difference compare(const Image& a, const Image& b, int channel_tolerance) {
  Difference d;
  for (size_t i = 0; i < a.pixels.size(); ++i) {
    const uint32_t p = a.pixels[i], q = b.pixels[i];
    if (p == q) continue;
    const int delta = std::max({std::abs(int(red(p)) - int(red(q))), std::abs(int(green(p)) - int(green(q))),
                                std::abs(int(blue(p)) - int(blue(q))), std::abs(int(p >> 24) - int(q >> 24))});
    d.max_channel_delta = std::max(d.max_channel_delta, delta);
    if (delta > channel_tolerance) ++d.differing_pixels;
  }
  return d;
}

Image difference_heat_map(const Image& a, const Image& b) {
  Image out(a.width, a.height);
  for (size_t i = 0; i < a.pixels.size(); ++i) {
    const uint32_t p = a.pixels[i], q = b.pixels[i];
    if (p == q) continue;
    const int delta = std::abs(int(red(p)) - int(red(q))) + std::abs(int(green(p)) - int(green(q))) +
                      std::abs(int(blue(p)) - int(blue(q)));
    out.pixels[i] = heat(0.25 + 0.75 * delta / 765.0);
  }
  return out;
}

Image count_heat_map(int width, int height, std::span<const uint16_t> counts, int max_count) {
  Image out(width, height);
  for (size_t i = 0; i < out.pixels.size(); ++i)
    out.pixels[i] = counts[i] == 0 ? rgba(0, 0, 0) : heat(double(counts[i]) / std::max(1, max_count));
  return out;
}

void blit(Image& dst, const Image& src, int x, int y) {
  for (int sy = 0; sy < src.height; ++sy) {
    const int dy = y + sy;
    if (dy < 0 || dy >= dst.height) continue;
    for (int sx = 0; sx < src.width; ++sx) {
      const int dx = x + sx;
      if (dx >= 0 && dx < dst.width) dst.at(dx, dy) = src.at(sx, sy);
    }
  }
}

}  // namespace p3d::image
