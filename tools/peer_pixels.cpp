// peer_pixels: our frames held against a Doom port's, pixel by pixel (tools/peer_pixels.sh
// makes the frames: one demo turning in place, replayed by Chocolate or Crispy Doom and
// by our game at the same tics).
//
//   peer_pixels --iwad W.wad [--label NAME] [--pictures DIR] OURS1 THEIRS1 [OURS2 THEIRS2 ...]
//
// Both frames are mapped back to the palette (PLAYPAL's first palette) as the port
// shows it: ours are drawn in its colours, a port's saved frames pass them through its
// gamma table and drop the low two bits of each channel (I_SetPalette), so each pixel
// becomes the nearest such colour, and pixels are compared as those colours (indices
// of one colour on the port's screen are one colour). Per pair it prints the
// share of pixels exactly equal and the share within one pixel (equal to one of the
// port's pixel's 3x3 neighbourhood). With --pictures, each pair's picture goes to
// DIR/NAME-vN.png: ours | the port's | the differences (the port's frame in grey, a
// pixel not within one pixel red, one within one pixel but not equal yellow), twice
// the size.
#include <array>
#include <cstdio>
#include <fstream>
#include <unordered_map>

#include "engine/bsp/load.h"
#include "engine/image/image.h"
#include "engine/util/error.h"
#include "engine/util/file.h"
#include "engine/wad/art.h"
#include "tools/cli.h"

using namespace p3d;

