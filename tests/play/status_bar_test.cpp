// Doom's status bar from Freedoom's art: each piece at Doom's place, keys and numbers
// as the values say, the same bar scaled by whole factors and centred, the rows
// above left alone, and the face glancing about.
#include <gtest/gtest.h>

#include <set>

#include "engine/bsp/load.h"
#include "engine/play/hud_font.h"
#include "engine/play/status_bar.h"
#include "engine/wad/art.h"
#include "tests/support/support.h"

namespace p3d::play {
namespace {

struct Fixture {
  wad::Stack wads = bsp::read_wads({test::freedoom_path("freedoom2.wad")});
  std::vector<uint32_t> palette = wad::Art(wads).palette();
  StatusBarArt art = *StatusBarArt::load(wads);

  // Whether the picture's opaque texels show at Doom's screen place (x, y) of a 320x200 frame.
  bool shows(const image::Image& frame, const std::string& lump, int x, int y) const {
    const wad::IndexedImage pic = wad::decode_picture(wads.find(lump)->bytes, lump);
    for (int c = 0; c < pic.width; ++c)
      for (int r = 0; r < pic.height; ++r)
        if (pic.opaque[pic.at(c, r)] &&
            frame.at(x - pic.left_offset + c, y - pic.top_offset + r) != palette[pic.indices[pic.at(c, r)]])
          return false;
    return true;
  }
};

TEST(StatusBar, PiecesAtDoomsPlacesAsTheValuesSay) {
  Fixture f;
  const uint32_t untouched = image::rgba(1, 2, 3);
  image::Image frame(320, 200, untouched);
  StatusValues v;
  v.health = 87;
  v.keys = 1 | 8 | 4;  // the blue card and skull, the red card
  v.face = 8 + 1;      // Face's index: the second face of pain, looking aside
  f.art.draw(v, frame, f.palette);
  for (int y = 0; y < 168; ++y)
    for (int x = 0; x < 320; ++x) ASSERT_EQ(frame.at(x, y), untouched) << x << "," << y << ": above the bar";
  const int digit = wad::decode_picture(f.wads.find("STTNUM0")->bytes, "STTNUM0").width;
  EXPECT_TRUE(f.shows(frame, "STTNUM7", 90 - digit, 171)) << "health 87, right-aligned at x 90";
  EXPECT_TRUE(f.shows(frame, "STTNUM8", 90 - 2 * digit, 171));
  EXPECT_TRUE(f.shows(frame, "STTPRCNT", 90, 171));
  EXPECT_TRUE(f.shows(frame, "STTNUM5", 44 - 2 * digit, 171)) << "50 bullets in hand";
  EXPECT_TRUE(f.shows(frame, "STTNUM0", 44 - digit, 171));
  EXPECT_TRUE(f.shows(frame, "STKEYS3", 239, 171)) << "the skull over its card";
  EXPECT_TRUE(f.shows(frame, "STKEYS2", 239, 191)) << "the red card";
  EXPECT_FALSE(f.shows(frame, "STKEYS1", 239, 181)) << "no yellow key";
  EXPECT_TRUE(f.shows(frame, "STYSNUM2", 111, 172)) << "the pistol owned: a yellow 2";
  EXPECT_TRUE(f.shows(frame, "STGNUM3", 123, 172)) << "no shotgun: a grey 3";
  EXPECT_TRUE(f.shows(frame, "STFST11", 143, 168)) << "the face the index names";
}

TEST(StatusBar, ScaledByWholeFactorsAndCentred) {
  Fixture f;
  image::Image small(320, 200), big(700, 400);
  f.art.draw({}, small, f.palette);
  f.art.draw({}, big, f.palette);
  EXPECT_EQ(StatusBarArt::height_in(700, 400), 64);
  EXPECT_EQ(StatusBarArt::height_in(320, 240), 32);
  const int left = (700 - 640) / 2;
  for (int y = 168; y < 200; ++y)
    for (int x = 0; x < 320; ++x)
      for (int d = 0; d < 4; ++d)
        ASSERT_EQ(big.at(left + 2 * x + d % 2, 2 * y + d / 2), small.at(x, y)) << x << "," << y;
  EXPECT_EQ(big.at(0, 399), image::rgba(0, 0, 0)) << "the sides are left as they were";
}

TEST(StatusBar, TheFaceGlancesEveryHalfSecondAndShowsPain) {
  Face face;
  Random random;
  std::set<int> seen;
  int changes = 0, last = -1;
  for (int tic = 0; tic < 35 * 20; ++tic) {
    face.tic(random, 100);
    seen.insert(face.index());
    changes += face.index() != last;
    last = face.index();
  }
  EXPECT_EQ(seen, (std::set<int>{0, 1, 2})) << "straight ahead, and either side";
  EXPECT_LE(changes, 20 * 2 + 1) << "at most a new glance each 17 tics";
  EXPECT_GT(changes, 10);
  EXPECT_EQ(random.play_index(), 0) << "the play stream is never drawn from";
  Face hurt;
  for (int tic = 0; tic < 20; ++tic) hurt.tic(random, 10);
  EXPECT_GE(hurt.index(), 4 * 8) << "10% health: the last face of pain";
  hurt.tic(random, 0);
  EXPECT_EQ(hurt.index(), 5 * 8 + 1) << "the dead face (STFDEAD0), after the god's";
}

// Doom's message font: capitals from STCFN, other characters a 4-pixel space.
TEST(HudFont, DrawsDoomsLettersInCapitals) {
  Fixture f;
  const HudFont font = *HudFont::load(f.wads);
  image::Image frame(320, 200), upper(320, 200);
  font.draw(frame, "a b", 0, 0, 1, 0, 0, f.palette);
  font.draw(upper, "A B", 0, 0, 1, 0, 0, f.palette);
  EXPECT_EQ(frame.pixels, upper.pixels) << "in capitals";
  EXPECT_TRUE(f.shows(frame, "STCFN065", 0, 0));
  const int a = wad::decode_picture(f.wads.find("STCFN065")->bytes, "A").width;
  EXPECT_TRUE(f.shows(frame, "STCFN066", a + 4, 0)) << "a space is 4 pixels";
  image::Image big(640, 400);
  EXPECT_EQ(font.draw(big, "A", 0, 0, 2, 0, 0, f.palette), (font.height() + 1) * 2);
  EXPECT_EQ(big.at(1, 1), big.at(0, 0)) << "each texel a 2x2 square";
}

}  // namespace
}  // namespace p3d::play
