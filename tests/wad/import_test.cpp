// The WAD importer on small maps the tests write: each quirk Doom tolerates is
// repaired or kept with its warning and the map compiles (BSP invariants exact, the
// front-to-back renderer equal to the reference); broken WADs give their message;
// UDMF gives the same level as the binary format; Doom's pegging and masked middles.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "engine/bsp/check.h"
#include "engine/bsp/load.h"
#include "engine/image/image.h"
#include "engine/level/io.h"
#include "engine/play/world.h"
#include "engine/render/renderer.h"
#include "engine/util/error.h"
#include "tests/support/support.h"
#include "tests/support/wad_writer.h"

namespace p3d::wad {
namespace {

using test::TestMap;

// Two rooms: A (0..256 square; floor 0, ceiling 128) and B east of it (256..512;
// floor 16, ceiling 96), joined by line 2 (x = 256), two-sided, its front facing A.
TestMap two_rooms() {
  TestMap m;
  m.sectors.push_back({});
  m.sectors.push_back({16, 96});
  auto line = [&](int x1, int y1, int x2, int y2, int sector) {
    TestMap::Side s;
    s.middle = "WALL";
    s.sector = sector;
    m.lines.push_back({m.add_vertex(x1, y1), m.add_vertex(x2, y2), 1, 0, 0, m.add_side(s)});
  };
  line(0, 0, 0, 256, 0);     // 0: A west
  line(0, 256, 256, 256, 0);  // 1: A north
  TestMap::Side front, back;
  front.upper = front.lower = "WALL";
  back.sector = 1;
  m.lines.push_back({m.add_vertex(256, 256), m.add_vertex(256, 0), 4, 0, 0, m.add_side(front), m.add_side(back)});  // 2
  line(256, 0, 0, 0, 0);      // 3: A south
  line(256, 256, 512, 256, 1);  // 4: B north
  line(512, 256, 512, 0, 1);    // 5: B east
  line(512, 0, 256, 0, 1);      // 6: B south
  m.things.push_back({64, 128, 0, 1, 7});
  return m;
}

struct Built {
  level::Level level;
  std::vector<std::string> warnings;
};

Stack stack_of(const TestMap& m, bool udmf = false) {
  test::WadWriter w(true);
  test::add_test_art(w);
  if (udmf) {
    w.lump("MAP01");
    w.text_lump("TEXTMAP", m.udmf());
    w.lump("ENDMAP");
  } else {
    m.add_to(w, "MAP01");
  }
  Stack stack;
  stack.add(Wad(w.bytes(), "test.wad"));
  return stack;
}

Built build(const TestMap& m, bool udmf = false) {
  const Stack stack = stack_of(m, udmf);
  Built b;
  b.level = bsp::build_wad_map(stack, "MAP01", {}, &b.warnings);
  return b;
}

std::string build_error(const TestMap& m) {
  try {
    build(m);
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

::testing::AssertionResult has_warning(const Built& b, const std::string& text) {
  for (const std::string& w : b.warnings)
    if (w.find(text) != std::string::npos) return ::testing::AssertionSuccess();
  std::string all;
  for (const std::string& w : b.warnings) all += "\n  " + w;
  return ::testing::AssertionFailure() << "no warning containing '" << text << "' among:" << all;
}

// The compiled level is sound: exact invariants, and bsp renders exactly as the
// reference and the painter. The first two draw palette indices and resolve them at the
// end, the painter writes colours at once; so does bsp on a copy of the level without
// its index light maps. Frames that keep their indices give the same picture.
void expect_sound(const level::Level& level, const std::string& what) {
  const auto problems = bsp::check_invariants(level);
  EXPECT_TRUE(problems.empty()) << what << ": " << (problems.empty() ? "" : problems.front());
  ASSERT_FALSE(level.light_indices.empty()) << what << ": the test art's shades are palette colours";
  level::Level in_colours = level;
  in_colours.light_indices.clear();
  Rng rng(7);
  for (int i = 0; i < 24; ++i) {
    const render::Camera c = i == 0 ? render::camera_at(level, level.player_start, level.player_angle)
                                    : test::random_camera(level, rng);
    render::Frame a(64, 40), b(64, 40), painted(64, 40), direct(64, 40);
    render::make_renderer("bsp", {.threads = 2})->render(level, c, a);
    render::make_renderer("reference")->render(level, c, b);
    render::make_renderer("painter")->render(level, c, painted);
    render::make_renderer("bsp")->render(in_colours, c, direct);
    EXPECT_EQ(a.pixels, b.pixels) << what << " camera " << i;
    EXPECT_EQ(a.pixels, painted.pixels) << what << " camera " << i << ": the painter";
    EXPECT_EQ(a.pixels, direct.pixels) << what << " camera " << i << ": drawn in colours";
    EXPECT_FALSE(a.indexed() || b.indexed() || painted.indexed() || direct.indexed()) << "not asked to keep indices";
    // Frames that keep their indices (Doom's 8-bit screen): the same picture, pixels untouched.
    for (const char* name : {"bsp", "reference", "painter"}) {
      render::Frame kept(64, 40, image::rgba(1, 2, 3));
      kept.keep_indices = true;
      render::make_renderer(name, {.threads = 2})->render(level, c, kept);
      if (std::string_view(name) == "painter") {  // it draws over its own pixels, in colours
        EXPECT_FALSE(kept.indexed());
        EXPECT_EQ(kept.pixels, a.pixels) << what << " camera " << i << ": " << name;
        continue;
      }
      ASSERT_TRUE(kept.indexed()) << name;
      EXPECT_EQ(kept.palette, level.palette);
      EXPECT_EQ(kept.pixels, std::vector<uint32_t>(kept.pixels.size(), image::rgba(1, 2, 3))) << name;
      kept.resolve_colours();
      EXPECT_EQ(kept.pixels, a.pixels) << what << " camera " << i << ": " << name << " keeping indices";
    }
  }
}

// Found by fuzzing: a map whose every line is dropped (here: all zero-length) left an
// empty tree that the checker and point location read past. It is an error now.
TEST(Import, AMapWithNoUsableLinesIsAnError) {
  TestMap m;
  m.sectors.push_back({});
  TestMap::Side s;
  s.middle = "WALL";
  for (int i = 0; i < 3; ++i) m.lines.push_back({m.add_vertex(16 * i, 0), m.add_vertex(16 * i, 0), 1, 0, 0, m.add_side(s)});
  m.things.push_back({8, 8, 0, 1, 7});
  EXPECT_EQ(build_error(m), "test.wad:MAP01: no usable lines: there is no level to build");
}

TEST(Import, AValidMapCompilesWithoutWarnings) {
  const Built b = build(two_rooms());
  EXPECT_TRUE(b.warnings.empty()) << b.warnings.front();
  const level::Level& l = b.level;
  EXPECT_EQ(l.walls.size(), 7u);
  EXPECT_EQ(l.walls[2].source, 2);
  EXPECT_TRUE(l.walls[2].two_sided());
  EXPECT_EQ(l.title, "MAP01");
  EXPECT_EQ(l.player_start, geom::Vec2(64, 128));
  EXPECT_TRUE(l.paletted());
  ASSERT_NE(l.sky_texture, level::kNone);
  EXPECT_EQ(l.textures[size_t(l.sky_texture)].name, "SKY1");
  // Only the art the map uses is embedded: WALL, the two flats, the sky.
  EXPECT_EQ(l.textures.size(), 4u);
  expect_sound(l, "two rooms");
}

TEST(Import, UdmfGivesTheSameLevelAsTheBinaryFormat) {
  const Built binary = build(two_rooms()), udmf = build(two_rooms(), true);
  EXPECT_TRUE(udmf.warnings.empty());
  ASSERT_EQ(udmf.level.walls.size(), binary.level.walls.size());
  for (size_t i = 0; i < binary.level.walls.size(); ++i) {
    EXPECT_EQ(udmf.level.walls[i].p1, binary.level.walls[i].p1);
    EXPECT_EQ(udmf.level.walls[i].p2, binary.level.walls[i].p2);
    EXPECT_EQ(udmf.level.walls[i].flags, binary.level.walls[i].flags);
    for (int s = 0; s < 2; ++s) {
      EXPECT_EQ(udmf.level.walls[i].sides[s].sector, binary.level.walls[i].sides[s].sector);
      EXPECT_EQ(udmf.level.walls[i].sides[s].upper, binary.level.walls[i].sides[s].upper);
      EXPECT_EQ(udmf.level.walls[i].sides[s].middle, binary.level.walls[i].sides[s].middle);
    }
  }
  for (size_t s = 0; s < binary.level.sectors.size(); ++s) {
    EXPECT_EQ(udmf.level.sectors[s].floor, binary.level.sectors[s].floor);
    EXPECT_EQ(udmf.level.sectors[s].ceiling, binary.level.sectors[s].ceiling);
    EXPECT_EQ(udmf.level.sectors[s].light, binary.level.sectors[s].light);
  }
  EXPECT_EQ(udmf.level.things.size(), binary.level.things.size());
  EXPECT_EQ(udmf.level.things[0].flags, binary.level.things[0].flags);
}

// ---- quirks Doom tolerates: repaired or kept, with a warning ---------------------

TEST(Import, CeilingBelowFloorIsKept) {
  TestMap m = two_rooms();
  m.sectors[1].ceiling = 10;  // below its floor of 16
  const Built b = build(m);
  EXPECT_TRUE(has_warning(b, "test.wad:MAP01: SECTORS #1: warning: ceiling 10 is below floor 16"));
  EXPECT_EQ(b.level.sectors[1].ceiling, 10);
  expect_sound(b.level, "inverted sector");
}

TEST(Import, CrossingLinesAreKept) {
  TestMap m = two_rooms();
  TestMap::Side trigger;
  const int s = m.add_side(trigger);
  m.lines.push_back({m.add_vertex(32, 32), m.add_vertex(200, 200), 4, 2, 0, s, s});
  m.lines.push_back({m.add_vertex(32, 200), m.add_vertex(200, 32), 4, 2, 0, s, s});
  const Built b = build(m);
  EXPECT_TRUE(has_warning(b, "LINEDEFS #8: warning: crosses LINEDEFS #7 (both kept, as Doom draws both)"));
  expect_sound(b.level, "crossing");
}

TEST(Import, DuplicateAndOverlappingLinesKeepTheEarlierOne) {
  TestMap m = two_rooms();
  // Line 2 again, reversed (the E3M6 quirk), and a two-sided piece overlapping A's north wall.
  TestMap::Side a, bside;
  bside.sector = 1;
  m.lines.push_back({m.lines[2].v2, m.lines[2].v1, 4, 0, 0, m.add_side(bside), m.add_side(a)});  // 7
  m.lines.push_back({m.add_vertex(128, 256), m.add_vertex(384, 256), 4, 0, 0, m.add_side(a), m.add_side(bside)});  // 8
  const Built b = build(m);
  EXPECT_TRUE(has_warning(b, "LINEDEFS #7: warning: lies on LINEDEFS #2 (dropped: the earlier line is drawn)"));
  EXPECT_TRUE(has_warning(b, "LINEDEFS #8: warning: lies on LINEDEFS #1, LINEDEFS #4 (dropped"));
  for (const level::Wall& w : b.level.walls) EXPECT_NE(w.source, 7);
  // Line 8 keeps nothing: lines 1 and 4 cover it.
  for (const level::Wall& w : b.level.walls) EXPECT_NE(w.source, 8);
  expect_sound(b.level, "overlaps");
}

TEST(Import, OverlapsKeepTheUncoveredPieceWithItsTextureAlignment) {
  TestMap m = two_rooms();
  TestMap::Side s;
  s.middle = "WALL";
  s.x_offset = 5;
  // A one-sided wall over A's south wall (3: 256,0 -> 0,0) and beyond it to x = -128, same direction.
  m.lines.push_back({m.add_vertex(128, 0), m.add_vertex(-128, 0), 1, 0, 0, m.add_side(s)});  // 7
  const Built b = build(m);
  EXPECT_TRUE(has_warning(b, "LINEDEFS #7: warning: overlaps LINEDEFS #3 (keeps only the part the earlier line leaves)"));
  int pieces = 0;
  for (const level::Wall& w : b.level.walls)
    if (w.source == 7) {
      ++pieces;
      EXPECT_EQ(geom::to_world(w.p1), geom::Vec2(0, 0));
      EXPECT_EQ(geom::to_world(w.p2), geom::Vec2(-128, 0));
      EXPECT_EQ(w.sides[0].x_offset, 5 + 128);  // the texture stays where the whole line put it
    }
  EXPECT_EQ(pieces, 1);
}

TEST(Import, LinesFacingApartOnOneStretchAreBothKept) {
  TestMap m = two_rooms();
  // A thin wall: one-sided lines on the same stretch facing apart.
  TestMap::Side s;
  s.middle = "WALL";
  m.lines.push_back({m.add_vertex(64, 64), m.add_vertex(64, 192), 1, 0, 0, m.add_side(s)});
  m.lines.push_back({m.add_vertex(64, 192), m.add_vertex(64, 64), 1, 0, 0, m.add_side(s)});
  const Built b = build(m);
  EXPECT_FALSE(has_warning(b, "LINEDEFS #8"));
  EXPECT_EQ(b.level.walls.size(), 9u);
  expect_sound(b.level, "thin wall");
}

TEST(Import, SameSectorOnBothSidesIsKept) {
  TestMap m = two_rooms();
  TestMap::Side s;
  const int side = m.add_side(s);
  m.lines.push_back({m.add_vertex(64, 64), m.add_vertex(64, 192), 4, 0, 0, side, side});
  const Built b = build(m);
  EXPECT_TRUE(has_warning(b, "LINEDEFS #7: warning: sector 0 on both sides, no special, no texture"));
  expect_sound(b.level, "self-referencing");
}

TEST(Import, UnclosedSectorsAreKept) {
  TestMap m = two_rooms();
  m.lines.erase(m.lines.begin() + 5);  // B's east wall
  const Built b = build(m);
  EXPECT_TRUE(has_warning(b, "SECTORS #1: warning: not closed: its boundary has an open end at (512, 0)"));
  EXPECT_TRUE(bsp::check_invariants(b.level).empty());
}

// Doom's rule for a sector left open: every point is in its subsector's sector. Here B
// lacks its east wall: inside B, and out past where the wall would be, a camera stands
// in a sector (the floor and ceiling the tree puts there), and every renderer draws
// what the reference draws, to the bit.
TEST(Import, UnclosedSectorsGiveEveryPointItsLeafsSector) {
  TestMap m = two_rooms();
  m.lines.erase(m.lines.begin() + 5);  // B's east wall
  const Built b = build(m);
  const level::Level& l = b.level;
  EXPECT_EQ(l.sector_at({400, 128}), l.walls[4].sides[0].sector) << "inside B";
  for (const geom::Vec2 p : {geom::Vec2{400, 128}, geom::Vec2{530, 128}, geom::Vec2{700, 40}, geom::Vec2{600, 300}}) {
    ASSERT_NE(l.sector_at(p), level::kNone) << p.x << "," << p.y;
    for (double angle = 0; angle < 360; angle += 45) {
      const render::Camera camera = render::camera_at(l, p, angle);
      render::Frame expected(96, 60);
      render::make_renderer("reference")->render(l, camera, expected);
      for (const std::string& name : render::renderer_names()) {
        const auto renderer = render::make_renderer(name);
        if (!renderer->supports(l)) continue;
        render::Frame frame(96, 60);
        renderer->render(l, camera, frame);
        EXPECT_EQ(frame.pixels, expected.pixels) << name << " at " << p.x << "," << p.y << " angle " << angle;
      }
    }
  }
}

// Debian's wadc example `bsp` (wadccli --seed=69 bsp.wl): rooms in the cells of a
// partition whose outlines, drawn as lines of no sector, wadc gives sector 0, which is
// left open (an open end at (-2048, -1575)); they face out of their cells. A camera in
// that open area sees the one room wall facing it and nothing else: Chocolate Doom,
// with ZDBSP's nodes, from (-2015, -784) at 120.9375 degrees (a start facing 135
// degrees, then one tic's turn of -10 << 8), 320 wide, draws LINEDEF 79 in columns 257
// to 319 and no wall in the others (its floor and ceiling there are not drawn at all).
TestMap wadc_bsp_example() {
  const int floors[] = {-16, -16, -16, -16, -24, -24, -24, -24, -32, -32, -32, -32, -32, -32, -32, -32};
  // LINEDEFS in order: x1, y1, x2, y2, front sector, back sector (-1: one-sided).
  const int lines[][6] = {
      {0, -641, 0, 0, 0, -1}, {-449, -2048, 0, -2048, 0, -1}, {-2048, -1575, -2048, -2048, 0, -1}, {-1625, 0, -2048, 0, 0, -1},
      {-441, 0, -909, 0, 0, -1}, {-1460, -2048, -909, -2048, 0, -1}, {-909, -2009, -909, -2048, 0, -1}, {-909, 0, -909, -641, 0, -1},
      {0, -2048, 0, -641, 0, -1}, {-67, -641, 0, -641, 0, -1}, {-441, -641, -449, -641, 0, 2}, {-909, -641, -728, -641, 0, -1},
      {-728, -641, -728, -269, 0, -1}, {-728, -269, -441, -269, 0, -1}, {-441, -269, -441, -641, 0, -1}, {0, 0, -162, 0, 0, -1},
      {-441, 0, -162, 0, 1, -1}, {-162, 0, -162, -135, 1, -1}, {-162, -135, -441, -135, 1, -1}, {-441, -135, -441, 0, 1, -1},
      {-441, -641, -67, -641, 2, -1}, {-449, -641, -728, -641, 0, -1}, {-67, -641, -67, -884, 2, -1}, {-67, -884, -449, -884, 2, -1},
      {-449, -884, -449, -719, 2, 3}, {-449, -2048, -707, -2048, 3, -1}, {-909, -2048, -707, -2048, 0, -1}, {-707, -2048, -707, -719, 3, -1},
      {-707, -719, -449, -719, 3, -1}, {-449, -884, -449, -2048, 3, -1}, {-449, -719, -449, -641, 2, -1}, {-909, -641, -909, -1160, 0, -1},
      {-2048, -604, -2048, -1160, 0, -1}, {-2036, -1160, -2048, -1160, 0, -1}, {-1266, -1160, -1460, -1160, 0, -1}, {-2048, -2048, -1460, -2048, 0, -1},
      {-1460, -1878, -1460, -2048, 0, -1}, {-1460, -1602, -1460, -1575, 4, 6}, {-1460, -1160, -1460, -1215, 0, -1}, {-1460, -1215, -1238, -1215, 4, -1},
      {-1238, -1215, -1238, -1602, 4, -1}, {-1238, -1602, -1340, -1602, 4, 5}, {-909, -1602, -909, -2009, 5, -1}, {-909, -1160, -909, -1602, 0, -1},
      {-909, -2009, -1340, -2009, 5, -1}, {-1340, -2009, -1340, -1602, 5, -1}, {-1238, -1602, -909, -1602, 5, -1}, {-1340, -1602, -1460, -1602, 4, -1},
      {-1460, -1602, -1460, -1878, 6, -1}, {-1460, -1575, -1460, -1215, 4, -1}, {-1460, -1878, -1908, -1878, 6, -1}, {-1908, -1878, -1908, -1575, 6, -1},
      {-1908, -1575, -1907, -1575, 6, 7}, {-2048, -1575, -2048, -1188, 7, -1}, {-2048, -1160, -2048, -1188, 0, -1}, {-2048, -1188, -1907, -1188, 7, -1},
      {-1907, -1188, -1907, -1575, 7, -1}, {-1908, -1575, -2048, -1575, 7, -1}, {-1907, -1575, -1460, -1575, 6, -1}, {-1460, -1160, -1531, -1160, 0, -1},
      {-1108, 0, -1531, 0, 0, -1}, {-1531, 0, -1531, -495, 11, -1}, {-1531, -641, -1531, -604, 0, -1}, {-2048, 0, -2048, -604, 0, -1},
      {-2014, -604, -2048, -604, 0, -1}, {-1531, -604, -1574, -604, 0, -1}, {-1866, -604, -1625, -604, 8, 10}, {-1574, -604, -1574, -1114, 8, -1},
      {-1574, -1114, -1866, -1114, 8, -1}, {-1866, -1114, -1866, -861, 8, 9}, {-1531, -1160, -1866, -1160, 0, -1}, {-1866, -1160, -2036, -1160, 9, -1},
      {-2036, -1160, -2036, -861, 9, -1}, {-2036, -861, -1866, -861, 9, -1}, {-1866, -1114, -1866, -1160, 9, -1}, {-1866, -861, -1866, -604, 8, -1},
      {-1866, -604, -2014, -604, 10, -1}, {-1625, -604, -1574, -604, 8, -1}, {-2014, -604, -2014, -461, 10, -1}, {-2014, -461, -1625, -461, 10, -1},
      {-1625, -461, -1625, -495, 10, 11}, {-1625, 0, -1531, 0, 11, -1}, {-1531, -604, -1531, -495, 0, -1}, {-1531, -495, -1625, -495, 11, -1},
      {-1625, -461, -1625, 0, 11, -1}, {-1625, -495, -1625, -604, 10, -1}, {-1531, -1160, -1531, -641, 0, -1}, {-974, -641, -909, -641, 0, -1},
      {-1108, -641, -1137, -641, 12, 14}, {-1531, -641, -1512, -641, 0, -1}, {-1512, -641, -1512, -512, 12, -1}, {-1512, -512, -1108, -512, 12, -1},
      {-1108, -512, -1108, -641, 12, -1}, {-909, 0, -959, 0, 0, -1}, {-1108, 0, -959, 0, 13, -1}, {-959, 0, -959, -464, 13, -1},
      {-959, -464, -1108, -464, 13, -1}, {-1108, -464, -1108, 0, 13, -1}, {-1108, -641, -974, -641, 14, -1}, {-1137, -641, -1512, -641, 12, -1},
      {-974, -641, -974, -974, 14, -1}, {-974, -974, -1137, -974, 14, -1}, {-1137, -974, -1137, -649, 14, 15}, {-909, -1160, -1137, -1160, 0, -1},
      {-1137, -1160, -1266, -1160, 15, -1}, {-1266, -1160, -1266, -649, 15, -1}, {-1266, -649, -1137, -649, 15, -1}, {-1137, -974, -1137, -1160, 15, -1},
      {-1137, -649, -1137, -641, 14, -1},
  };
  TestMap m;
  for (const int floor : floors) {
    TestMap::Sector s;
    s.floor = floor;
    m.sectors.push_back(s);
  }
  for (const auto& l : lines) {
    TestMap::Side front;
    front.sector = l[4];
    front.upper = front.lower = "WALL";
    if (l[5] < 0) {
      front.middle = "WALL";
      m.lines.push_back({m.add_vertex(l[0], l[1]), m.add_vertex(l[2], l[3]), TestMap::kBlocking, 0, 0, m.add_side(front)});
      continue;
    }
    TestMap::Side back = front;
    back.sector = l[5];
    m.lines.push_back({m.add_vertex(l[0], l[1]), m.add_vertex(l[2], l[3]), TestMap::kTwoSided, 0, 0, m.add_side(front), m.add_side(back)});
  }
  m.things.push_back({-32, -32, 270});
  return m;
}

TEST(Import, AnOpenAreaSeesTheWallsDoomDraws) {
  const Built b = build(wadc_bsp_example());
  EXPECT_TRUE(has_warning(b, "SECTORS #0: warning: not closed: its boundary has an open end at (-2048, -1575)"));
  const level::Level& l = b.level;
  EXPECT_TRUE(bsp::check_invariants(l).empty());
  {
    const render::Camera camera = render::camera_at(l, {-2015, -784}, 120.9375);
    render::Frame frame(320, 200);
    render::Probe probe;
    probe.want_columns = true;
    render::make_renderer("reference")->render(l, camera, frame, &probe);
    ASSERT_EQ(probe.columns.size(), 320u);
    for (int x = 0; x < 320; ++x) {
      const int32_t wall = probe.columns[size_t(x)].wall;
      if (x < 257) EXPECT_EQ(wall, level::kNone) << "column " << x;
      else EXPECT_TRUE(wall != level::kNone && l.walls[size_t(wall)].source == 79) << "column " << x;
    }
  }
  // The view the issue names, (-2014.75, -784.5) at 121.3 degrees: every renderer as the reference.
  for (const double angle : {121.3, 135.0, 90.0, 200.0}) {
    const render::Camera camera = render::camera_at(l, {-2014.75, -784.5}, angle);
    render::Frame expected(160, 100);
    render::make_renderer("reference")->render(l, camera, expected);
    for (const std::string& name : render::renderer_names()) {
      const auto renderer = render::make_renderer(name);
      if (!renderer->supports(l)) continue;
      render::Frame frame(160, 100);
      renderer->render(l, camera, frame);
      EXPECT_EQ(frame.pixels, expected.pixels) << name << " angle " << angle;
    }
  }
}

TEST(Import, ZeroLengthLinesAreDropped) {
  TestMap m = two_rooms();
  m.lines.push_back({0, 0, 1, 0, 0, 0});
  const Built b = build(m);
  EXPECT_TRUE(has_warning(b, "LINEDEFS #7: warning: zero-length line (dropped)"));
  EXPECT_EQ(b.level.walls.size(), 7u);
}

TEST(Import, UnknownTexturesAndFlatsAreMissing) {
  TestMap m = two_rooms();
  m.sides[0].middle = "NOPE";
  m.sectors[1].floor_flat = "NOFLAT";
  m.sides[2].upper = "-";  // needed: B's ceiling is lower
  const Built b = build(m);
  EXPECT_TRUE(has_warning(b, "LINEDEFS #0: warning: texture NOPE does not exist (drawn as missing)"));
  EXPECT_TRUE(has_warning(b, "SECTORS #1: warning: flat NOFLAT does not exist (drawn as a placeholder)"));
  EXPECT_TRUE(has_warning(b, "LINEDEFS #0: warning: one-sided line without a middle texture"));
  EXPECT_TRUE(has_warning(b, "LINEDEFS #2: warning: front side needs an upper texture (the far ceiling shows instead)"));
  expect_sound(b.level, "missing textures");
}

TEST(Import, BadSideReferencesAreRepaired) {
  TestMap m = two_rooms();
  m.lines[0].front = 999;      // no front side: dropped
  m.lines[2].back = 888;       // no back side: one-sided
  m.sides[1].sector = 77;      // line 1's front names no sector: dropped
  const Built b = build(m);
  EXPECT_TRUE(has_warning(b, "LINEDEFS #0: warning: front sidedef 999 does not exist (SIDEDEFS has 8) (line dropped)"));
  EXPECT_TRUE(has_warning(b, "LINEDEFS #2: warning: back sidedef 888 does not exist (SIDEDEFS has 8) (line made one-sided)"));
  EXPECT_TRUE(has_warning(b, "LINEDEFS #1: warning: front SIDEDEFS #1 names sector 77, which does not exist (SECTORS has 2)"));
  for (const level::Wall& w : b.level.walls) EXPECT_TRUE(w.source != 0 && w.source != 1);
  EXPECT_TRUE(bsp::check_invariants(b.level).empty());
}

TEST(Import, NoPlayerStartAndOutOfRangeLight) {
  TestMap m = two_rooms();
  m.things.clear();
  m.sectors[0].light = 300;
  const Built b = build(m);
  EXPECT_TRUE(has_warning(b, "THINGS: warning: no player 1 start (the player starts beside the first line)"));
  EXPECT_TRUE(has_warning(b, "SECTORS #0: warning: light 300 is outside 0..255 (clamped)"));
  EXPECT_EQ(b.level.sectors[0].light, 255);
  EXPECT_NE(b.level.sector_at(b.level.player_start), level::kNone);
}

// ---- maps that cannot be built: clear errors ---------------------------------------

TEST(Import, BrokenMapsGiveTheirMessage) {
  TestMap m = two_rooms();
  m.lines[3].v2 = 40;
  EXPECT_EQ(build_error(m), "test.wad:MAP01: LINEDEFS #3: vertex 40 does not exist (VERTEXES has 6)");

  test::WadWriter w(true);
  test::add_test_art(w);
  two_rooms().add_to(w, "MAP01");
  w.lump("MAP02");
  w.lump("THINGS", {1, 2, 3});  // not a whole number of 10-byte records
  Stack stack;
  stack.add(Wad(w.bytes(), "test.wad"));
  try {
    bsp::build_wad_map(stack, "MAP02", {}, nullptr);
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), "test.wad:MAP02: the map has no VERTEXES lump");
  }
  try {
    bsp::build_wad_map(stack, "MAP07", {}, nullptr);
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), "test.wad: no map MAP07 (maps: MAP01 MAP02)");
  }
}

