// Doom's view tables (doom_rules.h) against the numbers Chocolate Doom's
// R_InitTextureMapping and R_ExecuteSetViewSize compute at 320x200 (printed from
// its own code once, kept here).
#include <gtest/gtest.h>

#include "engine/render/doom_rules.h"

namespace p3d::render::doom {
namespace {

TEST(DoomRules, TablesAt320AreChocolateDooms) {
  const Tables& t = tables(320, 200);
  EXPECT_FALSE(t.crispy);
  const std::pair<int, Angle> xtoviewangle[] = {{0, 0x20080000},   {1, 0x1fe00000},   {80, 0x12e80000},
                                                {159, 0x00400000}, {160, 0x00000000}, {161, 0xffc00000},
                                                {240, 0xed180000}, {319, 0xe0200000}, {320, 0xdff80000}};
  for (const auto& [x, angle] : xtoviewangle) EXPECT_EQ(t.xtoviewangle[size_t(x)], angle) << "xtoviewangle[" << x << "]";
  EXPECT_EQ(t.clipangle, 0x20080000u);
  const std::pair<int, int> viewangletox[] = {{0, 320},   {1024, 320}, {1500, 232}, {2048, 160},
                                              {2049, 160}, {2600, 88},  {3072, 1},   {4095, 0}};
  for (const auto& [i, x] : viewangletox) EXPECT_EQ(t.viewangletox[size_t(i)], x) << "viewangletox[" << i << "]";
  EXPECT_EQ(t.yslope[0], 105384);
  EXPECT_EQ(t.yslope[99], 20971520);
  EXPECT_EQ(t.yslope[198], 106454);
  EXPECT_EQ(t.distscale[0], 92789);
  EXPECT_EQ(t.distscale[159], 65538);
  EXPECT_EQ(t.distscale[318], 92083);
}

TEST(DoomRules, OtherWidthsAreCrispyDoomsHires) {
  const Tables& t = tables(640, 400);
  EXPECT_TRUE(t.crispy);
  EXPECT_EQ(t.xtoviewangle[320], 0u);  // the centre column looks straight ahead
  EXPECT_EQ(t.sky_iscale, kFracUnit / 2);
  // Light diminishes with distance as at 320 columns: a scale twice as large, the same map.
  const int start = start_map(160, 0, 0);
  EXPECT_EQ(wall_map(t, start, 2 * kFracUnit), wall_map(tables(320, 200), start, kFracUnit));
  // Crispy's wiggle fix: taller sectors, fewer bits for the edges and a lower largest scale.
  EXPECT_EQ(wall_precision(t, 128).height_bits, 12);
  EXPECT_EQ(wall_precision(t, 128).max_scale, 2048 * kFracUnit);
  EXPECT_EQ(wall_precision(t, 1024).height_bits, 11);
  EXPECT_EQ(wall_precision(t, 4096).height_bits, 10);
  EXPECT_EQ(wall_precision(t, 40000).height_bits, 9);
  EXPECT_EQ(wall_precision(tables(320, 200), 40000).max_scale, 64 * kFracUnit);  // vanilla's
}

}  // namespace
}  // namespace p3d::render::doom