namespace {

// A 24- or 32-bit uncompressed BMP (what SDL's dummy driver saves), as RGBA.
image::Image load_bmp(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error("cannot read " + path.string());
  std::vector<uint8_t> b((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  auto u32 = [&](size_t at) {
    if (at + 4 > b.size()) throw Error(path.string() + ": not a BMP");
    return uint32_t(b[at]) | uint32_t(b[at + 1]) << 8 | uint32_t(b[at + 2]) << 16 | uint32_t(b[at + 3]) << 24;
  };
  if (b.size() < 54 || b[0] != 'B' || b[1] != 'M') throw Error(path.string() + ": not a BMP");
  const uint32_t offset = u32(10);
  const int width = int32_t(u32(18)), height_signed = int32_t(u32(22));
  const int bits = b[28] | b[29] << 8;
  if ((bits != 24 && bits != 32) || u32(30) != 0 || width <= 0 || width > 8192 || height_signed == 0)
    throw Error(path.string() + ": only uncompressed 24- and 32-bit BMPs are read");
  const int height = std::abs(height_signed);
  if (height > 8192) throw Error(path.string() + ": too tall");
  const size_t bpp = size_t(bits / 8), stride = (size_t(width) * bpp + 3) & ~size_t(3);
  if (offset + stride * size_t(height) > b.size()) throw Error(path.string() + ": truncated");
  image::Image img(width, height);
  for (int y = 0; y < height; ++y) {
    const size_t row = offset + stride * size_t(height_signed > 0 ? height - 1 - y : y);
    for (int x = 0; x < width; ++x) {
      const uint8_t* p = &b[row + size_t(x) * bpp];
      img.pixels[size_t(y) * size_t(width) + size_t(x)] = image::rgba(p[2], p[1], p[0]);
    }
  }
  return img;
}

image::Image load_any(const std::filesystem::path& path) {
  return path.extension() == ".bmp" || path.extension() == ".BMP" ? load_bmp(path) : image::load_png(path);
}

// Each pixel as a palette colour as the port shows it, named by the first index of
// that colour. Chocolate Doom passes each channel through its gamma table (level 0:
// c + 1 below 128) and drops the low two bits (I_SetPalette's & ~3), so some
// neighbouring palette colours are one colour on its screen: pixels are compared as the
// port shows them. Our frames hold palette colours exactly; a port's are matched to
// the nearest shown colour.
inline uint32_t port_channel(uint32_t c) { return (c < 128 ? c + 1 : c) & ~3u; }
inline uint32_t port_colour(uint32_t c) {
  return image::rgba(port_channel(image::red(c)), port_channel(image::green(c)), port_channel(image::blue(c)));
}

class Snap {
 public:
  explicit Snap(const std::vector<uint32_t>& palette) {
    for (uint32_t c : palette) shown_.push_back(port_colour(c));
    for (uint32_t c : palette) ours_.emplace(c | 0xFF000000u, 0);
  }
  std::vector<uint8_t> operator()(const image::Image& img) {
    std::vector<uint8_t> out(img.pixels.size());
    for (size_t i = 0; i < out.size(); ++i) out[i] = index_of(img.pixels[i] | 0xFF000000u);
    return out;
  }

 private:
  uint8_t index_of(uint32_t c) {
    if (auto it = cache_.find(c); it != cache_.end()) return it->second;
    const uint32_t masked = ours_.count(c) ? port_colour(c) : c;  // ours: a palette colour, as the port shows it
    int best = 0;
    long best_d = -1;
    for (int i = 0; i < int(shown_.size()); ++i) {
      const long dr = long(image::red(masked)) - long(image::red(shown_[size_t(i)]));
      const long dg = long(image::green(masked)) - long(image::green(shown_[size_t(i)]));
      const long db = long(image::blue(masked)) - long(image::blue(shown_[size_t(i)]));
      const long d = dr * dr + dg * dg + db * db;
      if (best_d < 0 || d < best_d) best = i, best_d = d;  // the first of equals: one name per colour
    }
    return cache_[c] = uint8_t(best);
  }
  std::vector<uint32_t> shown_;
  std::unordered_map<uint32_t, uint8_t> ours_;  // the palette's colours
  std::unordered_map<uint32_t, uint8_t> cache_;
};

struct Score {
  double exact = 0, within = 0;
};

// Per pixel: 0 equal, 1 within one pixel, 2 neither.
std::vector<uint8_t> classify(const std::vector<uint8_t>& ours, const std::vector<uint8_t>& theirs, int w, int h,
                              Score& score) {
  std::vector<uint8_t> kind(ours.size(), 2);
  size_t exact = 0, within = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const size_t i = size_t(y) * size_t(w) + size_t(x);
      if (ours[i] == theirs[i]) {
        kind[i] = 0, ++exact, ++within;
        continue;
      }
      for (int dy = -1; dy <= 1 && kind[i] == 2; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int xx = x + dx, yy = y + dy;
          if (xx < 0 || yy < 0 || xx >= w || yy >= h) continue;
          if (theirs[size_t(yy) * size_t(w) + size_t(xx)] == ours[i]) {
            kind[i] = 1, ++within;
            break;
          }
        }
    }
  score.exact = double(exact) / double(ours.size());
  score.within = double(within) / double(ours.size());
  return kind;
}

void save_picture(const image::Image& ours, const image::Image& theirs, const std::vector<uint8_t>& kind,
                  const std::filesystem::path& path) {
  const int w = ours.width, h = ours.height, gap = 4;
  image::Image diff(w, h);
  for (size_t i = 0; i < diff.pixels.size(); ++i) {
    const uint32_t c = theirs.pixels[i];
    const uint32_t grey = (image::red(c) * 3 + image::green(c) * 6 + image::blue(c)) / 10 / 2 + 40;
    diff.pixels[i] = kind[i] == 2 ? image::rgba(255, 32, 32) : kind[i] == 1 ? image::rgba(255, 220, 0) : image::rgba(grey, grey, grey);
  }
  image::Image row(3 * w + 2 * gap, h);
  std::fill(row.pixels.begin(), row.pixels.end(), image::rgba(32, 32, 40));
  image::blit(row, ours, 0, 0);
  image::blit(row, theirs, w + gap, 0);
  image::blit(row, diff, 2 * (w + gap), 0);
  const int scale = w <= 400 ? 2 : 1;
  image::Image big(row.width * scale, row.height * scale);
  for (int y = 0; y < big.height; ++y)
    for (int x = 0; x < big.width; ++x)
      big.pixels[size_t(y) * size_t(big.width) + size_t(x)] = row.pixels[size_t(y / scale) * size_t(row.width) + size_t(x / scale)];
  image::save_png(big, path);
}

}  // namespace

int main(int argc, char** argv) {
  cli::App app{"peer_pixels: our frames against a Doom port's, pixel by pixel (as palette colours)", "peer_pixels"};
  std::string iwad, label = "view", pictures;
  std::vector<std::string> files;
  app.add_option("--iwad", iwad, "the WAD whose PLAYPAL the frames use")->required();
  app.add_option("--label", label, "name printed on each line (and of the pictures)");
  app.add_option("--pictures", pictures, "write each pair's picture (ours | port's | differences) into this directory");
  app.add_option("frames", files, "OURS THEIRS pairs (PNG or BMP)")->required();
  return cli::run(app, argc, argv, [&] {
    if (files.size() % 2) throw Error("frames come in pairs: ours, then the port's");
    const wad::Stack stack = bsp::read_wads({std::filesystem::path(iwad)});
    const wad::Art art(stack);
    Snap snap(art.palette());
    for (size_t p = 0; p < files.size(); p += 2) {
      const image::Image ours = load_any(files[p]), theirs = load_any(files[p + 1]);
      if (ours.width != theirs.width || ours.height != theirs.height)
        throw Error(files[p] + " and " + files[p + 1] + " differ in size");
      Score score;
      const std::vector<uint8_t> kind = classify(snap(ours), snap(theirs), ours.width, ours.height, score);
      std::printf("%s v%zu exact %.4f within %.4f\n", label.c_str(), p / 2, score.exact, score.within);
      if (!pictures.empty()) {
        std::filesystem::create_directories(pictures);
        save_picture(ours, theirs, kind, std::filesystem::path(pictures) / (label + "-v" + std::to_string(p / 2) + ".png"));
      }
    }
    return 0;
  });
}