TEST(Import, UdmfErrorsAreLocated) {
  struct Case {
    std::string text, message;
  };
  const std::vector<Case> cases = {
      {"vertex { x = 1; }", "w:M: TEXTMAP:1: no 'namespace = \"...\";' statement"},
      {"namespace = \"doom\";\nvertex { x = 1 }", "w:M: TEXTMAP:2: expected ';', found '}'"},
      {"namespace = \"doom\";\n\nvertex { x = \"one\"; }", "w:M: TEXTMAP:3: 'x' must be a number"},
      {"namespace = \"doom\";\nlinedef { v1 = 0; v2 = 1; sidefront = 0; }", "w:M: TEXTMAP:2: linedef #0: vertex 0 does not exist (0 vertices come before it)"},
      {"namespace = \"doom\";\nlinedef { v1 = 0; }", "w:M: TEXTMAP:2: linedef #0 needs v1, v2 and sidefront"},
      {"namespace = \"doom\";\n/* never closed", "w:M: TEXTMAP:2: comment never closed"},
      {"namespace = \"doom\";\nthing { ambush = maybe; }", "w:M: TEXTMAP:2: 'ambush' must be true or false"},
      {"namespace = \"doom\";\nvertex { x = 0x; }", "w:M: TEXTMAP:2: '0x' is not a number"},
  };
  for (const Case& c : cases) {
    try {
      parse_udmf(c.text, "w:M");
      ADD_FAILURE() << c.text;
    } catch (const Error& e) {
      EXPECT_EQ(std::string(e.what()), c.message);
    }
  }
  const MapData d = parse_udmf("namespace = \"zdoom\"; vertex { x = -0x10; y = 1.5e1; unknownkey = \"ignored\"; }\n"
                               "sidedef { sector = 0; offsetx_mid = 4.5; light = 16; }\nfoo { bar = 1; }",
                               "w:M");
  ASSERT_EQ(d.vertices.size(), 1u);
  EXPECT_EQ(d.vertices[0].x, -16);
  EXPECT_EQ(d.vertices[0].y, 15);
  EXPECT_EQ(d.sidedefs[0].part_x[1], 4.5);
  EXPECT_EQ(d.sidedefs[0].light, 16);
}

