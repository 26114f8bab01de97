// The player's weapon over the view from Freedoom's sprites: placed by Doom's
// R_DrawPSprite arithmetic (worked out here again from the picture's offsets), lit by
// the player's sector unless its frame is bright, the powers' light maps, the shadow's
// fuzz, and palette indices in indexed frames.
#include <gtest/gtest.h>

#include <functional>
#include <set>

#include "engine/bsp/load.h"
#include "engine/play/weapon_view.h"
#include "engine/play/world.h"
#include "engine/wad/art.h"
#include "tests/support/support.h"
#include "tests/support/wad_writer.h"

namespace p3d::play {
namespace {

constexpr uint32_t kUntouched = image::rgba(1, 2, 3);
constexpr Fixed kWeaponTop = 32 * kFracUnit;  // Doom's WEAPONTOP: the weapon raised

struct WeaponViewFixture {
  wad::Stack wads = bsp::read_wads({test::freedoom_path("freedoom2.wad")});
  wad::Art doom_art{wads};
  WeaponArt art{wads};
  level::Level level;
  Sector sector;
  Subsector subsector;
  Mobj mo;
  Player player;

  WeaponViewFixture() {
    level.palette = doom_art.palette();
    for (int m = 0; m < 32; ++m)
      for (int i = 0; i < 256; ++i) level.light_maps.push_back(level.palette[doom_art.colormap()[size_t(m) * 256 + i]]);
    level::derive_shading(level);
    sector.light = 255;
    subsector.sector = &sector;
    mo.subsector = &subsector;
    player.mo = &mo;
    raise(kPsWeapon, StateId::kPistol);
  }
  void raise(int layer, StateId state) { player.psprites[size_t(layer)] = {state, 1, kFracUnit, kWeaponTop}; }
  wad::IndexedImage picture(const std::string& lump) const { return wad::decode_picture(wads.find(lump)->bytes, lump); }
  render::Frame draw(int width = 320, int height = 168, int bar = 32) {
    render::Frame frame(width, height, kUntouched);
    draw_weapon(player, art, level, frame, bar);
    return frame;
  }
  uint32_t lit(int map, uint8_t index) const { return level.light_maps[size_t(map) * 256 + index]; }
  // A colour through map 6, by its first palette index.
  uint32_t darkened(uint32_t colour) const {
    const auto index = std::find(level.palette.begin(), level.palette.end(), colour) - level.palette.begin();
    return lit(6, uint8_t(index));
  }
};

// Doom's R_DrawPSprite at 320x168 (pspritescale 1, centre column 160, centre row 84):
// the picture's first column and the first row its top texel row covers.
struct DoomPlace {
  int x1 = 0, top = 0;
  DoomPlace(const wad::IndexedImage& pic, Fixed sx, Fixed sy) {
    const Fixed tx = sx - 160 * kFracUnit - pic.left_offset * kFracUnit;
    x1 = (160 * kFracUnit + tx) >> kFracBits;
    const Fixed texture_mid = 100 * kFracUnit + kFracUnit / 2 - (sy - pic.top_offset * kFracUnit);
    top = (84 * kFracUnit - texture_mid + kFracUnit - 1) >> kFracBits;  // rows round up
  }
};

// Whether every opaque texel of the picture shows at its Doom place in the colour
// `colour` gives it (rows below the view cut off), and nothing else was drawn.
testing::AssertionResult drawn_at(const render::Frame& frame, const wad::IndexedImage& pic, const DoomPlace& at,
                                  const std::function<uint32_t(uint8_t)>& colour) {
  std::vector<bool> covered(frame.pixels.size());
  for (int c = 0; c < pic.width; ++c)
    for (int r = 0; r < pic.height; ++r) {
      const int x = at.x1 + c, y = at.top + r;
      if (!pic.opaque[pic.at(c, r)] || x < 0 || y < 0 || x >= frame.width || y >= frame.height) continue;
      covered[size_t(y) * size_t(frame.width) + size_t(x)] = true;
      if (frame.at(x, y) != colour(pic.indices[pic.at(c, r)]))
        return testing::AssertionFailure() << "texel " << c << "," << r << " at " << x << "," << y;
    }
  for (int y = 0; y < frame.height; ++y)
    for (int x = 0; x < frame.width; ++x)
      if (!covered[size_t(y) * size_t(frame.width) + size_t(x)] && frame.at(x, y) != kUntouched)
        return testing::AssertionFailure() << "drawn outside the picture at " << x << "," << y;
  return testing::AssertionSuccess();
}

TEST(WeaponView, ThePistolLandsWhereDoomDrawsIt) {
  WeaponViewFixture f;
  const wad::IndexedImage pic = f.picture("PISGA0");
  const DoomPlace at(pic, kFracUnit, kWeaponTop);
  const render::Frame frame = f.draw();
  EXPECT_TRUE(drawn_at(frame, pic, at, [&](uint8_t i) { return f.lit(0, i); })) << "full light: map 0";
  // Freedoom's pistol (50x64, offsets -138, -104): columns 139..188 from row 120, its
  // bottom 16 rows behind the status bar, as in Chocolate Doom.
  EXPECT_EQ(at.x1, 139);
  EXPECT_EQ(at.top, 120);
  EXPECT_GT(at.top + pic.height, 168);
  int bottom_drawn = 0;
  for (int x = 0; x < 320; ++x) bottom_drawn += frame.at(x, 167) != kUntouched;
  EXPECT_GT(bottom_drawn, 0) << "the weapon reaches the view's last row";
}

TEST(WeaponView, BobbingMovesItByWholeUnits) {
  WeaponViewFixture f;
  f.player.psprites[kPsWeapon].sx = -5 * kFracUnit;
  f.player.psprites[kPsWeapon].sy = kWeaponTop + 7 * kFracUnit;
  const wad::IndexedImage pic = f.picture("PISGA0");
  const DoomPlace at(pic, -5 * kFracUnit, kWeaponTop + 7 * kFracUnit);
  EXPECT_EQ(at.x1, 139 - 6);
  EXPECT_EQ(at.top, 127);
  EXPECT_TRUE(drawn_at(f.draw(), pic, at, [&](uint8_t i) { return f.lit(0, i); }));
}

TEST(WeaponView, ADarkSectorDarkensTheWeaponButNotABrightFlash) {
  WeaponViewFixture f;
  f.sector.light = 64;  // light level 4: Doom's map (15 - 4) * 4 - 23 = 21
  f.raise(kPsFlash, StateId::kPistolflash);
  const render::Frame frame = f.draw();
  const wad::IndexedImage gun = f.picture("PISGA0"), flash = f.picture("PISFA0");
  const DoomPlace gun_at(gun, kFracUnit, kWeaponTop), flash_at(flash, kFracUnit, kWeaponTop);
  for (int c = 0; c < flash.width; ++c)
    for (int r = 0; r < flash.height; ++r) {
      if (!flash.opaque[flash.at(c, r)]) continue;
      ASSERT_EQ(frame.at(flash_at.x1 + c, flash_at.top + r), f.lit(0, flash.indices[flash.at(c, r)]))
          << "the flash is bright, drawn over the weapon";
    }
  int darkened = 0;
  for (int c = 0; c < gun.width; ++c)
    for (int r = 0; r < gun.height && gun_at.top + r < 168; ++r) {
      const int x = gun_at.x1 + c, y = gun_at.top + r;
      const int fc = x - flash_at.x1, fr = y - flash_at.top;
      const bool under_flash =
          fc >= 0 && fr >= 0 && fc < flash.width && fr < flash.height && flash.opaque[flash.at(fc, fr)];
      if (!gun.opaque[gun.at(c, r)] || under_flash) continue;
      ASSERT_EQ(frame.at(x, y), f.lit(21, gun.indices[gun.at(c, r)])) << x << "," << y;
      ++darkened;
    }
  EXPECT_GT(darkened, 500);

  f.player.psprites[kPsFlash] = {};
  f.sector.light = 0;  // the darkest: map 31
  EXPECT_TRUE(drawn_at(f.draw(), gun, gun_at, [&](uint8_t i) { return f.lit(31, i); }));
  f.player.extra_light = 2;  // the gun's flash lights the sector: level 2, map 29
  EXPECT_TRUE(drawn_at(f.draw(), gun, gun_at, [&](uint8_t i) { return f.lit(29, i); }));
}

TEST(WeaponView, ThePowersLightMapsOverrideTheSector) {
  WeaponViewFixture f;
  f.sector.light = 0;
  const wad::IndexedImage gun = f.picture("PISGA0");
  const DoomPlace at(gun, kFracUnit, kWeaponTop);
  f.player.fixed_colormap = 1;  // the light amplification visor
  EXPECT_TRUE(drawn_at(f.draw(), gun, at, [&](uint8_t i) { return f.lit(1, i); }));
  f.player.fixed_colormap = 32;  // invulnerability: COLORMAP's inverse map, beyond the level's 32
  EXPECT_TRUE(drawn_at(f.draw(), gun, at,
                       [&](uint8_t i) { return f.level.palette[f.doom_art.colormap()[32 * 256 + size_t(i)]]; }));
}

TEST(WeaponView, IndexedFramesGetPaletteIndices) {
  WeaponViewFixture f;
  ASSERT_FALSE(f.level.light_indices.empty());
  f.sector.light = 64;
  render::Frame frame(320, 168, kUntouched);
  frame.indices.assign(size_t(320) * 168, 7);
  frame.palette = f.level.palette;
  draw_weapon(f.player, f.art, f.level, frame, 32);
  const wad::IndexedImage gun = f.picture("PISGA0");
  const DoomPlace at(gun, kFracUnit, kWeaponTop);
  const uint8_t texel = gun.indices[gun.at(25, 30)];
  ASSERT_TRUE(gun.opaque[gun.at(25, 30)]);
  const size_t pixel = size_t(at.top + 30) * 320 + size_t(at.x1 + 25);
  EXPECT_EQ(frame.indices[pixel], f.level.light_indices[21 * 256 + texel]);
  EXPECT_EQ(frame.pixels[pixel], f.level.palette[frame.indices[pixel]]);
  EXPECT_EQ(frame.indices[0], 7) << "the rest left alone";
}

TEST(WeaponView, InvisibleTheWeaponIsAShadowsFuzz) {
  WeaponViewFixture f;
  f.player.inv.powers[size_t(Power::kInvisibility)] = 60 * 35;
  const uint8_t behind = 100;
  render::Frame frame(320, 168, f.level.palette[behind]);
  draw_weapon(f.player, f.art, f.level, frame, 32);
  const wad::IndexedImage gun = f.picture("PISGA0");
  const DoomPlace at(gun, kFracUnit, kWeaponTop);
  // Over a plain wall, the fuzz darkens it through map 6: once, or more where it took
  // the row above, already darkened.
  std::set<uint32_t> darker;
  for (uint32_t c = f.level.palette[behind]; darker.insert(f.darkened(c)).second;) c = f.darkened(c);
  int fuzzed = 0;
  for (int c = 0; c < gun.width; ++c)
    for (int r = 0; r < gun.height && at.top + r < 167; ++r) {
      if (!gun.opaque[gun.at(c, r)]) continue;
      ASSERT_TRUE(darker.count(frame.at(at.x1 + c, at.top + r))) << c << "," << r;
      ++fuzzed;
    }
  EXPECT_GT(fuzzed, 500);
  EXPECT_EQ(frame.at(0, 0), f.level.palette[behind]);
  render::Frame again(320, 168, f.level.palette[behind]);
  draw_weapon(f.player, f.art, f.level, again, 32);
  EXPECT_EQ(again.pixels, frame.pixels) << "the same frame fuzzes the same";

  f.player.inv.powers[size_t(Power::kInvisibility)] = 4 * 32 - 16;  // running out, in a blink's seen half
  EXPECT_TRUE(drawn_at(f.draw(), gun, at, [&](uint8_t i) { return f.lit(0, i); }));
}

TEST(WeaponView, ScaledByTheStatusBarsFactor) {
  WeaponViewFixture f;
  const wad::IndexedImage pic = f.picture("PISGA0");
  // At 640x336 over a bar of 64 rows, as Crispy Doom's hires: Doom's screen twice over,
  // centre column 320 and row 168, each view pixel a half step through the picture.
  const render::Frame big = f.draw(640, 336, 64);
  const Fixed half = kFracUnit / 2;
  const int x1 = (320 * kFracUnit + 2 * (kFracUnit - 160 * kFracUnit - pic.left_offset * kFracUnit)) >> kFracBits;
  const Fixed texture_mid = 100 * kFracUnit + kFracUnit / 2 - (kWeaponTop - pic.top_offset * kFracUnit);
  int drawn = 0;
  for (int y = 0; y < big.height; ++y)
    for (int x = 0; x < big.width; ++x) {
      const int c = ((x - x1) * half) >> kFracBits, r = (texture_mid + (y - 168) * half) >> kFracBits;
      const bool texel = x >= x1 && c < pic.width && r >= 0 && r < pic.height && pic.opaque[pic.at(c, r)];
      ASSERT_EQ(big.at(x, y), texel ? f.lit(0, pic.indices[pic.at(c, r)]) : kUntouched) << x << "," << y;
      drawn += texel;
    }
  EXPECT_GT(drawn, 4 * 1000);
  // Full screen (no bar): Doom's 320x200 view, the weapon 16 rows lower and more of it shown.
  const render::Frame full = f.draw(320, 200, 0);
  DoomPlace at(pic, kFracUnit, kWeaponTop);
  at.top += 16;
  EXPECT_TRUE(drawn_at(full, pic, at, [&](uint8_t i) { return f.lit(0, i); }));
}

TEST(WeaponView, NothingWithoutItsSprite) {
  WeaponViewFixture f;
  f.player.psprites[kPsWeapon] = {};
  const render::Frame frame = f.draw();
  for (uint32_t p : frame.pixels) ASSERT_EQ(p, kUntouched);
  EXPECT_EQ(f.art.frame(Sprite::kPisg, 25), nullptr) << "no such frame in the WADs";
  ASSERT_NE(f.art.frame(Sprite::kPisg, 0), nullptr);
  EXPECT_FALSE(f.art.frame(Sprite::kPisg, 0)->flipped);
}

// A frame named in the second half of a sprite lump's name ("PISGC0B0": C, and B
// mirrored), as Doom's sprite table reads it.
TEST(WeaponView, AFrameSharedWithAnotherIsDrawnMirrored) {
  test::WadWriter w(true);
  test::add_test_art(w);
  wad::IndexedImage pic(2, 2);
  pic.left_offset = pic.top_offset = -100;
  for (int r = 0; r < 2; ++r) {
    pic.indices[pic.at(0, r)] = 10, pic.indices[pic.at(1, r)] = 20;
    pic.opaque[pic.at(0, r)] = pic.opaque[pic.at(1, r)] = 1;
  }
  w.lump("S_START");
  w.lump("PISGC0B0", test::encode_picture(pic));
  w.lump("S_END");
  wad::Stack wads;
  wads.add(wad::Wad(w.bytes(), "test.wad"));
  WeaponArt art(wads);
  ASSERT_NE(art.frame(Sprite::kPisg, 1), nullptr);
  EXPECT_TRUE(art.frame(Sprite::kPisg, 1)->flipped);
  ASSERT_NE(art.frame(Sprite::kPisg, 2), nullptr);
  EXPECT_FALSE(art.frame(Sprite::kPisg, 2)->flipped);

  level::Level level;  // no light maps of its own: the WADs' palette and COLORMAP
  Player player;
  player.psprites[kPsWeapon] = {StateId::kPistol4, 1, kFracUnit, kWeaponTop};  // PISG frame B
  render::Frame frame(320, 168, kUntouched);
  draw_weapon(player, art, level, frame, 32);
  // x1 = 160 + (1 - 160 + 100) = 101; top = 84 - (100.5 - 132) rounded up = 116.
  EXPECT_EQ(frame.at(101, 116), art.palette()[20]) << "mirrored: the last column first";
  EXPECT_EQ(frame.at(102, 117), art.palette()[10]);
  EXPECT_EQ(frame.at(100, 116), kUntouched);
  EXPECT_EQ(frame.at(101, 115), kUntouched);
  EXPECT_EQ(frame.at(101, 118), kUntouched);
}

}  // namespace
}  // namespace p3d::play
