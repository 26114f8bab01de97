// DEHACKED's BEX strings: Doom's messages as a WAD rewords them.
#include <gtest/gtest.h>

#include "engine/bsp/load.h"
#include "engine/play/dehacked.h"
#include "tests/support/support.h"

namespace p3d::play {
namespace {

TEST(Dehacked, BexStringsRewordDoomsMessages) {
  const auto texts = parse_dehacked_texts(
      "Patch File for DeHackEd v3.0\n[CODEPTR]\nGOTCLIP = not a string section\n"
      "[STRINGS]\n# a comment\nGOTCHAINGUN = You got the minigun!\r\n"
      "GOTSHOTGUN  =  A boom\\\n stick!\nUNKNOWN = nobody says this\nGOTSUPER =\n[PARS]\npar 1 1 30\n");
  EXPECT_EQ(texts.at("You got the chaingun!"), "You got the minigun!");
  EXPECT_EQ(texts.at("You got the shotgun!"), "A boomstick!") << "a value goes on after a trailing backslash";
  EXPECT_FALSE(texts.count("Picked up a clip.")) << "only the [STRINGS] section rewords";
  EXPECT_FALSE(texts.count("Supercharge!")) << "an empty value keeps Doom's";
  EXPECT_EQ(texts.size(), 2u);
}

TEST(Dehacked, FreedoomsIwadRewordsAsChocolateDoomShowsIt) {
  const wad::Stack wads = bsp::read_wads({test::freedoom_path("freedoom2.wad")});
  const auto texts = dehacked_texts(wads);
  ASSERT_TRUE(texts.count("You got the chaingun!"));
  EXPECT_EQ(texts.at("You got the chaingun!"), "You got the minigun!");
}

TEST(Dehacked, BexParsSetTheTallysParTimes) {
  const auto pars = parse_dehacked_pars("[PARS]\npar 1 1 30  # E1M1\npar 2 9 360\npar 7 180\n# par 8 60\n[STRINGS]\npar 9 1\n");
  EXPECT_EQ(pars.at({1, 1}), 30);
  EXPECT_EQ(pars.at({2, 9}), 360);
  EXPECT_EQ(pars.at({0, 7}), 180) << "two numbers: Doom II's MAP07";
  EXPECT_EQ(pars.size(), 3u) << "comments and other sections are not pars";
  const auto freedoom = dehacked_pars(bsp::read_wads({test::freedoom_path("freedoom1.wad")}));
  EXPECT_EQ(freedoom.at({1, 2}), 120) << "Freedoom's own par for E1M2 (Doom's is 75)";
}

}  // namespace
}  // namespace p3d::play
