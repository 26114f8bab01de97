// Maps made to break the simulation's arithmetic: coordinates and heights at the
// limits of Doom's 16-bit map numbers. Doom's 32-bit ints wrapped on them; ours must
// wrap by construction, so these tests mean most in the sanitizer build (UBSan traps
// on a signed overflow), where they run the same.
#include <gtest/gtest.h>

#include "engine/bsp/load.h"
#include "engine/play/world.h"
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

}  // namespace
}  // namespace p3d::play
