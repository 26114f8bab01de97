// The PNG encoder against the decoder (stb_image, independent of it): every pixel
// back exactly, opaque images as RGB and others as RGBA, 8-bit frames as palette
// indices, any size, at every kind of level (stored, runs, libdeflate's search); the
// same pixels give the same bytes.
#include <libdeflate.h>

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "engine/image/image.h"
#include "engine/image/png_filters.h"
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

// Stored, runs and literals, libdeflate's search at its fastest and its best.
constexpr int kLevels[] = {kPngStored, kPngRuns, 2, kPngMaxLevel};

TEST(Png, EncodesEveryPixelExactly) {
  for (const auto& [w, h] : {std::pair{1, 1}, {3, 2}, {17, 5}, {640, 400}, {1, 300}, {301, 1}}) {
    for (const auto& [opaque, level] : {std::pair{true, kPngStored}, {false, kPngStored}, {true, kPngRuns},
                                       {false, kPngRuns}, {true, 2}, {false, 2}}) {
      const Image img = noise(w, h, uint64_t(w * 1000 + h), opaque);
      const std::vector<uint8_t> png = encode_png(img, level);
      EXPECT_EQ(color_type(png), opaque ? 2 : 6) << w << "x" << h;
      const Image back = decode_png(png, "x.png");
      ASSERT_EQ(back.width, w);
      ASSERT_EQ(back.height, h);
      EXPECT_EQ(back.pixels, img.pixels) << w << "x" << h << (opaque ? " opaque" : " with alpha") << ", level "
                                         << level;
    }
  }
  const Image art = picture(320, 200);
  size_t previous = 0;
  for (const int level : kLevels) {
    const std::vector<uint8_t> png = encode_png(art, level);
    EXPECT_EQ(decode_png(png, "x.png").pixels, art.pixels) << "level " << level;
    if (level == kPngStored) {
      EXPECT_GT(png.size(), art.pixels.size() * 3);  // every byte of every row, and a filter byte a row
    } else {
      EXPECT_LT(png.size(), previous) << "level " << level;  // each level smaller than the one before
    }
    previous = png.size();
    EXPECT_EQ(encode_png(art, level), png);  // and deterministically
  }
}

TEST(Png, AnEmptyImageOrALevelOutOfRangeIsAnError) {
  EXPECT_THROW(encode_png(Image(0, 0)), Error);
  EXPECT_THROW(encode_png(Image(2, 2), -1), Error);
  EXPECT_THROW(encode_png(Image(2, 2), kPngMaxLevel + 1), Error);
}

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
        for (const int level : kLevels) {
          const std::vector<uint8_t> png = encode_png(w, h, p.indices, p.palette, level);
          EXPECT_EQ(color_type(png), 3) << w << "x" << h;
          EXPECT_EQ(decode_png(png, "x.png").pixels, p.colours().pixels)
              << w << "x" << h << ", " << colours << " colours, level " << level;
          EXPECT_EQ(encode_png(w, h, p.indices, p.palette, level), png);
        }
      }
    }
  }
  // A quarter of the bytes to compress: an 8-bit frame's PNG is smaller than its colours'.
  const Paletted p = paletted(320, 200, 256, true, 5);
  EXPECT_LT(encode_png(320, 200, p.indices, p.palette).size(), encode_png(p.colours()).size());
}

// A PNG's IDAT chunks inflated (libdeflate): its rows as filtered, each after its
// filter's byte; `size` bytes expected.
std::vector<uint8_t> inflated_rows(const std::vector<uint8_t>& png, size_t size) {
  const auto be32 = [&](size_t at) {
    return uint32_t(png[at]) << 24 | uint32_t(png[at + 1]) << 16 | uint32_t(png[at + 2]) << 8 | png[at + 3];
  };
  std::vector<uint8_t> idat;
  for (size_t at = 8; at + 12 <= png.size(); at += 12 + be32(at))
    if (std::string(png.begin() + long(at) + 4, png.begin() + long(at) + 8) == "IDAT")
      idat.insert(idat.end(), png.begin() + long(at) + 8, png.begin() + long(at + 8 + be32(at)));
  std::vector<uint8_t> rows(size);
  libdeflate_decompressor* d = libdeflate_alloc_decompressor();
  const libdeflate_result r = libdeflate_zlib_decompress(d, idat.data(), idat.size(), rows.data(), rows.size(), nullptr);
  libdeflate_free_decompressor(d);
  EXPECT_EQ(r, LIBDEFLATE_SUCCESS);
  return rows;
}

