// Which music Doom plays when (Chocolate's S_Start, D_DoAdvanceDemo, WI_Ticker,
// F_StartFinale, the mus cheat), and every Freedoom map's track read from its WAD.
#include <gtest/gtest.h>

#include "engine/bsp/load.h"
#include "engine/play/music.h"
#include "engine/util/error.h"
#include "tests/support/mus_writer.h"
#include "tests/support/support.h"
#include "tests/support/wad_writer.h"

namespace p3d::play {
namespace {

TEST(Music, LumpNamesAreDoomsWithD) {
  EXPECT_EQ(music_lump_name(Music::kE1M1), "D_E1M1");
  EXPECT_EQ(music_lump_name(Music::kTheDa), "D_THE_DA");
  EXPECT_EQ(music_lump_name(Music::kReadM), "D_READ_M");
  EXPECT_EQ(music_lump_name(Music::kDm2int), "D_DM2INT");
  EXPECT_EQ(music_name(Music::kIntroa), "introa");
}

TEST(Music, MapsPlayDoomsTracks) {
  EXPECT_EQ(map_track(1, 1), (Track{Music::kE1M1, true}));
  EXPECT_EQ(map_track(2, 5).music, Music::kE2M5);
  EXPECT_EQ(map_track(3, 9).music, Music::kE3M9);
  // Episode 4 borrows (spmus).
  EXPECT_EQ(map_track(4, 1).music, Music::kE3M4);
  EXPECT_EQ(map_track(4, 4).music, Music::kE1M5);
  EXPECT_EQ(map_track(4, 9).music, Music::kE1M9);
  EXPECT_EQ(map_track(4, 10).music, Music::kNone);
  // Doom II: MAP01 D_RUNNIN ... MAP30 D_OPENIN, MAP31 D_EVIL, MAP32 D_ULTIMA, then on into the table.
  EXPECT_EQ(map_track(0, 1).music, Music::kRunnin);
  EXPECT_EQ(map_track(0, 7).music, Music::kShawn);
  EXPECT_EQ(map_track(0, 30).music, Music::kOpenin);
  EXPECT_EQ(map_track(0, 31).music, Music::kEvil);
  EXPECT_EQ(map_track(0, 32).music, Music::kUltima);
  EXPECT_EQ(map_track(0, 33).music, Music::kReadM);
  EXPECT_EQ(map_track(0, 35).music, Music::kDm2int);
  EXPECT_EQ(map_track(0, 36).music, Music::kNone);
  EXPECT_EQ(map_track(0, 0).music, Music::kNone);
  EXPECT_EQ(map_track("E4M2").music, Music::kE3M2);
  EXPECT_EQ(map_track("MAP02").music, Music::kStalks);
  EXPECT_EQ(map_track("START").music, Music::kNone);
  EXPECT_EQ(map_track("MAP01X").music, Music::kNone);
}

TEST(Music, TitleIntermissionAndFinale) {
  EXPECT_EQ(title_track(false), (Track{Music::kIntro, false})) << "S_StartMusic: once";
  EXPECT_EQ(title_track(true), (Track{Music::kDm2ttl, false}));
  EXPECT_EQ(intermission_track(false), (Track{Music::kInter, true}));
  EXPECT_EQ(intermission_track(true), (Track{Music::kDm2int, true}));
  EXPECT_EQ(finale_track(false), (Track{Music::kVictor, true}));
  EXPECT_EQ(finale_track(true), (Track{Music::kReadM, true}));
  EXPECT_EQ(bunny_track(), (Track{Music::kBunny, false}));
  EXPECT_EQ(cast_track(), (Track{Music::kEvil, true}));
}

TEST(Music, TheMusCheatAsDoomCountsIt) {
  EXPECT_EQ(cheat_track('0', '1', true).music, Music::kRunnin);
  EXPECT_EQ(cheat_track('3', '2', true).music, Music::kUltima);
  EXPECT_EQ(cheat_track('3', '5', true).music, Music::kDm2int);
  EXPECT_EQ(cheat_track('3', '6', true).music, Music::kNone) << "IMPOSSIBLE SELECTION";
  EXPECT_EQ(cheat_track('0', '0', true).music, Music::kIntroa) << "Doom's arithmetic runs off the start";
  EXPECT_EQ(cheat_track('1', '1', false).music, Music::kE1M1);
  EXPECT_EQ(cheat_track('3', '9', false).music, Music::kE3M9);
  EXPECT_EQ(cheat_track('2', '0', false).music, Music::kE1M9) << "map 0 is the last episode's map 9";
  EXPECT_EQ(cheat_track('4', '6', false).music, Music::kNone);
  EXPECT_EQ(cheat_track('1', '0', false).music, Music::kNone);
  EXPECT_EQ(cheat_track('x', '1', false).music, Music::kNone);
}

TEST(Music, SongsAreReadFromTheLastWadWithTheLump) {
  test::WadWriter iwad(true);
  iwad.lump("D_E1M1", test::random_mus(7, 10));
  wad::Stack wads;
  wads.add(wad::Wad(iwad.bytes(), "iwad.wad"));
  const wad::MidiSong song = read_song(wads, Music::kE1M1);
  EXPECT_FALSE(song.messages.empty());
  try {
    read_song(wads, Music::kE1M2);
    ADD_FAILURE() << "no D_E1M2";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "iwad.wad: no music lump D_E1M2");
  }
  test::WadWriter pwad;
  pwad.lump("D_E1M1", {'M', 'U', 'S', 0x1A, 0, 0, 16, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0x50});
  wads.add(wad::Wad(pwad.bytes(), "broken.wad"));
  try {
    read_song(wads, Music::kE1M1);
    ADD_FAILURE() << "a broken D_E1M1";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "broken.wad: D_E1M1: byte 16: unknown event type 5 (descriptor 0x50)");
  }
}

// Every map of Freedoom finds its track, and the song reads.
TEST(Music, EveryFreedoomMapHasItsTrack) {
  for (const char* file : {"freedoom1.wad", "freedoom2.wad"}) {
    const wad::Stack wads = bsp::read_wads({test::freedoom_path(file)});
    int maps = 0;
    for (const std::string& map : wads.map_names()) {
      const Track track = map_track(map);
      ASSERT_NE(track.music, Music::kNone) << map;
      const wad::MidiSong song = read_song(wads, track.music);
      EXPECT_GT(song.length_us, 10'000'000u) << map << ": " << music_lump_name(track.music);
      ++maps;
    }
    EXPECT_GE(maps, 32) << file;
    const bool commercial = std::string(file) == "freedoom2.wad";
    for (const Track t : {title_track(commercial), intermission_track(commercial), finale_track(commercial)})
      EXPECT_NO_THROW(read_song(wads, t.music)) << file << ": " << music_lump_name(t.music);
  }
}

}  // namespace
}  // namespace p3d::play
