// The music player without a sound card: Freedoom's MAP01 music synthesized through
// FluidSynth (not silent, louder at volume 15 than at 8, nothing at 0, added to what
// the buffer holds), pause, stop, looping, a missing sound font; and 10 s of MAP01
// written to a WAV file with its level over time and the synthesis's cost.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <thread>

#include "engine/bsp/load.h"
#include "engine/play/music.h"
#include "game/music_player.h"
#include "game/session.h"
#include "tests/support/support.h"

namespace p3d::game {
namespace {

constexpr int kRate = 44100;

// The sound font, or the test skipped when none is installed.
#define REQUIRE_SOUNDFONT(path)                                        \
  std::string why_;                                                    \
  const auto path = find_soundfont("", why_);                          \
  if (!path) GTEST_SKIP() << why_ << " (tools/install-deps.sh installs fluid-soundfont-gm)"

MusicOptions quick_options(const std::filesystem::path& font) {
  MusicOptions o;
  o.rate = kRate;
  o.soundfont = font;
  o.wait_for_soundfont = true;
  o.samples_on_demand = true;  // a second to start rather than five
  return o;
}

wad::MidiSong map01_song() {
  const wad::Stack wads = bsp::read_wads({test::freedoom_path("freedoom2.wad")});
  return play::read_song(wads, play::map_track("MAP01").music);
}

// `seconds` of what the player adds to a buffer holding `base` in every sample,
// in blocks of an audio callback's size.
std::vector<int16_t> render(MusicPlayer& player, double seconds, int16_t base = 0) {
  std::vector<int16_t> out(size_t(seconds * kRate) * 2, base);
  for (size_t at = 0; at < out.size(); at += 1024)
    player.mix(std::span<int16_t>(out).subspan(at, std::min<size_t>(1024, out.size() - at)));
  return out;
}

double rms(std::span<const int16_t> samples, int16_t base = 0) {
  double sum = 0;
  for (int16_t s : samples) sum += (double(s) - base) * (double(s) - base);
  return samples.empty() ? 0 : std::sqrt(sum / double(samples.size()));
}

// A song of one note (channel 0, a piano, key 60) held `note_us`, the song `length_us` long.
wad::MidiSong one_note(uint64_t note_us, uint64_t length_us) {
  wad::MidiSong song;
  song.messages = {{0, 0xC0, 0, 0}, {0, 0x90, 60, 110}, {note_us, 0x80, 60, 0}};
  song.length_us = length_us;
  song.tracks = 1;
  return song;
}

TEST(MusicPlayer, FindsDebiansSoundFontOrTheOneGiven) {
  std::string why;
  EXPECT_FALSE(find_soundfont("/nonexistent/x.sf2", why));
  EXPECT_EQ(why, "no sound font /nonexistent/x.sf2");
  REQUIRE_SOUNDFONT(font);
  EXPECT_EQ(find_soundfont(font->string(), why), *font);
}

TEST(MusicPlayer, WithoutASoundFontIsSilentAndSaysWhy) {
  MusicPlayer none(MusicOptions{});
  EXPECT_TRUE(none.failed());
  EXPECT_EQ(none.problem(), "no sound font");
  none.play(one_note(100000, 200000), true);
  EXPECT_EQ(render(none, 0.1, 7), std::vector<int16_t>(size_t(0.1 * kRate) * 2, 7));

  const auto dir = test::temp_dir("music-bad-font");
  std::ofstream(dir / "bad.sf2") << "not a sound font";
  MusicOptions o = quick_options(dir / "bad.sf2");
  MusicPlayer bad(o);
  EXPECT_TRUE(bad.failed());
  EXPECT_NE(bad.problem().find("bad.sf2: not loaded"), std::string::npos) << bad.problem();
}

// The game makes its player with the font loading on a thread: a player gone before
// the font has loaded (a game quit at once) stops the reading rather than wait for it.
TEST(MusicPlayer, LoadsTheWholeFontOnAThreadThatStopsWhenThePlayerGoes) {
  REQUIRE_SOUNDFONT(font);
  using Clock = std::chrono::steady_clock;
  auto t0 = Clock::now();
  {
    MusicPlayer player(MusicOptions{kRate, *font});
    while (!player.ready() && !player.failed()) std::this_thread::sleep_for(std::chrono::milliseconds(5));
    ASSERT_TRUE(player.ready()) << player.problem();
  }
  const double whole = std::chrono::duration<double>(Clock::now() - t0).count();
  t0 = Clock::now();
  { MusicPlayer gone(MusicOptions{kRate, *font}); }
  const double stopped = std::chrono::duration<double>(Clock::now() - t0).count();
  std::printf("the whole font (%s): loaded in %.2f s; a player gone at once: %.3f s\n", font->c_str(), whole, stopped);
  EXPECT_LT(stopped, std::max(0.2, whole / 2));
}

// Not silent, and Doom's volume scales it: 8 plays at 64/120 of 15's level (Chocolate's
// gain, volume * 8 / 127), 0 adds nothing to the sound effects already in the buffer.
TEST(MusicPlayer, PlaysMap01AtDoomsVolumes) {
  REQUIRE_SOUNDFONT(font);
  MusicPlayer player(quick_options(*font));
  ASSERT_TRUE(player.ready()) << player.problem();
  const wad::MidiSong song = map01_song();
  player.set_volume(15);
  player.play(song, true);
  const std::vector<int16_t> loud = render(player, 3.0);
  player.set_volume(8);
  player.play(song, true);  // from the start again, the synthesizer reset
  const std::vector<int16_t> default_volume = render(player, 3.0);
  player.set_volume(0);
  player.play(song, true);
  const std::vector<int16_t> muted = render(player, 3.0, 1000);

  const double loud_rms = rms(loud), default_rms = rms(default_volume);
  std::printf("MAP01 (D_RUNNIN), 3 s: RMS %.0f at volume 15, %.0f at 8 (ratio %.3f, expected %.3f)\n", loud_rms,
              default_rms, default_rms / loud_rms, 64.0 / 120.0);
  EXPECT_GT(loud_rms, 300) << "music is heard";
  EXPECT_NEAR(default_rms / loud_rms, 64.0 / 120.0, 0.01);
  EXPECT_EQ(muted, std::vector<int16_t>(loud.size(), 1000)) << "volume 0: the effects alone";
  EXPECT_TRUE(player.playing());
}

// Two players made alike play alike (a player restarting a song does not: FluidSynth's
// chorus goes on from where it was).
TEST(MusicPlayer, AddsToTheSoundEffects) {
  REQUIRE_SOUNDFONT(font);
  MusicPlayer player(quick_options(*font)), twin(quick_options(*font));
  player.play(one_note(500000, 600000), false);
  twin.play(one_note(500000, 600000), false);
  const std::vector<int16_t> alone = render(player, 0.5);
  const std::vector<int16_t> over = render(twin, 0.5, 1000);
  ASSERT_GT(rms(alone), 100);
  for (size_t i = 0; i < alone.size(); ++i) ASSERT_EQ(over[i], std::clamp(alone[i] + 1000, -32768, 32767)) << i;
}

TEST(MusicPlayer, PauseHoldsTheSongWhereItIs) {
  REQUIRE_SOUNDFONT(font);
  MusicPlayer player(quick_options(*font)), twin(quick_options(*font));
  const wad::MidiSong song = map01_song();
  twin.play(song, true);
  render(twin, 1.0);
  const std::vector<int16_t> straight_on = render(twin, 1.0);
  player.play(song, true);
  render(player, 1.0);
  player.pause();
  EXPECT_EQ(render(player, 0.5, 3), std::vector<int16_t>(size_t(0.5 * kRate) * 2, 3)) << "paused: nothing added";
  player.resume();
  EXPECT_EQ(render(player, 1.0), straight_on) << "resumed where it was";
  player.stop();
  EXPECT_FALSE(player.playing());
  EXPECT_EQ(rms(render(player, 0.2)), 0) << "stopped";
}

TEST(MusicPlayer, LoopsOrPlaysOnce) {
  REQUIRE_SOUNDFONT(font);
  MusicPlayer player(quick_options(*font));
  // A note of 0.1 s in a song of 0.25 s: looping, it sounds again in every 0.25 s.
  player.play(one_note(100000, 250000), true);
  const std::vector<int16_t> looped = render(player, 1.0);
  const size_t quarter = size_t(0.25 * kRate) * 2, note = size_t(0.08 * kRate) * 2;
  for (int i = 0; i < 4; ++i)
    EXPECT_GT(rms(std::span(looped).subspan(size_t(i) * quarter, note)), 100) << "loop " << i;
  player.play(one_note(100000, 250000), false);
  const std::vector<int16_t> once = render(player, 1.0);
  EXPECT_GT(rms(std::span(once).subspan(0, note)), 100);
  EXPECT_EQ(rms(std::span(once).subspan(quarter)), 0) << "reset at the song's end, as FluidSynth's player does";
  EXPECT_FALSE(player.playing());
}

// What the window plays (Session::music): the map's track, the intermission's during
// the tally, the next map's after it; nothing for a level that is no Doom map.
TEST(SessionMusic, MapIntermissionAndNextMap) {
  Session doom2(bsp::LevelSource{{}, {test::freedoom_path("freedoom2.wad")}, "MAP01"});
  EXPECT_EQ(doom2.music(), (play::Track{play::Music::kRunnin, true}));
  ASSERT_TRUE(doom2.start_intermission());
  EXPECT_EQ(doom2.music(), (play::Track{play::Music::kDm2int, true}));
  doom2.enter_next_map();
  EXPECT_EQ(doom2.music(), (play::Track{play::Music::kStalks, true}));
  const std::optional<wad::MidiSong> song =
      play::read_song(bsp::read_wads({test::freedoom_path("freedoom2.wad")}), doom2.music().music);
  ASSERT_TRUE(song);
  EXPECT_FALSE(song->messages.empty());

  Session doom(bsp::LevelSource{{}, {test::freedoom_path("freedoom1.wad")}, "E4M1"});
  EXPECT_EQ(doom.music().music, play::Music::kE3M4);
  ASSERT_TRUE(doom.start_intermission());
  EXPECT_EQ(doom.music().music, play::Music::kInter);

  Session mine(test::source_dir() / "maps/outpost.map");
  EXPECT_EQ(mine.music().music, play::Music::kNone);
}

// The listening check a machine can do: 10 s of MAP01's music as the game plays it
// (volume 15), written to a WAV file, its level every half second, and what the
// synthesis costs (P3D_MUSIC_WHOLE_FONT=1: with the whole font loaded first, as the
// game loads it, rather than samples read as the notes need them).
TEST(MusicPlayer, TenSecondsOfMap01ToAWavFile) {
  REQUIRE_SOUNDFONT(font);
  MusicOptions options = quick_options(*font);
  options.samples_on_demand = !std::getenv("P3D_MUSIC_WHOLE_FONT");
  MusicPlayer player(options);
  player.set_volume(15);
  player.play(map01_song(), true);
  const auto start = std::chrono::steady_clock::now();
  const std::vector<int16_t> audio = render(player, 10.0);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  const std::filesystem::path wav = std::filesystem::temp_directory_path() / "p3d-map01-music.wav";
  {
    std::ofstream out(wav, std::ios::binary);
    const auto u32 = [&](uint32_t v) { for (int i = 0; i < 4; ++i) out.put(char(v >> (8 * i))); };
    const auto u16 = [&](uint16_t v) { out.put(char(v)), out.put(char(v >> 8)); };
    const uint32_t bytes = uint32_t(audio.size() * 2);
    out.write("RIFF", 4), u32(36 + bytes), out.write("WAVEfmt ", 8), u32(16), u16(1), u16(2), u32(kRate),
        u32(kRate * 4), u16(4), u16(16), out.write("data", 4), u32(bytes);
    for (int16_t s : audio) u16(uint16_t(s));
  }
  std::printf("wrote %s: 10 s of D_RUNNIN at volume 15; synthesized in %.3f s (%.1f ms a second of audio%s)\n",
              wav.c_str(), seconds, seconds * 100, options.samples_on_demand ? ", samples read on demand" : "");
  std::printf("RMS every 0.5 s:");
  const size_t half = size_t(0.5 * kRate) * 2;
  int quiet = 0, clipped = 0;
  for (size_t at = 0; at + half <= audio.size(); at += half) {
    const double level = rms(std::span(audio).subspan(at, half));
    std::printf(" %.0f", level);
    quiet += level < 150;
  }
  for (int16_t s : audio) clipped += s == 32767 || s == -32768;
  std::printf("\n%d of %zu samples at full scale\n", clipped, audio.size());
  EXPECT_LE(quiet, 1) << "music all along (a rest of half a second at most)";
  EXPECT_LT(clipped, int(audio.size() / 1000)) << "seldom clipped";
  EXPECT_EQ(player.samples_rendered(), uint64_t(10 * kRate));
}

}  // namespace
}  // namespace p3d::game
