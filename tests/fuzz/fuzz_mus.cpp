// A music lump's bytes (MUS or MIDI): converted to a MIDI file and read into timed
// messages, and read as a MIDI file as it is. What the converter writes is always a
// MIDI file the reader accepts, with the score's notes: a broken promise traps.
#include "engine/util/error.h"
#include "tests/fuzz/target.h"
#include "engine/wad/midi.h"
#include "engine/wad/mus.h"
#include "tests/fuzz/harness.h"

using namespace p3d;

P3D_FUZZ_TARGET(mus) {
  const std::span<const uint8_t> lump(data, size);
  if (wad::is_mus(lump)) {
    std::vector<uint8_t> midi;
    try {
      std::vector<std::string> warnings;
      midi = wad::mus_to_midi(lump, "D_FUZZ", &warnings);
    } catch (const Error&) {
      return 0;
    }
    try {
      const wad::MidiSong song = wad::read_midi(midi, "D_FUZZ");
      if (song.tracks != 1 || (!song.messages.empty() && song.messages.back().time_us > song.length_us)) __builtin_trap();
    } catch (const Error&) {
      __builtin_trap();  // the converter wrote what the reader refuses
    }
    return 0;
  }
  try {
    const wad::MidiSong song = wad::read_midi(lump, "D_FUZZ");
    for (size_t i = 1; i < song.messages.size(); ++i)
      if (song.messages[i].time_us < song.messages[i - 1].time_us) __builtin_trap();  // in time order
  } catch (const Error&) {
  }
  return 0;
}