TEST(Import, APwadMapUsesTheIwadArtAndOverridesItsMap) {
  test::WadWriter iwad(true), pwad;
  test::add_test_art(iwad);
  two_rooms().add_to(iwad, "MAP01");
  TestMap mine = two_rooms();
  mine.sectors[0].light = 96;
  mine.add_to(pwad, "MAP01");
  pwad.lump("F_START");
  pwad.lump("FLOOR", std::vector<uint8_t>(64 * 64, 200));  // a replacement flat
  pwad.lump("F_END");
  Stack stack;
  stack.add(Wad(iwad.bytes(), "doom.wad"));
  stack.add(Wad(pwad.bytes(), "mine.wad"));
  std::vector<std::string> warnings;
  const level::Level l = bsp::build_wad_map(stack, "map01", {}, &warnings);
  EXPECT_EQ(l.sectors[0].light, 96);
  const level::Texture& floor = l.textures[size_t(l.sectors[0].floor_texture)];
  EXPECT_EQ(floor.indices[0], 200);
  EXPECT_EQ(bsp::resolve_map_name(stack, ""), "MAP01");
}

// ---- drawing: Doom's pegging and masked middles ------------------------------------

// The texel row of each pixel of column x (the test art's WALL texture encodes its
// row in the palette index: red = row + 100), or -1 where the pixel is not WALL.
std::vector<int> texel_rows(const level::Level& level, const render::Camera& camera, int x) {
  render::Frame frame(160, 100);
  render::make_renderer("bsp")->render(level, camera, frame);
  std::vector<int> rows;
  for (int y = 0; y < frame.height; ++y) {
    const uint32_t c = frame.at(x, y);
    const int row = int(image::red(c)) - 100;
    rows.push_back(row >= 0 && row < 72 && image::green(c) == 255 - image::red(c) ? row : -1);
  }
  return rows;
}

