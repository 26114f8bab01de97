// Doom's status bar from Freedoom's art: each piece at Doom's place, keys and numbers
// as the values say, the same bar scaled by whole factors and centred, the rows
// above left alone, and Doom's face: glancing, grinning, turning toward an attacker,
// ouch, rampage, god and dead.
#include <gtest/gtest.h>

#include <set>

#include "engine/bsp/load.h"
#include "engine/play/hud_font.h"
#include "engine/play/status_bar.h"
#include "engine/play/world.h"
#include "engine/wad/art.h"
#include "tests/support/support.h"
#include "tests/support/wad_pictures.h"

namespace p3d::play {
namespace {

struct StatusBarFixture {
  wad::Stack wads = bsp::read_wads({test::freedoom_path("freedoom2.wad")});
  std::vector<uint32_t> palette = wad::Art(wads).palette();
  StatusBarArt art = *StatusBarArt::load(wads);

  // Whether the picture's opaque texels show at Doom's screen place (x, y) of a 320x200 frame.
  bool shows(const image::Image& frame, const std::string& lump, int x, int y) const {
    return test::shows_picture(frame, wads, palette, lump, x, y);
  }
};

TEST(StatusBar, PiecesAtDoomsPlacesAsTheValuesSay) {
  StatusBarFixture f;
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

// A netgame: the face on the player's colour; in deathmatch the frags where the arms were.
TEST(StatusBar, DeathmatchShowsTheFragsAndANetgameThePlayersColour) {
  StatusBarFixture f;
  image::Image frame(320, 200, image::rgba(1, 2, 3));
  StatusValues v;
  v.deathmatch = true;
  v.frags = 12;
  v.face_background = 2;
  f.art.draw(v, frame, f.palette);
  const int digit = wad::decode_picture(f.wads.find("STTNUM0")->bytes, "STTNUM0").width;
  EXPECT_TRUE(f.shows(frame, "STTNUM2", 138 - digit, 171)) << "12 frags, right-aligned at x 138";
  EXPECT_TRUE(f.shows(frame, "STTNUM1", 138 - 2 * digit, 171));
  EXPECT_FALSE(f.shows(frame, "STYSNUM2", 111, 172)) << "no arms in deathmatch";
  EXPECT_FALSE(f.shows(frame, "STARMS", 104, 168));
  image::Image coop(320, 200, image::rgba(1, 2, 3));
  v.deathmatch = false;
  f.art.draw(v, coop, f.palette);
  EXPECT_TRUE(f.shows(coop, "STYSNUM2", 111, 172));
}

TEST(StatusBar, ScaledByWholeFactorsAndCentred) {
  StatusBarFixture f;
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

FaceInput healthy(int health = 100) {
  FaceInput in;
  in.health = health;
  return in;
}

TEST(StatusBar, TheFaceGlancesEveryHalfSecondAndShowsPain) {
  Face face;
  Random random;
  std::set<int> seen;
  int changes = 0, last = -1;
  for (int tic = 0; tic < 35 * 20; ++tic) {
    face.tic(random, healthy());
    seen.insert(face.index());
    changes += face.index() != last;
    last = face.index();
  }
  EXPECT_EQ(seen, (std::set<int>{0, 1, 2})) << "straight ahead, and either side";
  EXPECT_LE(changes, 20 * 2 + 1) << "at most a new glance each 17 tics";
  EXPECT_GT(changes, 10);
  EXPECT_EQ(random.play_index(), 0) << "the play stream is never drawn from";
  Random counted;
  for (int tic = 0; tic < 5; ++tic) face.tic(counted, healthy());
  EXPECT_EQ(counted.other(), kRandomTable[6]) << "one draw of the other stream a tic";
  Face hurt;
  for (int tic = 0; tic < 20; ++tic) hurt.tic(random, healthy(10));
  EXPECT_GE(hurt.index(), 4 * 8) << "10% health: the last face of pain";
  hurt.tic(random, healthy(0));
  EXPECT_EQ(hurt.index(), 5 * 8 + 1) << "the dead face (STFDEAD0), after the god's";
  for (int tic = 0; tic < 100; ++tic) hurt.tic(random, healthy(0));
  EXPECT_EQ(hurt.index(), 5 * 8 + 1) << "and it stays";
}

TEST(StatusBar, TheFaceGrinsAtANewWeaponForTwoSeconds) {
  Face face;
  Random random;
  face.tic(random, healthy());
  FaceInput in = healthy(60);  // the second face of pain: 8 * (40 * 5 / 101)
  in.bonus_count = 6;
  in.weapons[2] = true;  // the shotgun
  face.tic(random, in);
  EXPECT_EQ(face.index(), 8 + 6) << "STFEVL1";
  in.bonus_count = 0;
  for (int tic = 1; tic < 70; ++tic) {
    face.tic(random, in);
    ASSERT_EQ(face.index(), 8 + 6) << tic;
  }
  face.tic(random, in);
  EXPECT_LT(face.index() - 8, 3) << "then straight again";
  in.bonus_count = 6;  // a pickup that is not a new weapon
  face.tic(random, in);
  EXPECT_LT(face.index() - 8, 3);

  Face next_level;  // weapons carried into a level are not new there
  next_level.start_level(in);
  next_level.tic(random, in);
  EXPECT_LT(next_level.index() - 8, 3);
}

TEST(StatusBar, TheFaceTurnsTowardItsAttacker) {
  auto hurt_from = [](Angle to_attacker) {
    Face face;
    Random random;
    face.tic(random, healthy());
    FaceInput in = healthy(90);
    in.damage_count = 10;
    in.attacked = true;
    in.angle = kAngle90;  // facing north
    in.angle_to_attacker = to_attacker;
    face.tic(random, in);
    return face.index();
  };
  EXPECT_EQ(hurt_from(kAngle180), 4) << "from the west, on the left: STFTL00";
  EXPECT_EQ(hurt_from(0), 3) << "from the east, on the right: STFTR00";
  EXPECT_EQ(hurt_from(kAngle90 + kAngle45 / 2), 7) << "from ahead: the rampage face";
  EXPECT_EQ(hurt_from(kAngle270), 4) << "from right behind: turned left (Doom's tie)";

  Face face;  // then turned for a second
  Random random;
  FaceInput in = healthy(90);
  face.tic(random, in);
  in.damage_count = 10;
  in.attacked = true;
  in.angle_to_attacker = kAngle90;  // facing east, hurt from the north
  for (int tic = 0; tic < 35; ++tic) {
    face.tic(random, in);
    ASSERT_EQ(face.index(), 4) << tic;
    in.damage_count = 0;
  }
  face.tic(random, in);
  EXPECT_LT(face.index(), 3);
}

TEST(StatusBar, TheFaceTakesItsInputFromThePlayer) {
  Mobj mo, imp;
  Player player;
  player.mo = &mo;
  mo.angle = kAngle90;
  imp.x = 100 * kFracUnit;  // to the east
  player.attacker = &imp;
  player.inv.damage_count = 3;
  player.inv.weapons[size_t(Weapon::kChaingun)] = true;
  player.cheats = kCheatGodMode;
  const FaceInput in = face_input(player);
  EXPECT_TRUE(in.attacked);
  EXPECT_EQ(in.angle_to_attacker, 0u);
  EXPECT_EQ(in.angle, kAngle90);
  EXPECT_EQ(in.damage_count, 3);
  EXPECT_TRUE(in.weapons[3]);
  EXPECT_TRUE(in.god_mode);
  player.attacker = &mo;
  EXPECT_FALSE(face_input(player).attacked) << "its own rocket: no one to turn to";
}

TEST(StatusBar, OuchAfterMuchPainInATic) {
  FaceInput in = healthy(100);
  Random random;
  Face meant(Face::Ouch::kBigDamage), doom;
  meant.tic(random, in);
  doom.tic(random, in);
  in.health = 70;  // 30 lost in a tic, from a thing ahead
  in.damage_count = 30;
  in.attacked = true;
  meant.tic(random, in);
  doom.tic(random, in);
  EXPECT_EQ(meant.index(), 8 + 5) << "STFOUCH1";
  EXPECT_EQ(doom.index(), 8 + 7) << "vanilla's inverted test: no ouch, the head-on face";
  // Vanilla's ouch: the health rising by more than 20 while still hurt (a medikit).
  Face healed;
  FaceInput low = healthy(30);
  healed.tic(random, low);
  low.health = 55;
  low.damage_count = 4;
  healed.tic(random, low);
  EXPECT_EQ(healed.index(), 16 + 5) << "STFOUCH2: 55% health";
  // Hurt by the world (no attacker), a little: the rampage face.
  Face slime;
  FaceInput floor = healthy(100);
  slime.tic(random, floor);
  floor.health = 95;
  floor.damage_count = 5;
  slime.tic(random, floor);
  EXPECT_EQ(slime.index(), 7);
}

TEST(StatusBar, TheFaceRampagesAfterTwoSecondsOfFiring) {
  Face face;
  Random random;
  FaceInput in = healthy();
  in.attack_down = true;
  for (int tic = 0; tic < 70; ++tic) {
    face.tic(random, in);
    ASSERT_LT(face.index(), 3) << tic;
  }
  face.tic(random, in);
  EXPECT_EQ(face.index(), 7) << "STFKILL0";
  for (int tic = 0; tic < 50; ++tic) face.tic(random, in);
  EXPECT_EQ(face.index(), 7) << "while firing on";
  in.attack_down = false;
  face.tic(random, in);
  EXPECT_LT(face.index(), 3);
}

TEST(StatusBar, TheGodsFace) {
  Face face;
  Random random;
  FaceInput in = healthy();
  in.god_mode = true;
  face.tic(random, in);
  EXPECT_EQ(face.index(), 5 * 8);
  in.god_mode = false;
  in.invulnerability = 30 * 35;
  face.tic(random, in);
  EXPECT_EQ(face.index(), 5 * 8) << "STFGOD0";
}

TEST(StatusBar, FacesLoadInDoomsOrder) {
  // The art holds a face per index; check a few by drawing them.
  StatusBarFixture f;
  const std::pair<int, const char*> faces[] = {{0, "STFST00"}, {2, "STFST02"},  {3, "STFTR00"},  {4, "STFTL00"},
                                               {5, "STFOUCH0"}, {6, "STFEVL0"}, {7, "STFKILL0"}, {8 + 7, "STFKILL1"},
                                               {40, "STFGOD0"}, {41, "STFDEAD0"}};
  for (const auto& [index, lump] : faces) {
    image::Image frame(320, 200);
    StatusValues v;
    v.face = index;
    f.art.draw(v, frame, f.palette);
    EXPECT_TRUE(f.shows(frame, lump, 143, 168)) << index << " " << lump;
  }
}

// Doom's message font: capitals from STCFN, other characters a 4-pixel space.
TEST(HudFont, DrawsDoomsLettersInCapitals) {
  StatusBarFixture f;
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
