// Music lumps: MUS converted to MIDI byte for byte as Chocolate Doom's mus2mid does
// (every music lump of freedoom1, freedoom2 and freedm, the same re-scored as MUS, and
// random scores, against the hashes of Chocolate's own conversion in
// tests/golden/music.hashes), bad scores refused with the lump and byte named, and
// MIDI files read back into timed messages.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "engine/bsp/load.h"
#include "engine/util/checksum.h"
#include "engine/util/error.h"
#include "engine/util/file.h"
#include "engine/wad/midi.h"
#include "engine/wad/mus.h"
#include "tests/support/mus_writer.h"
#include "tests/support/support.h"

namespace p3d::wad {
namespace {

using Bytes = std::vector<uint8_t>;

const char* const kWads[] = {"freedoom1.wad", "freedoom2.wad", "freedm.wad"};
constexpr int kRandomScores = 64;

int random_groups(int seed) { return 20 + seed * 7; }

Bytes mus(std::initializer_list<uint8_t> score, int instruments = 0) {
  const int start = 16 + 2 * instruments;
  const uint8_t header[] = {'M', 'U', 'S', 0x1A, uint8_t(score.size()), 0, uint8_t(start), 0, 1, 0, 0, 0,
                            uint8_t(instruments), 0};
  Bytes out(size_t(start) + score.size(), 0);  // after the header: the reserved field, the instruments (0)
  std::copy(std::begin(header), std::end(header), out.begin());
  std::copy(score.begin(), score.end(), out.begin() + start);
  return out;
}

// A MIDI file of mus2mid's header and this track.
Bytes midi(std::initializer_list<uint8_t> track) {
  Bytes out = {'M', 'T', 'h', 'd', 0, 0, 0, 6, 0, 0, 0, 1, 0, 0x46, 'M', 'T', 'r', 'k'};
  const size_t n = track.size();
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(uint8_t(n >> shift));
  out.insert(out.end(), track.begin(), track.end());
  return out;
}

std::string message_of(const Bytes& bytes, const std::string& what = "D_TEST") {
  try {
    mus_to_midi(bytes, what);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

// ---- the conversion, event by event

TEST(Mus, ConvertsEachEventAsMus2mid) {
  const Bytes in = mus({
      0x40, 0x00, 0x1E,        // ch 0: instrument 30 (the channel opened first: all notes off)
      0x91, 0xBC, 0x64,        // ch 1: key 60 at velocity 100, last of the group
      0x81, 0x0C,              // 140 ticks
      0x0F, 0x24,              // ch 15 (percussion, MIDI 9, never opened): key 36 released
      0x12, 0x3E,              // ch 2: key 62 at the channel's velocity (127 to start with)
      0x41, 0x03, 0xFF,        // ch 1: volume 255, written 127
      0xA1, 0x80,              // ch 1: pitch wheel centred, last
      0x00,                    // no delay
      0x33, 0x0B,              // ch 3 (opened): system event 11, all notes off
      0x60,                    // the end
  });
  const Bytes expected = midi({
      0x00, 0xB0, 0x7B, 0x00, 0x00, 0xC0, 0x1E,  //
      0x00, 0xB1, 0x7B, 0x00, 0x00, 0x91, 0x3C, 0x64,
      0x81, 0x0C, 0x89, 0x24, 0x00,  //
      0x00, 0xB2, 0x7B, 0x00, 0x00, 0x92, 0x3E, 0x7F,
      0x00, 0xB1, 0x07, 0x7F,  //
      0x00, 0xE1, 0x00, 0x40,  //
      0x00, 0xB3, 0x7B, 0x00, 0x00, 0xB3, 0x7B, 0x00,
      0x00, 0xFF, 0x2F, 0x00,
  });
  EXPECT_EQ(mus_to_midi(in, "D_TEST"), expected);
}

TEST(Mus, ChannelsInOrderOfFirstUseSkippingPercussion) {
  std::initializer_list<uint8_t> score = {0x1A, 0x3C, 0x10, 0x3C, 0x15, 0x3C, 0x11, 0x3C, 0x12, 0x3C, 0x13, 0x3C,
                                          0x14, 0x3C, 0x16, 0x3C, 0x17, 0x3C, 0x18, 0x3C, 0x19, 0x3C, 0x60};
  const Bytes out = mus_to_midi(mus(score), "D_TEST");
  const MidiSong song = read_midi(out, "D_TEST");
  std::vector<int> channels;  // of the notes, in order
  for (const MidiMessage& m : song.messages)
    if ((m.status & 0xF0) == 0x90) channels.push_back(m.status & 0x0F);
  EXPECT_EQ(channels, (std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7, 8, 10, 11}));
}

TEST(Mus, VelocityKeptPerChannelAndScoreEndOpensItsChannel) {
  const Bytes out = mus_to_midi(mus({0x10, 0xBC, 0x32, 0x10, 0x3E, 0x11, 0x40, 0x65}), "D_TEST");
  EXPECT_EQ(out, midi({0x00, 0xB0, 0x7B, 0x00, 0x00, 0x90, 0x3C, 0x32, 0x00, 0x90, 0x3E, 0x32,  //
                       0x00, 0xB1, 0x7B, 0x00, 0x00, 0x91, 0x40, 0x7F,                          //
                       0x00, 0xB2, 0x7B, 0x00, 0x00, 0xFF, 0x2F, 0x00}));
}

TEST(Mus, MidiPassesThroughAndOtherLumpsAreRefused) {
  const Bytes m = midi({0x00, 0xFF, 0x2F, 0x00});
  EXPECT_EQ(music_to_midi(m, "D_X"), m);
  EXPECT_THROW(music_to_midi(Bytes{'R', 'I', 'F', 'F', 0, 0}, "D_X"), Error);
  EXPECT_TRUE(is_mus(mus({0x60})));
  EXPECT_FALSE(is_mus(m));
  EXPECT_TRUE(is_midi(m));
}

TEST(Mus, HeaderFieldsAtOddsWithTheScoreAreWarnedOf) {
  Bytes in = mus({0x60});
  in[4] = 200;  // score length past the end
  in[8] = 17;   // primary channels
  std::vector<std::string> warnings;
  EXPECT_EQ(mus_to_midi(in, "D_TEST", &warnings), midi({0x00, 0xB0, 0x7B, 0x00, 0x00, 0xFF, 0x2F, 0x00}));
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_NE(warnings[0].find("byte 4: score length 200"), std::string::npos) << warnings[0];
  EXPECT_NE(warnings[1].find("byte 8:"), std::string::npos) << warnings[1];
  warnings.clear();
  in = mus({0x60}, 2);
  in[12] = 5;  // 5 instruments claimed, room for 2
  mus_to_midi(in, "D_TEST", &warnings);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("byte 12: the list of 5 instruments"), std::string::npos) << warnings[0];
}

// ---- bad scores: an Error naming the lump and the byte, never a crash

TEST(Mus, BadScoresAreRefusedWithTheLumpAndByte) {
  struct Case {
    Bytes bytes;
    std::string message;
  };
  Bytes bad_id = mus({0x60});
  bad_id[3] = 0;
  Bytes start_past_end = mus({0x60});
  start_past_end[6] = 17;
  Bytes start_in_header = mus({0x60});
  start_in_header[6] = 4;
  const std::vector<Case> cases = {
      {Bytes{'M', 'U', 'S', 0x1A, 0, 0}, "D_BAD: byte 6: the lump ends inside the 16-byte MUS header"},
      {bad_id, "D_BAD: byte 0: not a MUS score"},
      {start_past_end, "D_BAD: byte 6: score start 17 is past the lump's end (17 bytes)"},
      {start_in_header, "D_BAD: byte 6: score start 4 lies inside the 16-byte header"},
      {mus({0x10}), "D_BAD: byte 17: the lump ends before a pressed key"},
      {mus({0x10, 0x80}), "D_BAD: byte 18: the lump ends before a key's velocity"},
      {mus({0x00}), "D_BAD: byte 17: the lump ends before a released key"},
      {mus({0x20}), "D_BAD: byte 17: the lump ends before a pitch wheel's value"},
      {mus({0x40, 0x03}), "D_BAD: byte 18: the lump ends before a controller's value"},
      {mus({0x50, 0x00}), "D_BAD: byte 16: unknown event type 5 (descriptor 0x50)"},
      {mus({0x10, 0x3C, 0xF2}), "D_BAD: byte 18: unknown event type 7 (descriptor 0xF2)"},
      {mus({0x30, 0x09}), "D_BAD: byte 17: unknown system event 9 (10..14)"},
      {mus({0x30, 0x0F}), "D_BAD: byte 17: unknown system event 15 (10..14)"},
      {mus({0x40, 0x0A, 0x00}), "D_BAD: byte 17: unknown controller 10 (0..9)"},
      {mus({0x90, 0x3C, 0x81}), "D_BAD: byte 19: the lump ends before a delay"},
      {mus({0x90, 0x3C, 0x81, 0x80, 0x80, 0x80, 0x00, 0x60}), "D_BAD: byte 18: a delay longer than MIDI can write"},
      {mus({0x90, 0x3C, 0x05}), "D_BAD: byte 19: the lump ends before an event"},
      {mus({0x90, 0x3C, 0xFF, 0xFF, 0xFF, 0x7F, 0x60}), "D_BAD: byte 18: the score runs longer than 24 hours"},
  };
  for (const Case& c : cases) {
    const std::string message = message_of(c.bytes, "D_BAD");
    EXPECT_EQ(message.substr(0, c.message.size()), c.message) << message;
  }
  // Delays of four bytes are read (2^21 ticks, 4 hours); leading zero groups are read as nothing.
  EXPECT_NO_THROW(mus_to_midi(mus({0x90, 0x3C, 0x81, 0x80, 0x80, 0x00, 0x60}), "D_OK"));
  EXPECT_NO_THROW(mus_to_midi(mus({0x90, 0x3C, 0x80, 0x80, 0x80, 0x80, 0x80, 0x05, 0x60}), "D_OK"));
}

TEST(Mus, EveryTruncationOfAScoreIsRefused) {
  for (uint64_t seed = 1; seed <= 4; ++seed) {
    const Bytes whole = test::random_mus(seed, 30);
    const Bytes midi_whole = mus_to_midi(whole, "D_WHOLE");
    // The score's end is its last event, before any padding.
    size_t end = whole.size();
    while (end > 0 && whole[end - 1] == 0) --end;
    for (size_t n = 0; n < whole.size(); ++n) {
      const Bytes cut(whole.begin(), whole.begin() + std::ptrdiff_t(n));
      if (n >= end) {
        EXPECT_EQ(mus_to_midi(cut, "D_CUT"), midi_whole) << "seed " << seed << ", " << n << " bytes";
      } else {
        EXPECT_THROW(mus_to_midi(cut, "D_CUT"), Error) << "seed " << seed << ", " << n << " bytes";
      }
    }
  }
}

// ---- Chocolate's own conversions (tests/golden/music.hashes)

struct Golden {
  uint64_t in_bytes = 0, out_bytes = 0;
  std::string in_hash, out_hash;
};
// By "kind source lump".
std::map<std::string, Golden> read_golden() {
  std::ifstream in(test::source_dir() / "tests/golden/music.hashes");
  std::map<std::string, Golden> golden;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    std::string kind, source, lump;
    Golden g;
    fields >> kind >> source >> lump >> g.in_bytes >> g.in_hash >> g.out_bytes >> g.out_hash;
    golden[kind + " " + source + " " + lump] = g;
  }
  return golden;
}

std::string hex(uint64_t v) {
  char s[17];
  std::snprintf(s, sizeof s, "%016llx", static_cast<unsigned long long>(v));
  return s;
}

// The inputs of the golden file by key, and our conversion of each.
struct Input {
  std::string key;
  Bytes bytes;
};

std::vector<Input> wad_inputs(const std::string& file, bool rescored) {
  std::vector<Input> out;
  const Stack wads = bsp::read_wads({std::filesystem::path("/usr/share/games/doom") / file});
  for (const Lump& lump : wads.wads().front().lumps()) {
    if (lump.name.rfind("D_", 0) != 0) continue;
    Bytes bytes(lump.bytes.begin(), lump.bytes.end());
    if (rescored) bytes = test::midi_to_mus(read_midi(bytes, file + ": " + lump.name));
    out.push_back({std::string(rescored ? "rescored " : "lump ") + file + " " + lump.name, std::move(bytes)});
  }
  return out;
}

std::vector<Input> random_inputs() {
  std::vector<Input> out;
  for (int seed = 1; seed <= kRandomScores; ++seed)
    out.push_back({"random seed-" + std::to_string(seed) + " " + std::to_string(random_groups(seed)),
                   test::random_mus(uint64_t(seed), random_groups(seed))});
  return out;
}

// Checks our conversions against Chocolate's; returns how many matched.
int check_against_golden(const std::vector<Input>& inputs, const std::map<std::string, Golden>& golden) {
  int matched = 0;
  for (const Input& input : inputs) {
    const auto it = golden.find(input.key);
    if (it == golden.end()) {
      ADD_FAILURE() << input.key << ": not in tests/golden/music.hashes";
      continue;
    }
    const Golden& g = it->second;
    EXPECT_EQ(hex(checksum64(input.bytes)), g.in_hash) << input.key << ": another input than Chocolate converted";
    const Bytes ours = music_to_midi(input.bytes, input.key);
    EXPECT_EQ(ours.size(), g.out_bytes) << input.key;
    EXPECT_EQ(hex(checksum64(ours)), g.out_hash) << input.key;
    matched += ours.size() == g.out_bytes && hex(checksum64(ours)) == g.out_hash;
    EXPECT_NO_THROW(read_midi(ours, input.key)) << "every conversion is a MIDI file we read";
  }
  return matched;
}

// The WAD's lumps, if this version of it is the one the hashes were made from.
bool installed_as_measured(const std::string& file, const std::map<std::string, Golden>& golden, std::string& why) {
  if (!std::filesystem::exists(std::filesystem::path("/usr/share/games/doom") / file)) {
    why = file + " is not installed";
    return false;
  }
  for (const Input& input : wad_inputs(file, false)) {
    const auto it = golden.find(input.key);
    if (it == golden.end() || it->second.in_hash != hex(checksum64(input.bytes))) {
      why = file + " is another version than the one measured (" + input.key + ")";
      return false;
    }
  }
  return true;
}

TEST(MusGolden, EveryFreedoomMusicLumpAsChocolateConvertsIt) {
  const auto golden = read_golden();
  ASSERT_FALSE(golden.empty());
  int checked = 0;
  for (const char* file : kWads) {
    std::string why;
    if (!installed_as_measured(file, golden, why)) {
      std::printf("skipped: %s\n", why.c_str());
      continue;
    }
    const std::vector<Input> lumps = wad_inputs(file, false), rescored = wad_inputs(file, true);
    EXPECT_EQ(check_against_golden(lumps, golden), int(lumps.size())) << file;
    EXPECT_EQ(check_against_golden(rescored, golden), int(rescored.size())) << file << " re-scored as MUS";
    std::printf("%s: %zu music lumps and the same re-scored as MUS, byte for byte as Chocolate's\n", file, lumps.size());
    checked += int(lumps.size());
  }
  if (checked == 0) GTEST_SKIP() << "none of freedoom1, freedoom2, freedm installed as measured";
}

TEST(MusGolden, RandomScoresAsChocolateConvertsThem) {
  const std::vector<Input> inputs = random_inputs();
  EXPECT_EQ(check_against_golden(inputs, read_golden()), kRandomScores);
}

// Writes every input of the golden file, one file each, for tools/peers/music_hashes.sh
// to convert with Chocolate's mus2mid (P3D_MUS_INPUTS names the directory).
TEST(MusGolden, DISABLED_WriteInputs) {
  const char* dir = std::getenv("P3D_MUS_INPUTS");
  ASSERT_NE(dir, nullptr) << "set P3D_MUS_INPUTS to a directory";
  std::vector<Input> inputs = random_inputs();
  for (const char* file : kWads)
    for (bool rescored : {false, true})
      for (Input& input : wad_inputs(file, rescored)) inputs.push_back(std::move(input));
  for (const Input& input : inputs) {
    std::string name = input.key;
    std::replace(name.begin(), name.end(), ' ', '~');
    write_file_atomically(std::filesystem::path(dir) / name, input.bytes);
  }
}

// ---- MIDI files read back

TEST(Midi, ReadsTimedMessagesThroughTempoChangesAndRunningStatus) {
  // Two tracks at 96 ticks a quarter note: a tempo change after a quarter note to
  // twice as fast; notes in running status.
  const Bytes file = {'M', 'T', 'h', 'd', 0, 0, 0, 6, 0, 1, 0, 2, 0, 96,
                      'M', 'T', 'r', 'k', 0, 0, 0, 11,
                      0x60, 0xFF, 0x51, 0x03, 0x03, 0xD0, 0x90,  // 250000 us a quarter after 96 ticks
                      0x00, 0xFF, 0x2F, 0x00,
                      'M', 'T', 'r', 'k', 0, 0, 0, 19,
                      0x00, 0x90, 0x3C, 0x64,        // note on at 0
                      0x60, 0x3E, 0x64,              // running status at 96: 0.5 s
                      0x60, 0xFF, 0x01, 0x01, 'x',   // a text event at 192 keeps the running status
                      0x00, 0x40, 0x00,              // at 192: 0.75 s
                      0x00, 0xFF, 0x2F, 0x00};
  const MidiSong song = read_midi(file, "TEST");
  ASSERT_EQ(song.messages.size(), 3u);
  EXPECT_EQ(song.messages[0], (MidiMessage{0, 0x90, 0x3C, 0x64}));
  EXPECT_EQ(song.messages[1], (MidiMessage{500000, 0x90, 0x3E, 0x64}));
  EXPECT_EQ(song.messages[2], (MidiMessage{750000, 0x90, 0x40, 0x00}));
  EXPECT_EQ(song.length_us, 750000u);
  EXPECT_EQ(song.tracks, 2);
}

TEST(Midi, MusTicksAre140ASecond) {
  const MidiSong song = read_midi(mus_to_midi(mus({0x90, 0x3C, 0x81, 0x0C, 0x00, 0x3C, 0x60}), "D_T"), "D_T");
  ASSERT_EQ(song.messages.size(), 3u);  // all notes off, note on, note off
  EXPECT_EQ(song.messages[2].time_us, 1000000u);
  EXPECT_EQ(song.length_us, 1000000u);
}

TEST(Midi, BadFilesAreRefusedWithTheByte) {
  const auto message = [](const Bytes& bytes) -> std::string {
    try {
      read_midi(bytes, "D_BAD");
    } catch (const Error& e) {
      return e.what();
    }
    return "";
  };
  Bytes header_5 = midi({0x00, 0xFF, 0x2F, 0x00});
  header_5[7] = 5;
  Bytes format_3 = midi({0x00, 0xFF, 0x2F, 0x00});
  format_3[9] = 3;
  Bytes no_tracks = midi({0x00, 0xFF, 0x2F, 0x00});
  no_tracks[11] = 0;
  Bytes two_tracks = midi({0x00, 0xFF, 0x2F, 0x00});
  two_tracks[11] = 2;
  Bytes long_track = midi({0x00, 0xFF, 0x2F, 0x00});
  long_track[21] = 9;
  const std::vector<std::pair<Bytes, std::string>> cases = {
      {Bytes{'M', 'T', 'h', 'd'}, "D_BAD: byte 0: not a MIDI file"},
      {header_5, "D_BAD: byte 4: a header of 5 bytes"},
      {format_3, "D_BAD: byte 8: format 3"},
      {no_tracks, "D_BAD: byte 10: no tracks"},
      {two_tracks, "D_BAD: byte 26: the file ends after 1 of its 2 tracks"},
      {long_track, "D_BAD: byte 18: a chunk of 9 bytes runs past the file's end"},
      {midi({0x00, 0x3C, 0x40}), "D_BAD: byte 23: data byte 60 with no status"},
      {midi({0x00, 0x90, 0x3C, 0x80}), "D_BAD: byte 25: data byte 128 of a message"},
      {midi({0x00, 0x90, 0x3C}), "D_BAD: byte 25: the track ends before a message's data"},
      {midi({0x00, 0xF3, 0x01}), "D_BAD: byte 23: status 243 is no event"},
      {midi({0x00, 0xFF, 0x51, 0x02, 0x00, 0x00}), "D_BAD: byte 25: a tempo of 2 bytes"},
      {midi({0x00, 0xFF, 0x51, 0x03, 0x00, 0x00, 0x00}), "D_BAD: byte 26: a tempo of 0 microseconds"},
      {midi({0x00, 0xFF, 0x01, 0x05, 'a'}), "D_BAD: byte 26: a meta event of 5 bytes runs past the track's end"},
      {midi({0x80, 0x80, 0x80, 0x80, 0x00}), "D_BAD: byte 22: an event's delay longer than 4 bytes"},
      {midi({0xFF, 0xFF, 0xFF, 0x7F, 0x90, 0x3C, 0x40, 0xFF, 0xFF, 0xFF, 0x7F, 0x90, 0x3C, 0x40}), "D_BAD: longer than 24 hours"},
  };
  for (const auto& [bytes, expected] : cases) {
    const std::string m = message(bytes);
    EXPECT_EQ(m.substr(0, expected.size()), expected) << m;
  }
  // A track with no end-of-track event ends where its chunk does.
  EXPECT_EQ(read_midi(midi({0x00, 0x90, 0x3C, 0x40, 0x81, 0x0C, 0x80, 0x3C, 0x00}), "D_OK").length_us, 1000000u);
}

}  // namespace
}  // namespace p3d::wad