int first_wall_row(const std::vector<int>& rows) {
  for (int r : rows)
    if (r >= 0) return r;
  return -1;
}
int last_wall_row(const std::vector<int>& rows) {
  for (auto it = rows.rbegin(); it != rows.rend(); ++it)
    if (*it >= 0) return *it;
  return -1;
}

// A column through a two-sided line's opening: its first run of WALL rows from the top
// is the upper part, its last from the bottom the lower part (the far room's walls show
// through the opening between them).
std::pair<std::vector<int>, std::vector<int>> upper_and_lower(const std::vector<int>& rows) {
  std::vector<int> upper, lower;
  size_t y = 0;
  while (y < rows.size() && rows[y] < 0) ++y;
  for (; y < rows.size() && rows[y] >= 0; ++y) upper.push_back(rows[y]);
  size_t end = rows.size();
  while (end > 0 && rows[end - 1] < 0) --end;
  for (; end > 0 && rows[end - 1] >= 0; --end) lower.insert(lower.begin(), rows[end - 1]);
  return {upper, lower};
}

TEST(Import, DoomPeggingAndTexturesOf72RowsWrap) {
  // One room 0..256 with a 96-high ceiling, lit full bright; the east wall faces the camera.
  TestMap m;
  m.add_room({{0, 0}, {0, 256}, {256, 256}, {256, 0}}, {0, 96, "FLOOR", "CEIL", 255});
  m.things.push_back({128, 128, 0, 1, 7});
  const render::Camera camera{{128, 128}, 41, 0, 90};
  std::vector<int> rows = texel_rows(build(m).level, camera, 80);
  EXPECT_LE(first_wall_row(rows), 1);  // pegged: the texture hangs from the ceiling
  // 96 units of a 72-row texture: it wraps once, by modulo.
  bool wrapped = false;
  for (size_t y = 1; y < rows.size(); ++y)
    if (rows[y] >= 0 && rows[y - 1] >= 0 && rows[y] < rows[y - 1]) wrapped = true;
  EXPECT_TRUE(wrapped);

  m.lines[2].flags |= 16;  // lower unpegged: a one-sided wall's texture stands on the floor
  rows = texel_rows(build(m).level, camera, 80);
  EXPECT_GE(last_wall_row(rows), 70);
}

