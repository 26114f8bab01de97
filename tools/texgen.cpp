// texgen: generates the bundled textures and sprites (maps/textures/*.png)
// procedurally and deterministically, so their origin and licence (CC0) are plain.
#include <cmath>
#include <functional>
#include <optional>

#include "engine/image/image.h"
#include "engine/util/rng.h"
#include "tools/cli.h"

using namespace p3d;

namespace {

struct Rgb {
  double r, g, b;
};
Rgb operator*(Rgb c, double k) { return {c.r * k, c.g * k, c.b * k}; }
Rgb operator+(Rgb a, Rgb b) { return {a.r + b.r, a.g + b.g, a.b + b.b}; }
Rgb mix(Rgb a, Rgb b, double t) { return a * (1 - t) + b * t; }

uint32_t pack(Rgb c) {
  auto ch = [](double v) { return static_cast<uint32_t>(std::clamp(v, 0.0, 255.0) + 0.5); };
  return image::rgba(ch(c.r), ch(c.g), ch(c.b));
}

// Tileable value noise: lattice values hashed from wrapped coordinates.
double lattice(int x, int y, int period, uint64_t seed) {
  x = ((x % period) + period) % period;
  y = ((y % period) + period) % period;
  return (Rng::mix(seed, uint64_t(x), uint64_t(y)) >> 11) * 0x1.0p-53;
}

double noise(double x, double y, int period, uint64_t seed) {
  const int xi = static_cast<int>(std::floor(x)), yi = static_cast<int>(std::floor(y));
  const double fx = x - xi, fy = y - yi;
  const double sx = fx * fx * (3 - 2 * fx), sy = fy * fy * (3 - 2 * fy);
  const double a = lattice(xi, yi, period, seed), b = lattice(xi + 1, yi, period, seed);
  const double c = lattice(xi, yi + 1, period, seed), d = lattice(xi + 1, yi + 1, period, seed);
  return (a + (b - a) * sx) * (1 - sy) + (c + (d - c) * sx) * sy;
}

// Fractal noise over a texture of `size` pixels, tiling at every octave.
double fbm(double x, double y, int size, int base_period, uint64_t seed, int octaves = 4) {
  double sum = 0, amp = 0.5, norm = 0;
  int period = base_period;
  for (int o = 0; o < octaves; ++o) {
    sum += amp * noise(x * period / size, y * period / size, period, seed + o);
    norm += amp;
    amp *= 0.5;
    period *= 2;
  }
  return sum / norm;
}

using Shader = std::function<Rgb(int x, int y)>;

image::Image make(int w, int h, const Shader& shader) {
  image::Image img(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) img.at(x, y) = pack(shader(x, y));
  return img;
}

image::Image brick() {
  return make(128, 128, [](int x, int y) {
    const int row = y / 16, shifted = x + (row % 2) * 16;
    const int col = (shifted / 32) % 4;
    const bool mortar = y % 16 < 2 || shifted % 32 < 2;
    const double grit = fbm(x, y, 128, 16, 11);
    if (mortar) return Rgb{120, 112, 100} * (0.8 + 0.4 * grit);
    const double tone = 0.75 + 0.35 * lattice(col, row, 1 << 20, 12);
    const double edge = (y % 16 == 2 || shifted % 32 == 2) ? 1.15 : (y % 16 == 15 ? 0.75 : 1.0);
    return Rgb{150, 62, 44} * (tone * edge * (0.75 + 0.5 * grit));
  });
}

image::Image stone() {
  return make(128, 128, [](int x, int y) {
    const int row = y / 32, shifted = x + (row % 2) * 32;
    const bool joint = y % 32 < 2 || shifted % 64 < 2;
    const double n = fbm(x, y, 128, 8, 21, 5);
    const double tone = 0.8 + 0.3 * lattice(shifted / 64, row, 1 << 20, 22);
    if (joint) return Rgb{50, 50, 48} * (0.8 + 0.3 * n);
    const double shade = (y % 32 == 31 || shifted % 64 == 63) ? 0.7 : (y % 32 == 2 ? 1.2 : 1.0);
    return Rgb{128, 126, 118} * (tone * shade * (0.6 + 0.7 * n));
  });
}

image::Image metal() {
  return make(128, 128, [](int x, int y) {
    const double n = fbm(x, y, 128, 32, 31, 3);
    const int px = x % 64, py = y % 64;
    const bool seam = px < 1 || py < 1;
    const bool rivet = (px == 4 || px == 59) && (py == 4 || py == 59);
    const bool rivet_ring = (std::abs(px - 4) + std::abs(py - 4) == 1) || (std::abs(px - 59) + std::abs(py - 59) == 1) ||
                            (std::abs(px - 4) + std::abs(py - 59) == 1) || (std::abs(px - 59) + std::abs(py - 4) == 1);
    Rgb c = Rgb{96, 104, 116} * (0.85 + 0.25 * n + 0.08 * std::sin(y * 0.9));
    if (seam) c = c * 0.45;
    if (rivet_ring) c = c * 0.6;
    if (rivet) c = Rgb{190, 196, 205};
    return c;
  });
}

image::Image wood() {
  return make(128, 128, [](int x, int y) {
    const int plank = x / 16;
    const double grain = fbm(x * 4.0, y * 0.5, 128, 8, 41 + plank, 4);
    const double rings = 0.5 + 0.5 * std::sin((x % 16) * 0.6 + grain * 9 + plank);
    const double tone = 0.8 + 0.3 * lattice(plank, 0, 1 << 20, 42);
    Rgb c = mix(Rgb{110, 66, 34}, Rgb{160, 104, 58}, rings) * tone;
    if (x % 16 == 0) c = c * 0.45;
    if ((y + plank * 37) % 128 == 0) c = c * 0.55;
    return c;
  });
}

image::Image tech() {
  return make(128, 128, [](int x, int y) {
    const double n = fbm(x, y, 128, 16, 51, 3);
    Rgb c = Rgb{58, 62, 70} * (0.8 + 0.3 * n);
    const bool frame = x % 64 < 3 || y % 64 < 3;
    if (frame) return Rgb{40, 42, 46};
    const int cx = (x % 64) / 8, cy = (y % 64) / 8;
    if (cy >= 2 && cy <= 5 && cx >= 1 && cx <= 6) {  // a screen with text-like rows
      const bool glyph = lattice(x / 2, y / 3, 1 << 20, 52) > 0.55 && y % 3 != 0;
      return glyph ? Rgb{90, 230, 120} : Rgb{10, 40, 20};
    }
    if (cy == 7 && (x % 8) >= 2 && (x % 8) <= 5 && (y % 8) >= 2 && (y % 8) <= 5) {  // indicator lights
      const double pick = lattice(x / 8, y / 8, 1 << 20, 53);
      return pick < 0.33 ? Rgb{230, 60, 40} : pick < 0.66 ? Rgb{240, 200, 40} : Rgb{60, 140, 240};
    }
    return c;
  });
}

image::Image hazard() {
  return make(64, 16, [](int x, int y) {
    const bool stripe = ((x + y) / 8) % 2 == 0;
    const double n = fbm(x, y, 64, 8, 61, 3);
    Rgb c = stripe ? Rgb{220, 180, 30} : Rgb{30, 30, 30};
    if (y == 0) c = Rgb{170, 170, 160};
    return c * (0.8 + 0.3 * n);
  });
}

image::Image tiles() {
  return make(64, 64, [](int x, int y) {
    const double n = fbm(x, y, 64, 8, 71, 4);
    const bool grout = x % 16 == 0 || y % 16 == 0;
    const bool dark = ((x / 16) + (y / 16)) % 2;
    if (grout) return Rgb{60, 58, 54} * (0.8 + 0.3 * n);
    return (dark ? Rgb{110, 104, 94} : Rgb{150, 144, 128}) * (0.8 + 0.35 * n);
  });
}

image::Image ceiling_light() {
  return make(64, 64, [](int x, int y) {
    const double n = fbm(x, y, 64, 8, 81, 3);
    const bool lamp = x >= 20 && x < 44 && y >= 20 && y < 44;
    const bool rim = x >= 18 && x < 46 && y >= 18 && y < 46;
    if (lamp) return Rgb{245, 240, 215} * (0.95 + 0.05 * n);
    if (rim) return Rgb{70, 70, 74};
    return Rgb{112, 110, 104} * (0.8 + 0.3 * n) * ((x % 32 == 0 || y % 32 == 0) ? 0.7 : 1.0);
  });
}

image::Image grass() {
  return make(64, 64, [](int x, int y) {
    const double n = fbm(x, y, 64, 8, 91, 5), blade = lattice(x, y, 64, 92);
    return mix(Rgb{46, 92, 30}, Rgb{92, 150, 50}, n) * (0.85 + 0.3 * blade);
  });
}

image::Image rock() {
  return make(64, 64, [](int x, int y) {
    const double n = fbm(x, y, 64, 4, 101, 5), m = fbm(x, y, 64, 16, 102, 3);
    return mix(Rgb{84, 70, 56}, Rgb{140, 122, 100}, n) * (0.8 + 0.4 * m);
  });
}

image::Image water() {
  return make(64, 64, [](int x, int y) {
    const double n = fbm(x, y, 64, 4, 111, 4);
    const double w = 0.5 + 0.5 * std::sin((x + y) * 0.2 + n * 8);
    return mix(Rgb{20, 50, 110}, Rgb{60, 110, 180}, w * 0.7 + n * 0.3);
  });
}

image::Image sky() {
  return make(256, 128, [](int x, int y) {
    const double t = y / 127.0;
    Rgb c = mix(Rgb{40, 80, 170}, Rgb{170, 200, 235}, t);
    const double cloud = fbm(x, y * 2.0, 256, 8, 121, 5);
    if (cloud > 0.55) c = mix(c, Rgb{245, 245, 250}, std::min(1.0, (cloud - 0.55) * 4));
    const double ridge = 100 + 14 * fbm(x, 0, 256, 8, 122, 4);  // distant mountains
    if (y > ridge) c = mix(Rgb{60, 70, 90}, Rgb{40, 46, 60}, (y - ridge) / 30);
    return c;
  });
}

// ---- sprites: pictures for things, transparent around their shape ----------------

// A sprite: the shader returns a colour, or nothing where the picture is transparent.
template <typename Shader>
image::Image make_sprite(int w, int h, const Shader& shader) {
  image::Image img(w, h, 0u);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      if (const std::optional<Rgb> c = shader(x, y)) img.at(x, y) = pack(*c);
  return img;
}

// Shading across a cylinder of half-width r at horizontal offset dx from its axis.
double round_shade(double dx, double r) { return 0.55 + 0.45 * std::sqrt(std::max(0.0, 1 - (dx * dx) / (r * r))); }

image::Image lamp() {  // a floor lamp: base, pole, glowing shade
  return make_sprite(20, 64, [](int x, int y) -> std::optional<Rgb> {
    const double dx = x - 9.5;
    if (y >= 58 && std::fabs(dx) < 3 + (y - 58)) return Rgb{60, 60, 66} * round_shade(dx, 8);
    if (y >= 16 && y < 58 && std::fabs(dx) < 1.2) return Rgb{90, 90, 96};
    const double half = 5 + (y - 2) * 0.3;  // the shade widens downwards
    if (y >= 2 && y < 16 && std::fabs(dx) < half) return mix(Rgb{255, 236, 170}, Rgb{255, 250, 230}, round_shade(dx, half));
    return std::nullopt;
  });
}

image::Image barrel() {  // a dented green barrel with dark bands and a hazard stripe
  return make_sprite(24, 32, [](int x, int y) -> std::optional<Rgb> {
    const double dx = x - 11.5;
    if (std::fabs(dx) > 11) return std::nullopt;
    const double shade = round_shade(dx, 11.5) * (0.9 + 0.2 * fbm(x, y, 32, 8, 131, 3));
    if (y <= 2) return Rgb{70, 96, 64} * (0.8 + 0.2 * shade);
    if ((y >= 5 && y <= 6) || (y >= 25 && y <= 26)) return Rgb{40, 44, 40} * shade;
    if (y >= 13 && y <= 17) return ((x + y) / 3) % 2 ? Rgb{200, 170, 40} * shade : Rgb{30, 30, 30} * shade;
    return Rgb{64, 110, 58} * shade;
  });
}

image::Image column() {  // a fluted stone column with a capital and a base
  return make_sprite(24, 72, [](int x, int y) -> std::optional<Rgb> {
    const double dx = x - 11.5, grain = 0.9 + 0.2 * fbm(x, y, 72, 6, 141, 3);
    if (y < 6 && std::fabs(dx) < 12) return Rgb{170, 164, 150} * (y == 5 ? 0.7 : 1.0) * grain;
    if (y >= 64 && std::fabs(dx) < 11) return Rgb{150, 144, 132} * (y == 64 ? 0.7 : 1.0) * grain;
    if (y >= 6 && y < 64 && std::fabs(dx) < 8) {
      const double flute = 0.8 + 0.2 * std::cos(dx * 1.6);
      return Rgb{180, 174, 160} * round_shade(dx, 8) * flute * grain;
    }
    return std::nullopt;
  });
}

image::Image plant() {  // a potted plant: a terracotta pot, leaves above
  return make_sprite(32, 44, [](int x, int y) -> std::optional<Rgb> {
    const double dx = x - 15.5;
    if (y >= 30) {
      const double half = 8 + (44 - y) * 0.25;
      if (std::fabs(dx) < half) return Rgb{170, 90, 50} * round_shade(dx, half) * (y == 30 ? 0.8 : 1.0);
      return std::nullopt;
    }
    const double leaf = fbm(x, y, 32, 6, 151, 4);
    const double cx = std::fabs(dx) / 15, cy = (y - 18) / 16.0;
    if (cx * cx + cy * cy < 0.55 + 0.6 * (leaf - 0.5)) return mix(Rgb{30, 80, 26}, Rgb{96, 170, 60}, leaf);
    return std::nullopt;
  });
}

image::Image lantern() {  // a lantern hanging from a chain
  return make_sprite(16, 40, [](int x, int y) -> std::optional<Rgb> {
    const double dx = x - 7.5;
    if (y < 14) return std::fabs(dx) < (y % 4 < 2 ? 0.6 : 1.6) ? std::optional<Rgb>(Rgb{80, 80, 84}) : std::nullopt;
    if (y < 17 && std::fabs(dx) < 5) return Rgb{70, 60, 50};
    if (y >= 36 && y < 39 && std::fabs(dx) < 6) return Rgb{70, 60, 50};
    if (y >= 17 && y < 36 && std::fabs(dx) < 7) {
      if (std::fabs(dx) > 5.5 || y == 26) return Rgb{70, 60, 50};  // the frame
      return mix(Rgb{255, 200, 90}, Rgb{255, 250, 220}, round_shade(dx, 5.5));
    }
    return std::nullopt;
  });
}

}  // namespace

int main(int argc, char** argv) {
  cli::App app{"pseudo3d-texgen: write the bundled procedural textures (CC0) into a directory", "pseudo3d-texgen"};
  std::string dir;
  app.add_option("directory", dir, "output directory, e.g. maps/textures (made if missing)")->required();
  return cli::run(app, argc, argv, [&] {
    std::filesystem::create_directories(dir);
    const std::pair<const char*, image::Image (*)()> textures[] = {
        {"brick", brick}, {"stone", stone}, {"metal", metal}, {"wood", wood},   {"tech", tech},   {"hazard", hazard},
        {"tiles", tiles}, {"ceiling", ceiling_light},       {"grass", grass}, {"rock", rock},   {"water", water},
        {"sky", sky},     {"lamp", lamp},    {"barrel", barrel}, {"column", column}, {"plant", plant},
        {"lantern", lantern}};
    for (const auto& [name, make_texture] : textures)
      image::save_png(make_texture(), std::filesystem::path(dir) / (std::string(name) + ".png"));
    return 0;
  });
}
