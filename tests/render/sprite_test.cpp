// Sprites: properties of single sprites (hidden behind a wall, whole in the open,
// equal depths ordered by thing index, hanging from the ceiling, full bright), and
// every renderer against the reference on random maps dense with things whose
// pictures have holes and reach across the BSP's splitters; things that move, come
// and go in the state, at any height, some drawn as Doom's fuzz.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/bsp/load.h"
#include "engine/map/generate.h"
#include "engine/map/source.h"
#include "engine/render/draw.h"
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
  level::rest_things(level, state);
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
  src.things.back().flags = p3d::doom::kThingEasy;  // skills 1 and 2 only
  const level::Level level = test::compile(src);
  const Camera camera = camera_at(level, {100, 256}, 0);
  Frame frame(160, 100);
  auto renderer = make_renderer("bsp");
  renderer->render(level, level::start_state(level, 3), camera, frame);
  EXPECT_EQ(count(frame, kRed), 0u);
  renderer->render(level, level::start_state(level, 2), camera, frame);
  EXPECT_GT(count(frame, kRed), 0u);
  level::State state = level::start_state(level, 1);
  ASSERT_EQ(state.things.size(), 1u);
  EXPECT_EQ(state.things[0].placed, 0);
  state.things.clear();  // picked up
  renderer->render(level, state, camera, frame);
  EXPECT_EQ(count(frame, kRed), 0u);

  map::Source multi = room_with_wall();
  add_thing(multi, {200, 256}, add_sprite(multi, picture(32, 48, kRed), false, true));
  multi.things.back().flags = p3d::doom::kThingAllSkills | p3d::doom::kThingNotSingle;
  const level::Level ml = test::compile(multi);
  EXPECT_TRUE(level::start_state(ml).things.empty()) << "multiplayer-only things are left out";
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

// A thing moved in the state (along and up) draws at its new place and nowhere else;
// a thing added to the state after load draws too.
TEST(Sprites, ThingsMoveAndComeInTheState) {
  map::Source src = room_with_wall();
  add_thing(src, {200, 256}, add_sprite(src, picture(32, 48, kRed), false, true));  // full bright: exactly kRed
  const level::Level level = test::compile(src);
  const Camera camera = camera_at(level, {100, 256}, 0);
  const int w = 160, h = 100;
  // The pixels showing a 32x48 picture whose feet stand at (pos, z), seen in the open.
  auto expected = [&](geom::Vec2 pos, double z) {
    const double depth = pos.x - camera.pos.x, inv = depth / (w / 2.0);
    size_t n = 0;
    for (int x = 0; x < w; ++x) {
      const double lateral = (x + 0.5 - w / 2.0) * inv - (camera.pos.y - pos.y);
      if (lateral < -16 || lateral >= 16) continue;
      for (int y = 0; y < h; ++y) {
        const double at = camera.z - (y + 0.5 - h / 2.0) * inv;
        n += at > z && at <= z + 48;
      }
    }
    return n;
  };
  level::State state = level::start_state(level);
  ASSERT_EQ(state.things.size(), 1u);
  state.things[0].pos = {180, 270};
  state.things[0].z = 20;  // off the floor: flying
  Frame moved(w, h);
  for (const char* r : {"bsp", "reference", "painter", "sphere"}) {
    Frame frame(w, h);
    make_renderer(r)->render(level, state, camera, frame);
    EXPECT_EQ(count(frame, kRed), expected({180, 270}, 20)) << r;
    if (std::string(r) == "bsp") moved = frame;
    EXPECT_EQ(frame.pixels, moved.pixels) << r;
  }
  Frame placed(w, h);
  make_renderer("bsp")->render(level, level::start_state(level), camera, placed);
  EXPECT_NE(placed.pixels, moved.pixels);

  level::State added = level::start_state(level);
  added.things.clear();
  Frame empty(w, h);
  make_renderer("bsp")->render(level, added, camera, empty);
  EXPECT_EQ(count(empty, kRed), 0u);
  level::ShownThing spawned;
  spawned.pos = {220, 240};
  spawned.z = -8;  // sunk into the floor, which does not hide its feet (as in Doom)
  spawned.frame = 0;
  spawned.sector = 0;
  added.things.push_back(spawned);
  for (const char* r : {"bsp", "reference", "painter", "sphere"}) {
    Frame frame(w, h);
    const RenderStats s = make_renderer(r)->render(level, added, camera, frame);
    EXPECT_EQ(s.sprites_drawn, 1u) << r;
    EXPECT_EQ(count(frame, kRed), expected({220, 240}, -8)) << r << ": sprites clip to walls, not to floors";
  }
}