TEST(Import, UpperAndLowerTexturesFollowDoomsRules) {
  // From A, facing line 2: the upper part (96..128) and the lower part (0..16).
  TestMap m = two_rooms();
  m.sectors[0].light = m.sectors[1].light = 255;
  const render::Camera camera{{100, 128}, 41, 0, 90};
  auto parts = [&](const TestMap& map) { return upper_and_lower(texel_rows(build(map).level, camera, 80)); };
  auto [upper, lower] = parts(m);
  ASSERT_FALSE(upper.empty());
  ASSERT_FALSE(lower.empty());
  EXPECT_GE(upper.back(), 70);  // the upper texture rests on the far ceiling
  EXPECT_LE(lower.front(), 1);  // the lower texture hangs from the far floor
  m.lines[2].flags |= 8 | 16;   // upper unpegged: from the near ceiling; lower unpegged: from the near ceiling too
  std::tie(upper, lower) = parts(m);
  EXPECT_LE(upper.front(), 1);
  // 128 - 16 = 112 units from the near ceiling down to the far floor: row 112 mod 72 = 40 there.
  EXPECT_NEAR(lower.front(), 40, 1);
}

// UDMF's per-part offsets move their part's texture only; a middle's equals the side's
// own offset of the binary format, pixel for pixel.
TEST(Import, UdmfPartOffsetsMoveOnlyTheirPart) {
  TestMap m = two_rooms();
  m.sectors[0].light = m.sectors[1].light = 255;
  const render::Camera east{{100, 128}, 41, 0, 90};
  auto parts = [&](const TestMap& map) { return upper_and_lower(texel_rows(build(map, true).level, east, 80)); };
  auto shifted = [](std::vector<int> rows, int by) {
    for (int& r : rows) r = (r + by) % 72;
    return rows;
  };
  const auto [upper, lower] = parts(m);
  ASSERT_FALSE(upper.empty());
  ASSERT_FALSE(lower.empty());
  TestMap::Side& front = m.sides[size_t(m.lines[2].front)];
  front.udmf_fields = "offsety_top = 8;";
  EXPECT_EQ(parts(m), std::make_pair(shifted(upper, 8), lower));
  front.udmf_fields = "offsety_bottom = 5; offsety_mid = 30;";  // no middle texture: the mid offset shows nowhere
  EXPECT_EQ(parts(m), std::make_pair(upper, shifted(lower, 5)));

  const render::Camera west{{128, 128}, 41, 180, 90};
  TestMap plain = two_rooms(), udmf = two_rooms();
  plain.sides[size_t(plain.lines[0].front)].y_offset = 8;
  plain.sides[size_t(plain.lines[0].front)].x_offset = 3;
  udmf.sides[size_t(udmf.lines[0].front)].udmf_fields = "offsety_mid = 8; offsetx_mid = 3;";
  render::Frame a(160, 100), b(160, 100), c(160, 100);
  render::make_renderer("bsp")->render(build(plain).level, west, a);
  render::make_renderer("bsp")->render(build(udmf, true).level, west, b);
  render::make_renderer("bsp")->render(build(two_rooms(), true).level, west, c);
  EXPECT_EQ(a.pixels, b.pixels);
  EXPECT_NE(b.pixels, c.pixels);  // the offsets show
}