// The filter type of each row of a PNG.
std::vector<int> row_filters(const std::vector<uint8_t>& png, int width, int height, size_t channels) {
  const size_t stride = size_t(width) * channels + 1;
  const std::vector<uint8_t> rows = inflated_rows(png, stride * size_t(height));
  std::vector<int> filters;
  for (int y = 0; y < height; ++y) filters.push_back(rows[size_t(y) * stride]);
  return filters;
}

// Level 0 stores each row as it is, after None's filter byte, in blocks of at most
// 65,535 bytes (libdeflate checks each block's length against its complement): at
// widths whose rows end before, at and after a block's end.
TEST(Png, StoredRowsAreTheImagesBytes) {
  for (const int width : {1, 255, 256, 257, 65534, 65535, 65536}) {
    const int height = width > 300 ? 3 : 600;
    const Paletted p = paletted(width, height, 256, true, uint64_t(width));
    const std::vector<uint8_t> png = encode_png(width, height, p.indices, p.palette, kPngStored);
    std::vector<uint8_t> expected;
    for (int y = 0; y < height; ++y) {
      expected.push_back(0);
      expected.insert(expected.end(), p.indices.begin() + long(y) * width, p.indices.begin() + long(y + 1) * width);
    }
    EXPECT_EQ(inflated_rows(png, expected.size()), expected) << "width " << width;
    if (width <= 16384) {  // decode_png's largest side
      EXPECT_EQ(decode_png(png, "x.png").pixels, p.colours().pixels) << "width " << width;
    }
  }
}

// A filtered row put back (PNG's reconstruction, written here apart from the encoder).
std::vector<uint8_t> unfiltered(const uint8_t* filtered, const std::vector<uint8_t>& up, size_t channels) {
  const int type = filtered[0];
  std::vector<uint8_t> row(up.size());
  for (size_t x = 0; x < row.size(); ++x) {
    const int a = x >= channels ? row[x - channels] : 0, b = up[x], c = x >= channels ? up[x - channels] : 0;
    const int pa = std::abs(b - c), pb = std::abs(a - c), pc = std::abs(a + b - 2 * c);
    const int predicted = type == 0 ? 0 : type == 1 ? a : type == 2 ? b : type == 3 ? (a + b) / 2
                        : pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
    row[x] = uint8_t(filtered[x + 1] + predicted);
  }
  return row;
}

// The filter filter_row chooses for each row of a one-byte-a-pixel image, each row
// checked to come back exactly.
std::vector<int> chosen_filters(int width, int height, const std::vector<uint8_t>& bytes) {
  std::vector<int> filters;
  std::vector<uint8_t> up(size_t(width), 0), out(size_t(width) + 1);
  for (int y = 0; y < height; ++y) {
    const uint8_t* row = bytes.data() + size_t(y) * size_t(width);
    filter_row(row, up.data(), size_t(width), 1, out.data());
    EXPECT_EQ(unfiltered(out.data(), up, 1), std::vector<uint8_t>(row, row + width)) << "width " << width << ", row " << y;
    filters.push_back(out[0]);
    up.assign(row, row + width);
  }
  return filters;
}

// Widths around the encoder's steps of sixteen bytes (costed in samples, written whole).
constexpr int kFilterWidths[] = {5, 17, 31, 32, 33, 48, 49, 64, 65, 100, 301};

// Rows made for None, Sub, Up and Average in turn (each filter's bytes all zero, the
// others' not), between rows of noise: each is chosen, and comes back.
TEST(Png, EachFilterIsChosenWhereItIsBest) {
  for (const int width : kFilterWidths) {
    Rng rng{uint64_t(width)};
    const int height = 8;
    std::vector<uint8_t> indices(size_t(width * height));
    const auto at = [&](int x, int y) -> uint8_t& { return indices[size_t(y * width + x)]; };
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) {
        const int a = x ? at(x - 1, y) : 0, b = y ? at(x, y - 1) : 0;
        const int filter = y % 2 ? y / 2 : -1;  // odd rows: None, Sub, Up, Average; even rows: noise
        const int first = 1 + int(rng.below(255));  // Sub's row: one value, not zero (None would tie)
        const int value = filter == 0 ? 0 : filter == 1 ? (x ? a : first) : filter == 2 ? b : (a + b) / 2;
        at(x, y) = uint8_t(filter < 0 ? int(rng.below(256)) : value);
      }
    const std::vector<int> filters = chosen_filters(width, height, indices);
    for (int y = 1; y < height; y += 2) EXPECT_EQ(filters[size_t(y)], y / 2) << "width " << width << ", row " << y;
  }
}