// Doom's shadows: a kShownShadow thing draws no colour of its own; each pixel of its
// shape darkens (light map 6's multiplier on RGBA art) the pixel a row above or below.
TEST(Sprites, ShadowsAreDoomsFuzz) {
  map::Source src = room_with_wall();
  add_thing(src, {200, 256}, add_sprite(src, picture(32, 48, kRed), false, true));
  const level::Level level = test::compile(src);
  const Camera camera = camera_at(level, {100, 256}, 0);
  level::State state = level::start_state(level);
  level::State without = state;
  without.things.clear();
  state.things[0].flags = level::kShownShadow;
  Frame plain(160, 100), fuzzed(160, 100);
  make_renderer("reference")->render(level, without, camera, plain);
  const RenderStats rs = make_renderer("reference")->render(level, state, camera, fuzzed);
  EXPECT_EQ(rs.sprites_drawn, 1u);
  EXPECT_EQ(count(fuzzed, kRed), 0u);
  // Light map 6 of RGBA art: 26/32 of each channel.
  auto dark = [](uint32_t c) {
    return image::rgba(image::red(c) * 208 >> 8, image::green(c) * 208 >> 8, image::blue(c) * 208 >> 8);
  };
  size_t changed = 0;
  for (int y = 1; y + 1 < fuzzed.height; ++y)
    for (int x = 0; x < fuzzed.width; ++x) {
      if (fuzzed.at(x, y) == plain.at(x, y)) continue;
      ++changed;
      // Drawn top down: the row above is already fuzzed, the row below not yet.
      EXPECT_TRUE(fuzzed.at(x, y) == dark(fuzzed.at(x, y - 1)) || fuzzed.at(x, y) == dark(plain.at(x, y + 1)))
          << x << "," << y;
    }
  EXPECT_LE(changed, rs.sprite_pixels);
  EXPECT_GT(changed, rs.sprite_pixels / 2);
  EXPECT_GT(rs.sprite_pixels, 500u);
  for (const char* r : {"bsp", "painter", "sphere"}) {
    Frame frame(160, 100);
    make_renderer(r, {.threads = 2})->render(level, state, camera, frame);
    EXPECT_EQ(frame.pixels, fuzzed.pixels) << r;
  }
}

// Random things shown anywhere (moved far from where they were placed, sunk into
// floors, floating, hanging frames standing and standing frames high), some added,
// some shadows: every renderer against the reference, on random maps (RGBA art) and
// Freedoom's MAP01 (paletted: the painter draws colours, the others indices). The BSP
// renderer's culling, computed anew for every frame, never hides a sprite pixel.
void scatter_things(const level::Level& level, level::State& state, Rng& rng, size_t extra) {
  auto random_thing = [&](level::ShownThing& t) {
    t.pos = {rng.uniform(level.bounds.min.x, level.bounds.max.x), rng.uniform(level.bounds.min.y, level.bounds.max.y)};
    t.sector = level.sector_at(t.pos);
    const double floor = t.sector != level::kNone ? state.sectors[size_t(t.sector)].floor : 0;
    t.z = floor + rng.uniform(-24, 96);
    t.angle = rng.uniform(0, 360);
    t.frame = int32_t(rng.below(uint32_t(level.sprite_frames.size())));
    t.flags = rng.below(4) == 0 ? level::kShownShadow : 0;
  };
  for (level::ShownThing& t : state.things)
    if (rng.below(3) != 0) random_thing(t);
  for (size_t i = 0; i < extra; ++i) {
    level::ShownThing t;
    random_thing(t);
    state.things.push_back(t);
  }
}