TEST(Import, MaskedMiddlesShowWhatIsBehindAndAreNotTiled) {
  TestMap m = two_rooms();
  m.sectors[0].light = 255;     // full bright: every texel keeps its palette index
  m.sectors[1] = m.sectors[0];  // the same heights: nothing above or below the opening
  m.sides[2].upper = m.sides[2].lower = "-";
  m.sides[2].middle = "MESH";   // 32 rows high, every other column transparent
  const Built b = build(m);
  const render::Camera camera{{100, 128}, 41, 0, 90};
  render::Frame frame(160, 100);
  render::Probe probe;
  const render::RenderStats s = render::make_renderer("bsp")->render(b.level, camera, frame, &probe);
  EXPECT_GT(s.masked_pixels, 0u);
  EXPECT_EQ(s.pixels_written, 160u * 100);
  // MESH (index 40, red 40) hangs from the ceiling (128) down to 96: 32 units, once.
  const double scale = (160 / 2.0) / (256 - 100);  // pixels per unit at the line's depth
  const int mesh_bottom = int(50 - (96 - 41) * scale);
  int mesh = 0, through = 0;
  for (int y = 0; y < frame.height; ++y)
    for (int x = 40; x < 120; ++x) {
      const bool is_mesh = image::red(frame.at(x, y)) == 40;
      if (y > mesh_bottom + 1) {
        EXPECT_FALSE(is_mesh) << "tiled below the texture at row " << y;
      }
      if (y < mesh_bottom - 1 && y > 10) (is_mesh ? mesh : through)++;
    }
  EXPECT_GT(mesh, 0);
  EXPECT_GT(through, 0);  // the holes show the room behind
  expect_sound(b.level, "masked");
}

