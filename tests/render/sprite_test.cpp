// Sprites: properties of single sprites (hidden behind a wall, whole in the open,
// equal depths ordered by thing index, hanging from the ceiling, full bright), and
// every renderer against the reference on random maps dense with things whose
// pictures have holes and reach across the BSP's splitters.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/map/generate.h"
#include "engine/map/source.h"
#include "engine/render/renderer.h"
#include "tests/support/support.h"

namespace p3d::render {
namespace {

constexpr uint32_t kRed = image::rgba(250, 20, 20), kBlue = image::rgba(20, 20, 250);

// A picture: a solid colour, or with holes (every third column transparent).
map::SpriteImage picture(int w, int h, uint32_t colour, bool holes = false) {
  map::SpriteImage img;
  img.name = "p";
  img.image = image::Image(w, h, colour);
  if (holes)
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; x += 3) img.image.at(x, y) = 0;
  img.left = w / 2;
  img.top = h;
  return img;
}

// A sprite frame showing one picture from every side.
int add_sprite(map::Source& src, map::SpriteImage img, bool hanging = false, bool bright = false) {
  src.sprite_images.push_back(std::move(img));
  map::SpriteFrame f;
  f.name = "f";
  std::fill(std::begin(f.image), std::end(f.image), int(src.sprite_images.size()) - 1);
  f.hanging = hanging;
  f.bright = bright;
  src.sprites.push_back(f);
  return int(src.sprites.size()) - 1;
}

void add_thing(map::Source& src, geom::Vec2 pos, int sprite) {
  map::Thing t;
  t.type = 1000 + int(src.things.size());
  t.pos = pos;
  t.sprite = sprite;
  src.things.push_back(t);
}

// One square room (0..512), a wall segment across it at x = 300 from y = 128 to 384.
map::Source room_with_wall() {
  map::Source src = test::random_rooms(4, 1);  // textures and a first room to start from
  src.walls.clear();
  src.vertices.clear();
  src.sectors.resize(1);
  src.sectors[0].floor = 0, src.sectors[0].ceiling = 256, src.sectors[0].light = 255;
  src.things.clear();
  auto v = [&](double x, double y) {
    src.vertices.push_back({{int64_t(x * 256), int64_t(y * 256)}});
    return int(src.vertices.size()) - 1;
  };
  const int a = v(0, 0), b = v(0, 512), c = v(512, 512), d = v(512, 0);
  for (auto [p, q] : {std::pair{a, b}, {b, c}, {c, d}, {d, a}}) {
    map::Wall w;
    w.v1 = p, w.v2 = q;
    w.front.sector = 0;
    w.front.middle = 0;
    src.walls.push_back(w);
  }
  map::Wall seg;
  seg.v1 = v(300, 128), seg.v2 = v(300, 384);
  seg.segment = true;
  seg.front.middle = seg.back.middle = 0;
  src.walls.push_back(seg);
  src.player.pos = {100, 256};
  return src;
}

RenderStats draw(const level::Level& level, const std::string& renderer, const Camera& camera, Frame& frame) {
  return make_renderer(renderer)->render(level, camera, frame);
}

size_t count(const Frame& f, uint32_t colour) {
  return size_t(std::count(f.pixels.begin(), f.pixels.end(), colour));
}

TEST(Sprites, BehindASolidWallWriteNothing) {
  map::Source src = room_with_wall();
  add_thing(src, {400, 256}, add_sprite(src, picture(32, 48, kRed), false, true));  // behind the segment
  const level::Level level = test::compile(src);
  const Camera camera = camera_at(level, {100, 256}, 0);
  for (const char* r : {"bsp", "reference", "painter", "sphere"}) {
    Frame frame(160, 100);
    const RenderStats s = draw(level, r, camera, frame);
    EXPECT_EQ(s.sprite_pixels, 0u) << r;
    EXPECT_EQ(s.sprites_drawn, 0u) << r;
    EXPECT_EQ(count(frame, kRed), 0u) << r;
  }
}

TEST(Sprites, InFrontOfEverythingAreDrawnWhole) {
  map::Source src = room_with_wall();
  add_thing(src, {200, 256}, add_sprite(src, picture(32, 48, kRed), false, true));  // full bright: exactly kRed
  const level::Level level = test::compile(src);
  const Camera camera = camera_at(level, {100, 256}, 0);
  const int w = 160, h = 100;
  // The pixels whose centre's ray meets the 32x48 picture standing at depth 100.
  const double d = w / 2.0, depth = 100, inv = depth / d;
  size_t expected = 0;
  for (int x = 0; x < w; ++x) {
    const double lateral = (x + 0.5 - w / 2.0) * inv;
    if (lateral < -16 || lateral >= 16) continue;
    for (int y = 0; y < h; ++y) {
      const double z = camera.z - (y + 0.5 - h / 2.0) * inv;
      expected += z > 0 && z <= 48;
    }
  }
  for (const char* r : {"bsp", "reference", "painter", "sphere"}) {
    Frame frame(w, h);
    const RenderStats s = draw(level, r, camera, frame);
    EXPECT_EQ(s.sprites_drawn, 1u) << r;
    EXPECT_EQ(count(frame, kRed), expected) << r;
    EXPECT_EQ(s.sprite_pixels, count(frame, kRed)) << r;
  }
}

// Two pictures at exactly one depth, overlapping: the later thing is drawn last,
// whatever order the renderer met them in.
TEST(Sprites, EqualDepthsAreOrderedByThingIndex) {
  for (bool red_first : {true, false}) {
    map::Source src = room_with_wall();
    const int red = add_sprite(src, picture(40, 40, kRed), false, true);
    const int blue = add_sprite(src, picture(40, 40, kBlue), false, true);
    add_thing(src, {200, red_first ? 246 : 266}, red_first ? red : blue);
    add_thing(src, {200, red_first ? 266 : 246}, red_first ? blue : red);
    const level::Level level = test::compile(src);
    Frame a(160, 100), b(160, 100), c(160, 100);
    const Camera camera = camera_at(level, {100, 256}, 0);
    draw(level, "bsp", camera, a);
    draw(level, "reference", camera, b);
    draw(level, "painter", camera, c);
    EXPECT_EQ(a.pixels, b.pixels);
    EXPECT_EQ(a.pixels, c.pixels);
    // The overlap (the middle column) shows the second thing.
    EXPECT_EQ(a.at(80, 60), red_first ? kBlue : kRed);
  }
}

TEST(Sprites, HangFromTheCeilingAndFollowTheirSector) {
  map::Source src = room_with_wall();
  add_thing(src, {200, 256}, add_sprite(src, picture(16, 32, kRed, false), true, true));
  src.sprite_images.back().top = 0;  // the top row at the ceiling
  const level::Level level = test::compile(src);
  Frame frame(160, 100);
  const Camera camera{{100, 256}, 41, 0, 90};
  draw(level, "bsp", camera, frame);
  // At depth 100 the ceiling (256) is far above the screen: only a picture near the
  // ceiling would be off-screen; here the picture is 32 high under a 256 ceiling.
  EXPECT_EQ(count(frame, kRed), 0u);
  level::State state = level::start_state(level);
  state.sectors[0].ceiling = 96;  // a lower ceiling brings it into view, hanging from it
  make_renderer("bsp")->render(level, state, camera, frame);
  EXPECT_GT(count(frame, kRed), 0u);
  int lowest = -1;
  for (int y = 0; y < frame.height; ++y)
    if (frame.at(80, y) == kRed) lowest = y;
  const double inv = 100.0 / 80;  // map units per row at depth 100
  EXPECT_NEAR(41 - (lowest + 0.5 - 50) * inv, 96 - 32, 2 * inv);  // its bottom 32 below the ceiling
}

TEST(Sprites, SkillAndPresenceDecideWhatIsDrawn) {
  map::Source src = room_with_wall();
  const int sprite = add_sprite(src, picture(32, 48, kRed), false, true);
  add_thing(src, {200, 256}, sprite);
  src.things.back().flags = doom::kThingEasy;  // skills 1 and 2 only
  const level::Level level = test::compile(src);
  const Camera camera = camera_at(level, {100, 256}, 0);
  Frame frame(160, 100);
  auto renderer = make_renderer("bsp");
  renderer->render(level, level::start_state(level, 3), camera, frame);
  EXPECT_EQ(count(frame, kRed), 0u);
  renderer->render(level, level::start_state(level, 2), camera, frame);
  EXPECT_GT(count(frame, kRed), 0u);
  level::State state = level::start_state(level, 1);
  state.things[0] = 0;  // picked up
  renderer->render(level, state, camera, frame);
  EXPECT_EQ(count(frame, kRed), 0u);

  map::Source multi = room_with_wall();
  add_thing(multi, {200, 256}, add_sprite(multi, picture(32, 48, kRed), false, true));
  multi.things.back().flags = doom::kThingAllSkills | doom::kThingNotSingle;
  const level::Level ml = test::compile(multi);
  EXPECT_EQ(level::start_state(ml).things[0], 0) << "multiplayer-only things are left out";
}

// Random rooms and soups crowded with things (pictures with holes, some wide enough
// to reach across splitters, some hanging): bsp, painter and the sphere tracer
// against the reference, pixel for pixel.
TEST(Sprites, EveryRendererAgreesOnCrowdedMaps) {
  size_t frames = 0, sprites = 0, differ = 0, pixels = 0;
  for (uint64_t seed : {1, 2, 3, 4}) {
    map::Source src = seed % 2 ? test::random_rooms(400, seed) : test::random_soup(300, seed);
    const int small = add_sprite(src, picture(24, 40, kRed, true));
    const int wide = add_sprite(src, picture(160, 24, kBlue, true));
    const int hanging = add_sprite(src, picture(20, 30, kRed, true), true);
    src.sprite_images.back().top = 0;
    const level::Level bounds = test::compile(src);
    Rng rng(seed);
    for (int i = 0; i < 120; ++i) {
      const geom::Vec2 p{rng.uniform(bounds.bounds.min.x, bounds.bounds.max.x),
                         rng.uniform(bounds.bounds.min.y, bounds.bounds.max.y)};
      add_thing(src, p, i % 3 == 0 ? wide : i % 3 == 1 ? small : hanging);
      src.things.back().angle = rng.uniform(0, 360);
    }
    const level::Level level = test::compile(src);
    for (int c = 0; c < 40; ++c) {
      const Camera camera = test::random_camera(level, rng);
      const int w = 48 + int(rng.below(80)), h = 30 + int(rng.below(50));
      Frame ref(w, h);
      const RenderStats rs = draw(level, "reference", camera, ref);
      sprites += rs.sprites_drawn;
      for (const char* r : {"bsp", "painter", "sphere"}) {
        Frame f(w, h);
        const RenderStats s = draw(level, r, camera, f);
        size_t d = 0;
        for (size_t k = 0; k < f.pixels.size(); ++k) d += f.pixels[k] != ref.pixels[k];
        EXPECT_EQ(d, 0u) << r << " seed " << seed << " camera " << c;
        EXPECT_EQ(s.sprites_drawn, rs.sprites_drawn) << r << " seed " << seed << " camera " << c;
        differ += d;
        pixels += f.pixels.size();
      }
      ++frames;
    }
  }
  EXPECT_GT(sprites, frames) << "the maps are crowded";
  std::printf("[ stats    ] crowded maps: %zu frames, %zu sprites drawn, %zu/%zu pixels differ\n", frames, sprites,
              differ, pixels);
}

// On grid maps the grid ray caster draws the same sprites as the BSP renderer.
TEST(Sprites, TheGridRayCasterDrawsThemToo) {
  map::Source src = map::load_grid(test::source_dir() / "maps/bunker.grid");
  ASSERT_FALSE(src.things.empty());
  const level::Level level = test::compile(src);
  Rng rng(5);
  size_t sprites = 0;
  for (int c = 0; c < 40; ++c) {
    const Camera camera = test::random_camera(level, rng);
    Frame a(96, 60), b(96, 60);
    sprites += draw(level, "bsp", camera, a).sprites_drawn;
    draw(level, "dda", camera, b);
    EXPECT_EQ(a.pixels, b.pixels) << "camera " << c;
  }
  EXPECT_GT(sprites, 0u);
}

}  // namespace
}  // namespace p3d::render