size_t compare_renderers(const level::Level& level, const level::State& state, Rng& rng, int cameras,
                         const std::string& what) {
  size_t sprites = 0;
  for (int c = 0; c < cameras; ++c) {
    const Camera camera = test::random_camera(level, rng);
    const int w = 48 + int(rng.below(80)), h = 30 + int(rng.below(50));
    Frame ref(w, h);
    const RenderStats rs = make_renderer("reference")->render(level, state, camera, ref);
    sprites += rs.sprites_drawn;
    for (const char* r : {"bsp", "painter", "sphere"}) {
      Frame f(w, h);
      const RenderStats s = make_renderer(r, {.threads = 2})->render(level, state, camera, f);
      size_t d = 0;
      for (size_t k = 0; k < f.pixels.size(); ++k) d += f.pixels[k] != ref.pixels[k];
      EXPECT_EQ(d, 0u) << r << " " << what << " camera " << c;
      EXPECT_EQ(s.sprites_drawn, rs.sprites_drawn) << r << " " << what << " camera " << c;
      EXPECT_EQ(s.sprite_pixels, rs.sprite_pixels) << r << " " << what << " camera " << c;
    }
  }
  return sprites;
}

TEST(Sprites, MovedThingsAgreeEverywhere) {
  size_t sprites = 0;
  for (uint64_t seed : {11, 12, 13}) {
    map::Source src = seed % 2 ? test::random_rooms(300, seed) : test::random_soup(200, seed);
    const int small = add_sprite(src, picture(24, 40, kRed, true));
    const int wide = add_sprite(src, picture(160, 24, kBlue, true));
    const int hanging = add_sprite(src, picture(20, 30, kRed, true), true);
    src.sprite_images.back().top = 0;
    const level::Level bounds = test::compile(src);
    Rng rng(seed);
    for (int i = 0; i < 60; ++i) {
      add_thing(src, {rng.uniform(bounds.bounds.min.x, bounds.bounds.max.x), rng.uniform(bounds.bounds.min.y, bounds.bounds.max.y)},
                i % 3 == 0 ? wide : i % 3 == 1 ? small : hanging);
    }
    const level::Level level = test::compile(src);
    level::State state = level::start_state(level);
    scatter_things(level, state, rng, 60);
    sprites += compare_renderers(level, state, rng, 30, "seed " + std::to_string(seed));
  }
  EXPECT_GT(sprites, 90u);
}

TEST(Sprites, MovedThingsAgreeOnFreedoom) {
  const level::Level level =
      bsp::open_level(bsp::LevelSource{{}, {test::freedoom_path("freedoom2.wad")}, "MAP01"}).level;
  ASSERT_TRUE(level.paletted());
  Rng rng(21);
  level::State state = level::start_state(level);
  scatter_things(level, state, rng, 200);
  const size_t sprites = compare_renderers(level, state, rng, 30, "MAP01");
  EXPECT_GT(sprites, 30u);
}