// mapc imports a map without its pictures' colours (ImportOptions::colours false): the
// compiled level it writes is the same, byte for byte, as from the coloured import,
// holes (a masked middle, the things' sprites) and all, and reads back in colours.
TEST(Import, ALevelImportedWithoutColoursWritesTheSameBytes) {
  TestMap m = two_rooms();
  m.sides[2].middle = "MESH";  // every other column transparent
  const Stack stack = stack_of(m);
  wad::ImportOptions plain;
  plain.colours = false;
  const level::Level coloured = bsp::build_wad_map(stack, "MAP01", {}, nullptr);
  const level::Level uncoloured = bsp::build_wad_map(stack, "MAP01", {}, nullptr, nullptr, plain);
  ASSERT_TRUE(std::any_of(uncoloured.textures.begin(), uncoloured.textures.end(),
                          [](const level::Texture& t) { return t.holes && t.texels.empty() && !t.opaque.empty(); }));
  const std::vector<uint8_t> bytes = level::encode(uncoloured);
  EXPECT_EQ(bytes, level::encode(coloured));
  const level::Level back = level::decode(bytes, "uncoloured");
  ASSERT_EQ(back.textures.size(), coloured.textures.size());
  for (size_t i = 0; i < back.textures.size(); ++i) EXPECT_EQ(back.textures[i].texels, coloured.textures[i].texels);
}

// Doom's COLORMAP maps indices to indices; our light maps hold its colours. The level
// recovers the indices when every shade is a palette colour, and renders in colours when
// one is not.
TEST(Import, LightMapsBecomePaletteIndicesWhenEveryShadeIsInThePalette) {
  const Built b = build(two_rooms());
  const level::Level& level = b.level;
  ASSERT_EQ(level.light_indices.size(), level.light_maps.size());
  for (size_t i = 0; i < level.light_maps.size(); ++i)
    ASSERT_EQ(level.palette[level.light_indices[i]], level.light_maps[i]) << "shade " << i;

  level::Level odd = level;
  uint32_t outside = image::rgba(1, 2, 3);
  while (std::find(odd.palette.begin(), odd.palette.end(), outside) != odd.palette.end()) ++outside;
  odd.light_maps[limits::kPaletteSize * 7 + 5] = outside;
  level::derive_shading(odd);
  EXPECT_TRUE(odd.light_indices.empty());
  Rng rng(3);
  for (int i = 0; i < 8; ++i) {
    const render::Camera c = test::random_camera(odd, rng);
    render::Frame a(64, 40), r(64, 40);
    render::make_renderer("bsp")->render(odd, c, a);
    render::make_renderer("reference")->render(odd, c, r);
    EXPECT_EQ(a.pixels, r.pixels) << "camera " << i;
  }
}

// ---- things and sprites --------------------------------------------------------------

