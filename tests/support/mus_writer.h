// Writing MUS scores in tests: a MIDI song re-scored as MUS (what DMX's tools did to
// Doom's music), and seeded random scores that use every event and quirk of the format.
// Freedoom's music lumps are all MIDI files already, so these are what mus_to_midi is
// held against Chocolate's mus2mid with (tests/golden/music.hashes).
#pragma once

#include <cstdint>
#include <vector>

#include "engine/wad/midi.h"

namespace p3d::test {

// A MUS score of the song's channel messages at 140 ticks a second: MIDI's
// percussion channel 9 as MUS channel 15, the others in order; notes, programs,
// pitch bends, the controllers MUS has (the rest, and key and channel pressure, are
// dropped); a velocity written only when it changes.
std::vector<uint8_t> midi_to_mus(const wad::MidiSong& song);

// A score of `groups` random groups of events: every event type, channel and value
// range (velocity flags, controller values over 127, long delays, delays written with
// leading zero groups), ending on a random channel, sometimes followed by padding.
std::vector<uint8_t> random_mus(uint64_t seed, int groups);

}  // namespace p3d::test
