// The PNG encoder against the decoder (stb_image, independent of it): every pixel
// back exactly, opaque images as RGB and others as RGBA, 8-bit frames as palette
// indices, any size, deflated either way; the same pixels give the same bytes.
#include <gtest/gtest.h>

#include "engine/image/image.h"
#include "engine/util/error.h"
#include "engine/util/rng.h"

namespace p3d::image {
namespace {

Image noise(int w, int h, uint64_t seed, bool opaque) {
  Rng rng(seed);
  Image img(w, h);
  for (uint32_t& p : img.pixels) {
    p = uint32_t(rng.next());
    if (opaque) p |= 0xFF000000u;
  }
  return img;
}

// Smooth gradients and flat areas: every filter wins somewhere.
Image picture(int w, int h) {
  Image img(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      img.at(x, y) = x < w / 3 ? rgba(uint8_t(x * 3), uint8_t(y * 2), 40)
                     : y < h / 2 ? rgba(200, 10, 10)
                                 : rgba(uint8_t((x ^ y) & 0xFF), uint8_t(x + y), uint8_t(x * y));
  return img;
}

uint8_t color_type(const std::vector<uint8_t>& png) { return png.at(25); }  // IHDR's colour type byte

constexpr PngDeflate kBothWays[] = {PngDeflate::kRuns, PngDeflate::kSearch};

TEST(Png, EncodesEveryPixelExactly) {
  for (const auto& [w, h] : {std::pair{1, 1}, {3, 2}, {17, 5}, {640, 400}, {1, 300}, {301, 1}}) {
    for (const auto& [opaque, how] : {std::pair{true, PngDeflate::kRuns}, {false, PngDeflate::kRuns},
                                     {true, PngDeflate::kSearch}, {false, PngDeflate::kSearch}}) {
      const Image img = noise(w, h, uint64_t(w * 1000 + h), opaque);
      const std::vector<uint8_t> png = encode_png(img, how);
      EXPECT_EQ(color_type(png), opaque ? 2 : 6) << w << "x" << h;
      const Image back = decode_png(png, "x.png");
      ASSERT_EQ(back.width, w);
      ASSERT_EQ(back.height, h);
      EXPECT_EQ(back.pixels, img.pixels) << w << "x" << h << (opaque ? " opaque" : " with alpha");
    }
  }
  const Image art = picture(320, 200);
  for (const PngDeflate how : kBothWays) {
    const std::vector<uint8_t> png = encode_png(art, how);
    EXPECT_EQ(decode_png(png, "x.png").pixels, art.pixels);
    EXPECT_LT(png.size(), art.pixels.size() * 3 / 4);  // it compresses
    EXPECT_EQ(encode_png(art, how), png);                // and deterministically
  }
}

TEST(Png, AnEmptyImageIsAnError) { EXPECT_THROW(encode_png(Image(0, 0)), Error); }

// Indices into a palette of `colours` random colours, smooth in places (so filters matter).
struct Paletted {
  int width, height;
  std::vector<uint8_t> indices;
  std::vector<uint32_t> palette;
  Image colours() const {
    Image img(width, height);
    for (size_t i = 0; i < indices.size(); ++i) img.pixels[i] = palette[indices[i]];
    return img;
  }
};
Paletted paletted(int w, int h, int colours, bool opaque, uint64_t seed) {
  Rng rng(seed);
  Paletted p{w, h, {}, {}};
  for (int i = 0; i < colours; ++i) p.palette.push_back(uint32_t(rng.next()) | (opaque ? 0xFF000000u : 0));
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) p.indices.push_back(uint8_t(x < w / 2 ? (x + y) % colours : int(rng.below(uint64_t(colours)))));
  return p;
}

TEST(Png, EncodesPaletteIndicesExactly) {
  for (const auto& [w, h] : {std::pair{1, 1}, {3, 2}, {17, 5}, {640, 400}, {1, 300}, {301, 1}}) {
    for (const int colours : {1, 7, 256}) {
      for (bool opaque : {true, false}) {
        const Paletted p = paletted(w, h, colours, opaque, uint64_t(w * 1000 + h + colours));
        for (const PngDeflate how : kBothWays) {
          const std::vector<uint8_t> png = encode_png(w, h, p.indices, p.palette, how);
          EXPECT_EQ(color_type(png), 3) << w << "x" << h;
          EXPECT_EQ(decode_png(png, "x.png").pixels, p.colours().pixels) << w << "x" << h << ", " << colours << " colours";
          EXPECT_EQ(encode_png(w, h, p.indices, p.palette, how), png);
        }
      }
    }
  }
  // A quarter of the bytes to compress: an 8-bit frame's PNG is smaller than its colours'.
  const Paletted p = paletted(320, 200, 256, true, 5);
  EXPECT_LT(encode_png(320, 200, p.indices, p.palette).size(), encode_png(p.colours()).size());
}

TEST(Png, PaletteIndicesThatDoNotFitAreAnError) {
  const Paletted p = paletted(8, 8, 7, true, 1);
  EXPECT_THROW(encode_png(8, 7, p.indices, p.palette), Error);                              // too many indices
  EXPECT_THROW(encode_png(8, 8, p.indices, std::span(p.palette).first(3)), Error);          // an index past the palette
  EXPECT_THROW(encode_png(8, 8, p.indices, {}), Error);                                     // no palette
  EXPECT_THROW(encode_png(8, 8, p.indices, std::vector<uint32_t>(257, 0xFF000000u)), Error);  // more than 256 colours
  EXPECT_THROW(encode_png(0, 0, {}, p.palette), Error);
}

}  // namespace
}  // namespace p3d::image
