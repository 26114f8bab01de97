// The PNG encoder at each kind of level (stored, runs, libdeflate's search) against
// stb_image's decoder (an inflater of its own): every image comes back pixel for pixel.
// The first two bytes choose the width, whether the image is paletted or opaque, the
// level and how many times each byte repeats (runs, for deflate_runs' matches); the rest
// are its pixels.
#include <algorithm>
#include <cstdlib>

#include "engine/image/image.h"
#include "engine/util/error.h"
#include "tests/fuzz/target.h"

using namespace p3d;

namespace {

// A distinct colour for each index, some of them not opaque.
uint32_t palette_colour(size_t i) { return image::rgba(int(i), int(255 - i), int(i * 7 % 256), i % 5 ? 255 : int(i)); }

}  // namespace

// Rows enough for any step of the encoder; decode_png reads sides up to 16384 only.
constexpr size_t kMaxRows = 4096;

P3D_FUZZ_TARGET(encode) {
  if (size < 3) return 0;
  const int width = 1 + int(data[0]) * 3 % 300;  // past 16 and 48 bytes a row: the filters' SSE2 steps
  const bool paletted = data[1] & 1, opaque = data[1] & 2;
  constexpr int kLevels[4] = {image::kPngStored, image::kPngRuns, 2, image::kPngMaxLevel};
  const int level = kLevels[data[1] >> 2 & 3];
  const size_t repeat = 1 + (data[1] >> 4) % 12;
  std::vector<uint8_t> bytes;
  for (size_t i = 2; i < size; ++i) bytes.insert(bytes.end(), repeat, data[i]);

  std::vector<uint32_t> expected;
  std::vector<uint8_t> png;
  if (paletted) {
    const size_t colours = 1 + bytes[0];
    const size_t height = std::min(kMaxRows, (bytes.size() - 1) / size_t(width));
    if (height == 0) return 0;
    std::vector<uint32_t> palette;
    for (size_t i = 0; i < colours; ++i) palette.push_back(palette_colour(i));
    std::vector<uint8_t> indices(size_t(width) * height);
    for (size_t p = 0; p < indices.size(); ++p) {
      indices[p] = uint8_t(bytes[1 + p] % colours);
      expected.push_back(palette[indices[p]]);
    }
    png = image::encode_png(width, int(height), indices, palette, level);
  } else {
    const size_t height = std::min(kMaxRows, bytes.size() / 4 / size_t(width));
    if (height == 0) return 0;
    image::Image img(width, int(height));
    for (size_t p = 0; p < img.pixels.size(); ++p) {
      const uint8_t* b = &bytes[4 * p];
      img.pixels[p] = image::rgba(b[0], b[1], b[2], opaque ? 255 : b[3]);
    }
    expected = img.pixels;
    png = image::encode_png(img, level);
  }
  const image::Image back = image::decode_png(png, "encoded");
  if (back.width != width || back.pixels != expected) std::abort();  // not what was encoded
  return 0;
}