// One BSP renderer drawing frame after frame, things moving between them and the level
// changing now and then, draws what the reference draws in each: what a frame's things
// did to the tree is undone before the next frame's.
TEST(Sprites, OneRendererFollowsMovingThingsFrameAfterFrame) {
  std::vector<level::Level> levels;
  for (uint64_t seed : {31, 32}) {
    map::Source src = seed % 2 ? test::random_rooms(300, seed) : test::random_soup(200, seed);
    const int small = add_sprite(src, picture(24, 40, kRed, true));
    const int wide = add_sprite(src, picture(160, 24, kBlue, true));
    const level::Level bounds = test::compile(src);
    Rng rng(seed);
    for (int i = 0; i < 40; ++i)
      add_thing(src, {rng.uniform(bounds.bounds.min.x, bounds.bounds.max.x), rng.uniform(bounds.bounds.min.y, bounds.bounds.max.y)},
                i % 2 ? wide : small);
    levels.push_back(test::compile(src));
  }
  const auto bsp = make_renderer("bsp", {.threads = 2});
  Rng rng(33);
  size_t sprites = 0;
  for (int frame = 0; frame < 40; ++frame) {
    const level::Level& level = levels[size_t(frame / 10 % 2)];  // ten frames of one, then the other
    level::State state = level::start_state(level);
    scatter_things(level, state, rng, 30);
    const Camera camera = test::random_camera(level, rng);
    Frame ours(64, 40), ref(64, 40);
    const RenderStats rs = make_renderer("reference")->render(level, state, camera, ref);
    const RenderStats s = bsp->render(level, state, camera, ours);
    EXPECT_EQ(ours.pixels, ref.pixels) << "frame " << frame;
    EXPECT_EQ(s.sprites_drawn, rs.sprites_drawn) << "frame " << frame;
    sprites += rs.sprites_drawn;
  }
  EXPECT_GT(sprites, 40u);
}

// Under Doom's rules a frame's sprites are projected together, a test in doubles first
// turning away the things plainly behind the view or off to its sides: the same sprites
// as R_ProjectSprite gives each thing alone, for things anywhere (some far enough that
// Doom's 16.16 differences wrap), just nearer or farther than its MINZ, and either side
// of the edges of the wedge it keeps (|tx| = 4 tz).
TEST(Sprites, ProjectedTogetherAsOneByOne) {
  const level::Level level =
      bsp::open_level(bsp::LevelSource{{}, {test::freedoom_path("freedoom2.wad")}, "MAP01"}).level;
  Rng rng(31);
  level::State state = level::start_state(level);
  size_t projected = 0;
  for (int c = 0; c < 40; ++c) {
    Camera camera = test::random_camera(level, rng);
    camera.fov = 90;  // Doom's
    const View view(camera, 320 << (c % 2), 200 << (c % 2), level);
    ASSERT_NE(view.doom, nullptr);
    state.things.clear();
    for (int i = 0; i < 300; ++i) {
      level::ShownThing t;
      t.frame = int32_t(rng.below(uint32_t(level.sprite_frames.size())));
      t.angle = rng.uniform(0, 360);
      const double tz = i % 3 == 1 ? rng.uniform(2.5, 5.5) : rng.uniform(4, 2000);
      const double tx = i % 3 == 2 ? (rng.below(2) ? 1 : -1) * (4 * tz + rng.uniform(-6, 6)) : rng.uniform(-tz, tz);
      t.pos = i % 3 == 0 ? geom::Vec2{rng.uniform(-32000, 32000), rng.uniform(-32000, 32000)}
                         : camera.pos + view.forward * tz + view.right * tx;
      t.z = camera.z + rng.uniform(-100, 100);
      state.things.push_back(t);
    }
    std::vector<Canvas::Sprite> together, alone;
    Canvas::project_doom_sprites(level, state, view, together);
    Canvas::Sprite s;
    for (uint32_t i = 0; i < state.things.size(); ++i)
      if (Canvas::project_doom_sprite(level, state, view, i, s)) alone.push_back(s);
    ASSERT_EQ(together.size(), alone.size()) << "camera " << c;
    for (size_t k = 0; k < alone.size(); ++k) {
      EXPECT_EQ(together[k].thing, alone[k].thing) << "camera " << c;
      EXPECT_EQ(together[k].x0, alone[k].x0) << "camera " << c;
      EXPECT_EQ(together[k].x1, alone[k].x1) << "camera " << c;
      EXPECT_EQ(together[k].scale, alone[k].scale) << "camera " << c;
    }
    projected += alone.size();
  }
  EXPECT_GT(projected, 1000u);
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
