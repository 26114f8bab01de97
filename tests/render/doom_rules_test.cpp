// Doom's view tables (doom_rules.h) against the numbers Chocolate Doom's
// R_InitTextureMapping and R_ExecuteSetViewSize compute at 320x200 (printed from
// its own code once, kept here).
#include <gtest/gtest.h>

#include <algorithm>
#include <utility>
#include <vector>

#include "engine/render/doom_rules.h"
#include "engine/util/rng.h"

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

// The light's division by the width as a multiply: the same quotient as the division
// for every divisor tried, at the numerators where it could slip (each side of a
// multiple of the divisor, the largest) and at random ones.
TEST(DoomRules, ExactQuotientIsTheDivision) {
  Rng rng(5);
  constexpr int kBits = 41;
  const uint64_t top = (uint64_t(1) << kBits) - 1;
  std::vector<uint64_t> divisors = {1, 2, 3, 7, 320 << kLightScaleShift, 640 << kLightScaleShift, 7680 << kLightScaleShift};
  for (int i = 0; i < 200; ++i) divisors.push_back(uint64_t(1 + rng.below(16384)) << kLightScaleShift);
  for (int i = 0; i < 50; ++i) divisors.push_back(1 + rng.below(uint64_t(1) << 40));
  for (const uint64_t d : divisors) {
    uint64_t magic;
    int shift;
    magic_for(d, kBits, magic, shift);
    std::vector<uint64_t> numerators = {0, 1, top, top - 1, d - 1, d, d + 1};
    for (int i = 0; i < 200; ++i) {
      const uint64_t n = rng.below(top + 1);
      const uint64_t multiple = n / d * d;
      numerators.insert(numerators.end(), {n, multiple, multiple - 1, multiple + d - 1});
    }
    for (const uint64_t n : numerators) {
      if (n > top) continue;
      ASSERT_EQ(exact_quotient(n, magic, shift), n / d) << n << " / " << d;
    }
  }
}

// R_ScaleFromGlobalAngle's two sines as Doom writes them (visangle = viewangle +
// xtoviewangle[x]; anglea = ANG90 + visangle - viewangle; angleb = ANG90 + visangle -
// rw_normalangle), against scale_sines, whose view sine is tabulated per column, and
// against the tables seg_sines gives a run's columns, at any view and seg angle.
TEST(DoomRules, ScaleSinesAreDooms) {
  Rng rng(9);
  for (const auto& [w, h] : {std::pair{320, 200}, {640, 400}, {1920, 1080}}) {
    const Tables& t = tables(w, h);
    std::vector<int32_t> xs;
    for (int x = 0; x < w; x += 1 + int(rng.below(5))) xs.push_back(x);
    for (int i = 0; i < 100; ++i) {
      const Angle view_angle = Angle(rng.below(uint64_t(1) << 32));
      Seg seg;
      seg.normal = Angle(rng.below(uint64_t(1) << 32));
      const SegSines sines = seg_sines(t, seg, view_angle);
      for (size_t k = 0; k < xs.size(); ++k) {
        const Angle visangle = view_angle + t.xtoviewangle[size_t(xs[k])];
        const Fixed anglea = play::kFineSine[(play::kAngle90 + visangle - view_angle) >> play::kAngleToFineShift];
        const Fixed angleb = play::kFineSine[(play::kAngle90 + visangle - seg.normal) >> play::kAngleToFineShift];
        const ScaleSines one = scale_sines(t, seg, view_angle, xs[k]);
        ASSERT_EQ(one.view, anglea) << w << " x " << xs[k];
        ASSERT_EQ(one.seg, angleb) << w << " x " << xs[k];
        const size_t x = size_t(xs[k]);
        ASSERT_EQ(sines.view_sine[x], anglea) << w << " x " << xs[k];
        ASSERT_EQ(sines.fine_sine[(sines.seg_angle + sines.column_angle[x]) >> play::kAngleToFineShift], angleb)
            << w << " x " << xs[k];
      }
    }
  }
}

// wall_map as Doom's: scale * 320 / width (vanilla's windows: the scale itself) >> 12,
// at most 47, every scale a light index changes at.
TEST(DoomRules, WallLightIsDoomsAtAnyWidth) {
  for (const auto& [width, screen] : {std::pair{320, 0}, {640, 0}, {1920, 0}, {1366, 0}, {256, 320}, {96, 320}}) {
    const Tables& t = tables(width, width * 5 / 8, screen);
    for (int light = 0; light < 256; light += 37)
      for (uint32_t index = 0; index <= kMaxLightScale + 2; ++index)
        for (const int64_t nudge : {-1, 0, 1}) {
          const int64_t per_index = t.crispy ? int64_t(t.width) << kLightScaleShift : int64_t(kDoomWidth) << kLightScaleShift;
          const int64_t scale = std::clamp<int64_t>((int64_t(index) * per_index + kDoomWidth - 1) / kDoomWidth + nudge, 0, INT32_MAX);
          const int64_t scaled = t.crispy ? scale * kDoomWidth / t.width : scale;
          const int drop = t.scale_light_drop[std::min<int64_t>(scaled >> kLightScaleShift, kMaxLightScale - 1)];
          const int expected = std::clamp(start_map(light, 0, 0) - drop, 0, kColormaps - 1);
          ASSERT_EQ(wall_map(t, start_map(light, 0, 0), Fixed(scale)), expected) << width << " columns, scale " << scale;
        }
  }
}

}  // namespace
}  // namespace p3d::render::doom