// A Zombieman (3004, sprite POSS frame A) with five pictures named as Doom names them:
// POSSA1, POSSA2A8, POSSA3A7, POSSA4A6, POSSA5 (the A2A8 picture shows rotation 2, and
// mirrored rotation 8). Picture n has palette index 20n on its left half and 20n + 1
// on its right half, so a frame tells which picture shows and whether it is mirrored.
// Doom's animated flats and walls: a texture in one of Doom's ranges brings the
// range's frames into the level, and the world shows them in turn, 8 tics each,
// each frame's cycle starting at its Doom number (NUKAGE1 is flat 4 here: phase 1).
TEST(Import, AnimatedFlatsAndWallsCycleAsDoomCyclesThem) {
  test::TestMap m;
  m.add_room({{0, 0}, {0, 256}, {256, 256}, {256, 0}}, {0, 128, "NUKAGE2", "CEIL", 255}, "FIREWALB");
  m.things.push_back({128, 128, 0, 1, 7});
  const Built b = build(m);
  const level::Level& level = b.level;
  ASSERT_EQ(level.animations.size(), 2u);
  auto names = [&](const doom::TextureAnimation& a) {
    std::string out;
    for (int32_t f : a.frames) out += level.textures[size_t(f)].name + " ";
    return out;
  };
  const bool nukage_first = level.textures[size_t(level.animations[0].frames[0])].name == "NUKAGE1";
  const doom::TextureAnimation& fire = level.animations[nukage_first ? 1 : 0];
  const doom::TextureAnimation& nukage = level.animations[nukage_first ? 0 : 1];
  EXPECT_EQ(names(fire), "FIREWALA FIREWALB FIREWALL ");
  EXPECT_EQ(fire.phase, 5 % 3) << "FIREWALA is texture 5";
  EXPECT_EQ(names(nukage), "NUKAGE1 NUKAGE2 NUKAGE3 ");
  EXPECT_EQ(nukage.phase, 4 % 3) << "NUKAGE1 is the fifth flat";
  EXPECT_EQ(nukage.tics, 8);

  play::World world(play::map_from_wads(stack_of(m), "MAP01", level), level, play::GameOptions{}, play::Random{});
  const int nukage2 = nukage.frames[1];
  EXPECT_EQ(world.state().shown(nukage2), nukage2) << "before the first tic, every flat shows itself";
  std::string shown;  // the flat shown for NUKAGE2 after each tic
  for (int tic = 0; tic < 32; ++tic) {
    world.tick({});
    if (tic % 8 == 0) shown += level.textures[size_t(world.state().shown(nukage2))].name + " ";
  }
  EXPECT_EQ(shown, "NUKAGE3 NUKAGE1 NUKAGE2 NUKAGE3 ");
  EXPECT_EQ(world.state().shown(level::kSky), level::kSky);

  // The frames drawn: the floor's colour changes with the flat, every renderer agreeing.
  const render::Camera down{{128, 40}, 41, 90, 90};
  render::Frame before(64, 40), after(64, 40), reference(64, 40);
  render::make_renderer("bsp")->render(level, level::start_state(level), down, before);
  for (const char* name : {"bsp", "painter"}) {
    render::make_renderer(name)->render(level, world.state(), down, after);
    render::make_renderer("reference")->render(level, world.state(), down, reference);
    EXPECT_EQ(after.pixels, reference.pixels) << name;
  }
  EXPECT_NE(after.pixels, before.pixels) << "the nukage and the fire wall moved on";
}

TEST(Import, SpritesTurnAsDoomTurnsThem) {
  test::WadWriter w(true);
  test::add_test_art(w);
  TestMap m;
  m.add_room({{0, 0}, {0, 512}, {512, 512}, {512, 0}}, {0, 256, "FLOOR", "CEIL", 255});
  m.things.push_back({256, 256, 0, 3004, 7});  // facing east
  m.things.push_back({64, 64, 0, 1, 7});        // the player start: never drawn
  m.things.push_back({300, 300, 0, 2035, 7});   // a barrel: no sprite in this WAD
  m.things.push_back({310, 310, 0, 9999, 7});   // not a Doom thing
  m.add_to(w, "MAP01");
  w.lump("S_START");
  const char* names[] = {"POSSA1", "POSSA2A8", "POSSA3A7", "POSSA4A6", "POSSA5"};
  for (int n = 1; n <= 5; ++n) {
    IndexedImage pic(16, 32);
    pic.left_offset = 8, pic.top_offset = 32;
    for (int y = 0; y < 32; ++y)
      for (int x = 0; x < 16; ++x) pic.indices[pic.at(x, y)] = uint8_t(20 * n + (x >= 8)), pic.opaque[pic.at(x, y)] = 1;
    w.lump(names[n - 1], test::encode_picture(pic));
  }
  w.lump("S_END");
  Stack stack;
  stack.add(Wad(w.bytes(), "test.wad"));
  std::vector<std::string> warnings;
  const level::Level level = bsp::build_wad_map(stack, "MAP01", {}, &warnings);
  Built b{level, warnings};
  EXPECT_TRUE(has_warning(b, "THINGS #2: warning: sprite BAR1A does not exist (not drawn)"));
  EXPECT_TRUE(has_warning(b, "THINGS #3: warning: thing type 9999 is not Doom's (not drawn)"));
  EXPECT_FALSE(has_warning(b, "THINGS #1"));
  EXPECT_EQ(level.things[1].sprite, level::kNone);

  // From direction k * 45 degrees (seen from the thing), Doom shows rotation k + 1.
  const int picture[8] = {1, 2, 3, 4, 5, 4, 3, 2};
  const bool mirrored[8] = {false, false, false, false, false, true, true, true};
  auto renderer = render::make_renderer("bsp");
  for (int k = 0; k < 8; ++k) {
    const double a = k * M_PI / 4;
    const geom::Vec2 eye = geom::Vec2(256, 256) + geom::Vec2(std::cos(a), std::sin(a)) * 96.0;
    const render::Camera camera{eye, 24, k * 45.0 + 180, 90};
    render::Frame frame(64, 40);
    renderer->render(level, camera, frame);
    const int left = int(image::red(frame.at(30, 20))), right = int(image::red(frame.at(33, 20)));
    EXPECT_EQ(left, 20 * picture[k] + (mirrored[k] ? 1 : 0)) << "seen from " << k * 45 << " degrees";
    EXPECT_EQ(right, 20 * picture[k] + (mirrored[k] ? 0 : 1)) << "seen from " << k * 45 << " degrees";
  }
}

}  // namespace
}  // namespace p3d::wad
