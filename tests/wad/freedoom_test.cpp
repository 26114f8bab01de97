// Every map of Freedoom (Debian's freedoom package: freedoom1.wad and freedoom2.wad)
// compiles without a rejection, passes the BSP invariants exactly, and renders
// identically with the front-to-back renderer and the brute-force reference, pixel
// for pixel and column for column, things and all, at the player start and at
// random cameras, also with its doors, lifts and crushers set moving.
// The Release build tries every map; the sanitizer build a sample (P3D_SANITIZE).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "engine/bsp/check.h"
#include "engine/bsp/load.h"
#include "engine/play/world.h"
#include "engine/render/renderer.h"
#include "engine/wad/write.h"
#include "tests/support/support.h"

namespace p3d::wad {
namespace {

struct Tally {
  size_t maps = 0, frames = 0, columns = 0, column_mismatches = 0, pixels = 0, pixel_mismatches = 0, masked = 0;
  size_t sprites = 0, sprite_pixels = 0;
};

void compare_camera(const level::Level& level, const level::State& state, const render::Camera& camera, int w, int h,
                    Tally& t, const std::string& what) {
  auto bsp = render::make_renderer("bsp");
  auto ref = render::make_renderer("reference");
  render::Frame a(w, h), b(w, h);
  render::Probe pa, pb;
  pa.want_columns = pb.want_columns = true;
  const render::RenderStats sa = bsp->render(level, state, camera, a, &pa);
  const render::RenderStats sb = ref->render(level, state, camera, b, &pb);
  EXPECT_EQ(sa.pixels_written, uint64_t(w) * h) << what;
  EXPECT_EQ(sa.masked_pixels, sb.masked_pixels) << what;
  EXPECT_EQ(sa.sprites_drawn, sb.sprites_drawn) << what;
  EXPECT_EQ(sa.sprite_pixels, sb.sprite_pixels) << what;
  t.masked += sa.masked_pixels;
  t.sprites += sa.sprites_drawn;
  t.sprite_pixels += sa.sprite_pixels;
  for (int x = 0; x < w; ++x) {
    ++t.columns;
    const render::ColumnHit &ha = pa.columns[size_t(x)], &hb = pb.columns[size_t(x)];
    if (ha.wall != hb.wall || (ha.wall >= 0 && ha.dist != hb.dist)) {
      if (++t.column_mismatches <= 10)
        ADD_FAILURE() << what << " column " << x << ": bsp wall " << ha.wall << " at " << ha.dist << ", reference "
                      << hb.wall << " at " << hb.dist;
    }
  }
  size_t differ = 0;
  for (size_t i = 0; i < a.pixels.size(); ++i) differ += a.pixels[i] != b.pixels[i];
  if (differ && t.pixel_mismatches == 0)
    ADD_FAILURE() << what << ": " << differ << " pixels differ (camera " << camera.pos.x << "," << camera.pos.y
                  << " z " << camera.z << " angle " << camera.angle << " fov " << camera.fov << ")";
  t.pixel_mismatches += differ;
  t.pixels += a.pixels.size();
  ++t.frames;
}

// Doom's rules for a map of this name: Doom II's for MAPxx, else the episode's.
play::GameOptions options_for(const std::string& map) {
  play::GameOptions o;
  int episode = 0, number = 0;
  o.commercial = std::sscanf(map.c_str(), "MAP%d", &number) == 1;
  if (!o.commercial && std::sscanf(map.c_str(), "E%dM%d", &episode, &number) == 2) o.episode = episode;
  o.map = number;
  return o;
}

// Every line's special started as if the player had walked over, used or shot it,
// holding every key (teleporters and exits left out, and doors on one-sided lines,
// which Doom cannot open).
void set_everything_going(play::World& world) {
  play::Mobj* mo = world.player().mo;
  world.player().cards = 63;
  for (play::Line& line : world.map_.lines) {
    switch (line.special) {
      case 0: case 39: case 97: case 125: case 126: case 11: case 51: case 52: case 124: continue;
      case 1: case 26: case 27: case 28: case 31: case 32: case 33: case 34: case 117: case 118:
        if (line.side[1] < 0) continue;
        break;
      default: break;
    }
    world.cross_special_line(line.index, 0, mo);
    if (line.special) world.use_special_line(mo, &line, 0);
    if (line.special) world.shoot_special_line(mo, &line);
  }
}

void check_wad(const std::string& file, size_t cameras_per_map, Tally& t) {
  const auto path = test::freedoom_path(file);
  const Stack wads = bsp::read_wads({path});
  std::vector<std::string> maps = wads.map_names();
#ifdef P3D_SANITIZE
  // Under the sanitizers, a sample: every fourth map.
  std::vector<std::string> sample;
  for (size_t i = 0; i < maps.size(); i += 4) sample.push_back(maps[i]);
  maps = sample;
#endif
  for (const std::string& map : maps) {
    std::vector<std::string> warnings;
    const level::Level level = bsp::build_wad_map(wads, map, {}, &warnings);
    const auto problems = bsp::check_invariants(level);
    EXPECT_TRUE(problems.empty()) << file << ":" << map << ": " << (problems.empty() ? "" : problems.front());
    EXPECT_FALSE(level.light_indices.empty()) << file << ":" << map << ": drawn as palette indices";
    ++t.maps;
    const std::string what = file + ":" + map;
    const level::State start = level::start_state(level);
    const render::Camera at_start = render::camera_at(level, level.player_start, level.player_angle);
    compare_camera(level, start, at_start, 160, 100, t, what + " player start");
    compare_camera(level, start, at_start, 320, 200, t, what + " player start at Doom's size");  // vanilla's rules
    {  // palette indices resolved at the end, or colours at once: the same frame
      level::Level in_colours = level;
      in_colours.light_indices.clear();
      render::Frame indexed(160, 100), colours(160, 100);
      render::make_renderer("bsp")->render(level, start, at_start, indexed);
      render::make_renderer("bsp")->render(in_colours, start, at_start, colours);
      EXPECT_EQ(indexed.pixels, colours.pixels) << what << ": drawn in colours";
    }
    Rng rng(std::hash<std::string>()(map) & 0xFFFF);
    for (size_t i = 0; i < cameras_per_map; ++i) {
      render::Camera c = test::random_camera(level, rng);
      if (i % 2) c.fov = 90;  // Doom's rules
      const int w = 48 + int(rng.below(64)), h = 30 + int(rng.below(40));
      compare_camera(level, start, c, w, h, t, what + " camera " + std::to_string(i));
    }
    // Half-open doors, lowered lifts, crushers half way, flipped switches, lights
    // changed: a second set of cameras on the level in motion.
    play::World world(play::map_from_wads(wads, map, level), level, options_for(map), play::Random{});
    set_everything_going(world);
    for (int tic = 0; tic < 40; ++tic) world.tick({});
    for (size_t i = 0; i < cameras_per_map / 2; ++i) {
      render::Camera c = test::random_camera(level, rng);
      if (i % 2) c.fov = 90;
      compare_camera(level, world.state(), c, 64, 40, t, what + " moving camera " + std::to_string(i));
    }
  }
}

void report(const Tally& t, const char* what) {
  EXPECT_EQ(t.column_mismatches, 0u) << what;
  EXPECT_EQ(t.pixel_mismatches, 0u) << what;
  EXPECT_GT(t.sprites, t.frames) << what << ": crowded maps show more than a sprite a frame";
  std::printf("[ stats    ] %s: %zu maps, %zu frames, %zu columns (%zu differ), %zu pixels (%zu differ), "
              "%zu masked pixels, %zu sprites drawn (%zu pixels)\n",
              what, t.maps, t.frames, t.columns, t.column_mismatches, t.pixels, t.pixel_mismatches, t.masked, t.sprites,
              t.sprite_pixels);
}

TEST(Freedoom, EveryMapOfFreedoom1CompilesAndRendersAsTheReference) {
  Tally t;
  check_wad("freedoom1.wad", 20, t);
  report(t, "freedoom1");
}

TEST(Freedoom, EveryMapOfFreedoom2CompilesAndRendersAsTheReference) {
  Tally t;
  check_wad("freedoom2.wad", 20, t);
  report(t, "freedoom2");
}

// E3M4's hanging bodies stand exactly on lines between sectors 6 and 7 (ceilings 208
// and 272), where our tree says 7: Doom's nodes put THINGS #28, #31 and #32 in sector
// 6, and so must we (Chocolate Doom hangs them from the lower ceiling). THINGS #27 sits
// on a splitter's origin, where Doom's sign-bit shortcut sends it to the front: 7.
// Without node lumps, our own tree decides.
TEST(Freedoom, ThingsOnLinesStandWhereDoomsNodesPutThem) {
  const Stack wads = bsp::read_wads({test::freedoom_path("freedoom1.wad")});
  const level::Level level = bsp::build_wad_map(wads, "E3M4", {}, nullptr);
  EXPECT_EQ(level.things[27].sector, 7);
  for (size_t i : {28, 31, 32}) EXPECT_EQ(level.things[i].sector, 6) << "THINGS #" << i;

  Stack stripped;
  stripped.add(wads.wads().front());
  stripped.add(Wad(map_without_nodes(*wads.map("E3M4")), "no-nodes.wad"));
  const level::Level ours = bsp::build_wad_map(stripped, "E3M4", {}, nullptr);
  for (size_t i : {27, 28, 31, 32}) EXPECT_EQ(ours.things[i].sector, ours.sector_at(ours.things[i].pos));
}

}  // namespace
}  // namespace p3d::wad