// Paeth, the filter a rendered frame's rows choose most, is written on the way as the
// rows are costed: overlapping flat rectangles (walls, sprites) choose it in some rows
// and another filter in others, and every row comes back. As palette indices, every row
// is Paeth's.
TEST(Png, PaethRowsAndOthersComeBack) {
  for (const int width : kFilterWidths) {
    Rng rng{uint64_t(width)};
    const int height = 40;
    std::vector<uint8_t> indices(size_t(width * height));
    for (int k = 0; k < 60; ++k) {
      const int x0 = int(rng.below(uint64_t(width))), y0 = int(rng.below(height));
      const int x1 = std::min(width, x0 + 1 + int(rng.below(uint64_t(width))));
      const int y1 = std::min(height, y0 + 1 + int(rng.below(height)));
      const uint8_t v = uint8_t(rng.below(256));
      for (int y = y0; y < y1; ++y) std::fill_n(indices.begin() + y * width + x0, x1 - x0, v);
    }
    const std::vector<int> filters = chosen_filters(width, height, indices);
    EXPECT_NE(std::count(filters.begin(), filters.end(), 4), 0) << "width " << width;
    EXPECT_NE(std::count(filters.begin(), filters.end(), 4), height) << "width " << width;

    std::vector<uint32_t> grey(256);
    for (size_t i = 0; i < grey.size(); ++i) grey[i] = 0xFF000000u | uint32_t(i * 0x010101u);
    const std::vector<uint8_t> png = encode_png(width, height, indices, grey);
    EXPECT_EQ(row_filters(png, width, height, 1), std::vector<int>(size_t(height), 4)) << "width " << width;
    const Image back = decode_png(png, "x.png");
    for (size_t i = 0; i < indices.size(); ++i) ASSERT_EQ(back.pixels[i], grey[indices[i]]) << "width " << width;
  }
}

// The filters a byte at a time, sixteen and thirty-two bytes at a time (where this
// processor has AVX2) write the same bytes, which put the rows back; Paeth alone too. Widths around each
// step, one to four bytes a pixel.
TEST(Png, FiltersWriteTheSameBytesAtEveryWidth) {
  std::vector<FilterLanes> widths = {FilterLanes::kOne, FilterLanes::kSixteen};
  if (widest_filter_lanes() == FilterLanes::kThirtyTwo) widths.push_back(FilterLanes::kThirtyTwo);
  Rng rng{3};
  for (const size_t channels : {size_t(1), size_t(3), size_t(4)})
    for (size_t stride = channels; stride <= 200 * channels; stride += channels) {
      std::vector<uint8_t> up(stride), row(stride);
      for (size_t x = 0; x < stride; ++x) {
        up[x] = uint8_t(rng.below(4) ? x / 7 : rng.below(256));  // flat stretches, steps and noise
        row[x] = uint8_t(rng.below(3) ? up[x] + x / 11 : rng.below(256));
      }
      std::vector<uint8_t> first, first_paeth;
      for (const FilterLanes lanes : widths) {
        std::vector<uint8_t> out(stride + 1), paeth(stride + 1);
        filter_row(row.data(), up.data(), stride, channels, out.data(), lanes);
        paeth_row(row.data(), up.data(), stride, channels, paeth.data(), lanes);
        const std::string what = "stride " + std::to_string(stride) + ", " + std::to_string(channels) + " a pixel, " +
                                 std::to_string(int(lanes));
        EXPECT_EQ(unfiltered(out.data(), up, channels), row) << what;
        EXPECT_EQ(paeth[0], kPaethFilter) << what;
        EXPECT_EQ(unfiltered(paeth.data(), up, channels), row) << what << ", Paeth";
        if (first.empty()) {
          first = out, first_paeth = paeth;
        } else {
          EXPECT_EQ(out, first) << what;
          EXPECT_EQ(paeth, first_paeth) << what << ", Paeth";
        }
      }
    }
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
