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

}  // namespace
}  // namespace p3d::play
