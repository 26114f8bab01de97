// Doom's music lumps (D_*): MUS, the DMX sound library's score format, converted to
// a standard MIDI file byte for byte as Chocolate Doom's mus2mid converts it; a lump
// that is already a MIDI file passes through. engine/wad/midi.h reads the result.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace p3d::wad {

// "MUS\x1A": a DMX score.
bool is_mus(std::span<const uint8_t> lump);
// "MThd": a standard MIDI file.
bool is_midi(std::span<const uint8_t> lump);

// A MUS score as a type-0 MIDI file at 70 ticks a quarter note (140 a second at the
// default tempo, the MUS clock), exactly as Chocolate's mus2mid writes it: MUS
// channel 15 on MIDI's percussion channel 9, the others on MIDI channels in order of
// first use (skipping 9), each opened with an "all notes off"; a note's velocity kept
// per channel. Throws Error("<what>: byte N: ...") for what mus2mid refuses (a
// truncated score, an unknown event or controller) and for a missing "MUS\x1A", a
// score start inside the 16-byte header, a delay longer than MIDI can write or a
// score longer than a day (engine/wad/midi.h's kLongestMidiSongUs). What mus2mid
// accepts but is not as DMX writes it (a score length or instrument list at odds with
// the score) is converted as mus2mid converts it, with a line in `warnings`.
// (Chocolate keeps the velocities in statics, carried from one song to the next
// in a session; here each conversion starts afresh, as a new process of Chocolate does.)
std::vector<uint8_t> mus_to_midi(std::span<const uint8_t> mus, const std::string& what,
                                 std::vector<std::string>* warnings = nullptr);

// A music lump as a MIDI file: MIDI as it is, MUS converted; Error for anything else.
std::vector<uint8_t> music_to_midi(std::span<const uint8_t> lump, const std::string& what,
                                   std::vector<std::string>* warnings = nullptr);

}  // namespace p3d::wad
