// Maps made to break the simulation's arithmetic: coordinates and heights at the
// limits of Doom's 16-bit map numbers. Doom's 32-bit ints wrapped on them; ours must
// wrap by construction, so these tests mean most in the sanitizer build (UBSan traps
// on a signed overflow), where they run the same.
#include <gtest/gtest.h>

#include "engine/bsp/load.h"
#include "engine/play/savegame.h"
#include "engine/play/world.h"
#include "tests/support/support.h"
#include "tests/support/wad_writer.h"

namespace p3d::play {
namespace {

using test::TestMap;

constexpr int kMin = -32768, kMax = 32767;
constexpr TicCmd kHostileRunTurnFire{50, 24, 512, kBtAttack}, kHostileUse{0, 0, 0, kBtUse};

struct HostilePlay {
  explicit HostilePlay(const TestMap& m)
      : wads(test::test_stack({{"MAP01", m}})),
        level(bsp::build_wad_map(wads, "MAP01", {}, nullptr)),
        world(map_from_wads(wads, "MAP01", level), level, GameOptions{}, Random{}) {}
  void run(int tics) {
    for (int t = 0; t < tics; ++t) world.tick(t % 3 ? kHostileRunTurnFire : kHostileUse);
    (void)world.state();
  }
  wad::Stack wads;
  level::Level level;
  World world;
};

// The blockmap's origin at the far corner: a thing's cell is its offset from there,
// which Doom computed in an int that the room's far side overflows.
TEST(HostileMap, ARoomAsLargeAsTheMapSpawnsAndPlays) {
  TestMap m;
  m.add_room({{kMin, kMin}, {kMin, kMax}, {kMax, kMax}, {kMax, kMin}}, {});
  m.things.push_back({0, 0, 90, 1});
  m.things.push_back({kMax - 64, kMax - 64, 0, 3004});  // a trooper in the far corner
  m.things.push_back({kMin + 64, kMin + 64, 0, 2012});  // a medikit in the near one
  HostilePlay p(m);
  ASSERT_NE(p.world.player().mo, nullptr);
  EXPECT_EQ(p.world.player().mo->x, 0);
  p.run(140);
  EXPECT_GT(p.world.level_time(), 0);
}

// A floor above the ceiling, both at the limits: the view's clamp under the ceiling
// (and the things' under it) reach below the lowest Fixed.
TEST(HostileMap, AFloorAtTheTopAndACeilingAtTheBottomPlay) {
  TestMap m;
  m.add_room({{0, 0}, {0, 256}, {256, 256}, {256, 0}}, {.floor = kMax, .ceiling = kMin});
  m.things.push_back({128, 128, 0, 1});
  m.things.push_back({200, 200, 0, 3001});  // an imp
  m.things.push_back({60, 60, 0, 2035});    // a barrel
  HostilePlay p(m);
  ASSERT_NE(p.world.player().mo, nullptr);
  EXPECT_EQ(p.world.eye_z(), wrap_add(to_fixed(kMax), kViewHeight)) << "wrapped, as Doom's int: below the ceiling";
  p.run(140);
  EXPECT_GT(p.world.level_time(), 0);
}

// A REJECT lump shorter than the map needs (node builders may write it empty): Doom
// read on past it into the zone's next block header, which Chocolate Doom writes
// there: that block's size (four bytes a line in a sector's list, rounded up, plus 24),
// 0, PU_LEVEL (50) and the zone's id, then zeros. Its bits reject sight between the
// sectors they stand for; a lump of the whole size is read as it is.
TEST(HostileMap, AShortRejectLumpReadsOnAsDoomDid) {
  TestMap m;
  for (int i = 0; i < 3; ++i) m.add_room({{256 * i, 0}, {256 * i, 256}, {256 * i + 256, 256}, {256 * i + 256, 0}}, {});
  m.things.push_back({128, 128, 0, 1});
  const wad::Stack wads = test::test_stack({{"MAP01", m}});
  const level::Level level = bsp::build_wad_map(wads, "MAP01", {}, nullptr);
  const Map map = map_from_wads(wads, "MAP01", level);
  ASSERT_EQ(map.sectors.size(), 3u);
  ASSERT_EQ(map.reject.size(), 2u);  // 9 bits
  uint32_t line_refs = 0;
  for (const Line& ld : map.lines) line_refs += ld.back && ld.back != ld.front ? 2 : 1;
  EXPECT_EQ(line_refs, 12u) << "ten lines, two of them between two rooms";
  const uint32_t block_size = ((line_refs * 4 + 3) & ~3u) + 24;  // 72: bits 3 and 6
  EXPECT_EQ(map.reject[0], uint8_t(block_size));
  EXPECT_EQ(map.reject[1], uint8_t(block_size >> 8));
  EXPECT_TRUE(map.rejected(1, 0)) << "bit 3";
  EXPECT_TRUE(map.rejected(2, 0)) << "bit 6";
  EXPECT_FALSE(map.rejected(0, 1));
  EXPECT_FALSE(map.rejected(0, 0));
}

// A comb of `teeth` rooms `width` units wide east of the player's room, every wall
// between two of them a line that a shot east crosses; the player faces east at (-64, 128).
TestMap intercept_comb(int teeth, int width = 8) {
  TestMap m;
  m.add_room({{-128, 0}, {-128, 256}, {16, 256}, {16, 0}}, {});
  for (int i = 0; i < teeth; ++i) {
    const int x = 16 + width * i;
    m.add_room({{x, 0}, {x, 256}, {x + width, 256}, {x + width, 0}}, {});
  }
  m.things.push_back({-64, 128, 0, 1});
  for (int y : {40, 216}) m.things.push_back({-100, y, 0, 2035});  // barrels, off the shot's line
  return m;
}

struct BlockmapHeader {
  Fixed origin_x, origin_y;
  int width, height;
  bool operator==(const BlockmapHeader&) const = default;
};
BlockmapHeader blockmap_header(const World& w) {
  const Blockmap& bm = w.map().blockmap;
  return {bm.origin_x, bm.origin_y, bm.width, bm.height};
}

// The fraction of the shot's trace (2048 units east from the player) at the comb's wall
// number `n` (0 at x = 16), as Doom's P_InterceptVector rounds it.
Fixed comb_wall_frac(int n) {
  const Fixed trace_x = to_fixed(-64), trace_dx = to_fixed(2048), wall_x = to_fixed(16 + 8 * n);
  return fixed_div(wall_x - trace_x, trace_dx);
}

HostilePlay& fire_east(HostilePlay& p) {
  for (int t = 0; t < 35; ++t) p.world.tick(TicCmd{0, 0, 0, kBtAttack});
  return p;
}

// Vanilla Doom held 128 intercepts a trace and wrote the rest over the globals after the
// array, 12 bytes each (the fraction, whether it is a line, a pointer): intercept 147's
// flag became the blockmap's width, 148's fraction and flag its origin, 149's fraction
// its height, for the rest of the level. Chocolate Doom writes them there too, up to 189.
TEST(HostileMap, AShotAcrossMoreThan128LinesOverwritesTheBlockmapAsVanillaDid) {
  HostilePlay few(intercept_comb(100));
  const BlockmapHeader before = blockmap_header(few.world);
  EXPECT_EQ(blockmap_header(fire_east(few).world), before) << "101 walls: within vanilla's array";
  EXPECT_EQ(few.world.beyond_chocolate(), "");

  HostilePlay many(intercept_comb(160));
  fire_east(many);
  const BlockmapHeader after = blockmap_header(many.world);
  // Intercepts in the order the trace meets cells: the player (its own cell's thing,
  // after that cell's walls) is one of the first, so intercept k is wall k - 1.
  EXPECT_EQ(after.width, 1) << "intercept 147 is a line";
  EXPECT_EQ(after.origin_x, comb_wall_frac(147));
  EXPECT_EQ(after.origin_y, 1) << "intercept 148 is a line";
  EXPECT_EQ(after.height, comb_wall_frac(148));
  EXPECT_EQ(many.world.beyond_chocolate(), "") << "161 walls: within Chocolate's emulation";
  for (int tooth : {0, 50, 159}) {  // the nodes find a point's sector as before
    many.world.place_player(to_fixed(16 + 8 * tooth + 4), to_fixed(128), 0);
    EXPECT_EQ(many.world.player().mo->subsector->sector->index, tooth + 1);
  }
  // Saved and loaded (our extension keeps the header and the lists as they are), the
  // level plays on the same.
  const DoomNumbers numbers(many.wads, many.level);
  const std::vector<uint8_t> bytes = write_save(many.world, numbers, "overrun", {});
  World loaded(map_from_wads(many.wads, "MAP01", many.level), many.level, GameOptions{}, Random{});
  carry_over(loaded, many.world, read_save_header(bytes, "overrun"));
  EXPECT_TRUE(read_save(loaded, bytes, "overrun", numbers).extended);
  EXPECT_EQ(blockmap_header(loaded), after);
  for (int t = 0; t < 70; ++t) {
    const TicCmd cmd = t % 3 ? kHostileRunTurnFire : kHostileUse;
    many.world.tick(cmd), loaded.tick(cmd);
  }
  EXPECT_EQ(write_save(loaded, numbers, "on", {}), write_save(many.world, numbers, "on", {}));

  // Past intercept 147 only the blockmap's first column is searched: the rest of a cell
  // already begun is all a trace can add, so the comb's walls stand a unit apart.
  HostilePlay too_many(intercept_comb(200, 1));
  fire_east(too_many);
  EXPECT_NE(too_many.world.beyond_chocolate().find("more than 189 lines and things"), std::string::npos)
      << too_many.world.beyond_chocolate();
}

// Once an overrun has moved the blockmap, Doom's nodes still place every point where
// they did (our descent starts from cells of the blockmap's first area, not its present).
TEST(HostileMap, AMovedBlockmapLeavesThePointsInTheirSubsectors) {
  const wad::Stack wads = bsp::read_wads({test::freedoom_path("freedoom2.wad")});
  const level::Level level = bsp::build_wad_map(wads, "MAP01", {}, nullptr);
  Map map = map_from_wads(wads, "MAP01", level);
  ASSERT_TRUE(map.has_nodes());
  std::vector<const Subsector*> before;
  const Blockmap& bm = map.blockmap;
  auto each_point = [&](auto&& f) {
    for (int y = 0; y < bm.height * 128; y += 24)
      for (int x = 0; x < bm.width * 128; x += 24) f(wrap_add(bm.origin_x, to_fixed(x)), wrap_add(bm.origin_y, to_fixed(y)));
  };
  each_point([&](Fixed x, Fixed y) { before.push_back(map.point_in_subsector(x, y)); });
  Map moved = map;
  moved.blockmap.width = 1, moved.blockmap.origin_x = 43207, moved.blockmap.origin_y = 1, moved.blockmap.height = 42969;
  size_t i = 0, differ = 0;
  each_point([&](Fixed x, Fixed y) { differ += moved.point_in_subsector(x, y) - moved.subsectors.data() != before[i++] - map.subsectors.data(); });
  EXPECT_EQ(differ, 0u) << "of " << before.size() << " points";
}

}  // namespace
}  // namespace p3d::play
