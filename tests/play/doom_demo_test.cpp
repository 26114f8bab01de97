// Doom's demo format: Freedoom's own demos read, what is written reads back, and
// broken demos are refused with a located message.
#include <gtest/gtest.h>

#include "engine/bsp/load.h"
#include "engine/play/doom_demo.h"
#include "engine/util/error.h"
#include "tests/support/support.h"

namespace p3d::play {
namespace {

std::string demo_refusal(const std::vector<uint8_t>& bytes) {
  try {
    decode_doom_demo(bytes, "x.lmp");
  } catch (const Error& e) {
    return e.what();
  }
  return "accepted";
}

TEST(DoomDemo, FreedoomsDemosReadAsVersionOneNineOfTheirOwnMaps) {
  int read = 0;
  for (const char* file : {"freedoom1.wad", "freedoom2.wad"}) {
    const wad::Stack wads = bsp::read_wads({test::freedoom_path(file)});
    const bool commercial = wads.map("MAP01").has_value();
    for (const char* name : {"DEMO1", "DEMO2", "DEMO3", "DEMO4"}) {
      const wad::Lump* lump = wads.find(name);
      if (!lump) continue;
      const DoomDemo d = decode_doom_demo(lump->bytes, std::string(file) + ":" + name);
      EXPECT_EQ(d.version, 109) << file << " " << name;
      EXPECT_FALSE(d.truncated) << file << " " << name;
      EXPECT_GT(d.tic_count(), 35u * 10) << file << " " << name;
      EXPECT_TRUE(wads.map(d.map_name(commercial)).has_value()) << file << " " << name << " plays " << d.map_name(commercial);
      const std::vector<uint8_t> again = encode_doom_demo(d);
      EXPECT_EQ(again, std::vector<uint8_t>(lump->bytes.begin(), lump->bytes.begin() + std::ptrdiff_t(again.size())))
          << "written back byte for byte (a lump may pad after the end marker)";
      ++read;
    }
  }
  EXPECT_GE(read, 6);
}

TEST(DoomDemo, RoundTripsAndReadsTheOldFormat) {
  DoomDemo d;
  d.skill = 4;
  d.episode = 2;
  d.map = 3;
  d.players = {true, true, false, false};
  d.console_player = 1;
  for (int i = 0; i < 10; ++i) d.commands.push_back({int8_t(i), int8_t(-i), int16_t(3 * i << 8), uint8_t(i % 3)});
  const DoomDemo back = decode_doom_demo(encode_doom_demo(d), "x.lmp");
  EXPECT_EQ(back.commands, d.commands);
  EXPECT_EQ(back.tic_count(), 5u);
  EXPECT_EQ(back.console_tic(2), d.commands[5]) << "player 2's command of the third tic";
  EXPECT_EQ(back.map_name(false), "E2M3");
  EXPECT_EQ(back.map_name(true), "MAP03");
  // Doom 1.2's demos have no version byte: skill, episode, map, four players.
  const std::vector<uint8_t> old_bytes = {2, 1, 5, 1, 0, 0, 0, 25, 0, 1, 2, 0x80};
  const DoomDemo old = decode_doom_demo(old_bytes, "old.lmp");
  EXPECT_EQ(old.version, 0);
  EXPECT_EQ(old.skill, 3);
  EXPECT_EQ(old.map_name(false), "E1M5");
  ASSERT_EQ(old.tic_count(), 1u);
  EXPECT_EQ(old.console_tic(0), (DoomTic{25, 0, 256, 2})) << "the turn's byte is its high byte";
}

// Doom v1.91's long tics (version 111, Chocolate Doom's -longtics): five bytes a
// command, the turn whole, low byte first.
TEST(DoomDemo, LongTicsKeepTheWholeTurn) {
  const std::vector<uint8_t> bytes = {111, 2, 0, 7, 0, 0, 0, 0, 0, 1, 0, 0, 0,  // skill 3, MAP07
                                      50, 0xf0, 0x34, 0x12, 1, 0, 0, 0xff, 0xff, 2, 0x80};
  const DoomDemo d = decode_doom_demo(bytes, "long.lmp");
  EXPECT_TRUE(d.long_tics());
  EXPECT_EQ(d.map_name(true), "MAP07");
  ASSERT_EQ(d.tic_count(), 2u);
  EXPECT_EQ(d.console_tic(0), (DoomTic{50, -16, 0x1234, kButtonAttack}));
  EXPECT_EQ(d.console_tic(1), (DoomTic{0, 0, -1, kButtonUse})) << "a turn of 1/65536 to the right";
  EXPECT_EQ(encode_doom_demo(d), bytes) << "written back byte for byte";
  std::vector<uint8_t> cut = bytes;
  cut.resize(cut.size() - 2);
  EXPECT_EQ(demo_refusal(cut), "x.lmp: the last tic is cut short at byte 18");
}

TEST(DoomDemo, BrokenDemosAreRefusedAndAMissingEndIsTolerated) {
  const std::vector<uint8_t> header = {109, 2, 1, 1, 0, 0, 0, 0, 0, 1, 0, 0, 0};
  auto with = [&](std::vector<uint8_t> tail) {
    std::vector<uint8_t> b = header;
    b.insert(b.end(), tail.begin(), tail.end());
    return b;
  };
  EXPECT_EQ(demo_refusal({200, 1, 2}), "x.lmp: not a Doom demo (unknown version 200)");
  EXPECT_EQ(demo_refusal({109, 2, 1}), "x.lmp: truncated demo header");
  EXPECT_EQ(demo_refusal(with({25, 0, 0})), "x.lmp: the last tic is cut short at byte 13");
  std::vector<uint8_t> nobody = header;
  nobody[9] = 0;
  EXPECT_EQ(demo_refusal(nobody), "x.lmp: no player is in the game");
  std::vector<uint8_t> other_view = header;
  other_view[8] = 2;
  EXPECT_EQ(demo_refusal(other_view), "x.lmp: the demo's view is of player 3, who is not in the game");
  std::vector<uint8_t> bad_skill = header;
  bad_skill[1] = 7;
  EXPECT_EQ(demo_refusal(bad_skill), "x.lmp: skill 7 is not Doom's 0..4");
  const DoomDemo cut = decode_doom_demo(with({25, 0, 0, 0}), "x.lmp");  // no end marker: Doom plays what is there
  EXPECT_TRUE(cut.truncated);
  EXPECT_EQ(cut.tic_count(), 1u);
}

}  // namespace
}  // namespace p3d::play
