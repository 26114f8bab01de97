// Standard MIDI files (what a music lump becomes, engine/wad/mus.h) read into the
// channel messages a synthesizer plays, each at its time from the song's start: the
// tracks merged, running status expanded, tempo changes turned into time. Every byte
// is checked; nothing here plays or prints.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace p3d::wad {

// A channel message: note off/on, key pressure, controller, program, channel
// pressure or pitch bend (status 0x80..0xEF, the channel in its low 4 bits); data
// bytes 0..127, `b` 0 for the one-byte messages.
struct MidiMessage {
  uint64_t time_us = 0;  // microseconds from the start
  uint8_t status = 0, a = 0, b = 0;
  bool operator==(const MidiMessage&) const = default;
};

struct MidiSong {
  std::vector<MidiMessage> messages;  // in time order (ties: track order, then file order)
  uint64_t length_us = 0;             // when the last track ends (its end-of-track event, else its last event)
  int tracks = 0;
};

// The longest song read, a day: any song is far shorter, and times of a day keep every
// product of the arithmetic (ticks by tempo, microseconds by sample rate) in 64 bits.
constexpr uint64_t kLongestMidiSongUs = 24ull * 3600 * 1000000;

// Reads a format 0 or 1 MIDI file (format 2's sequences are played one over the
// other). Throws Error("<what>: byte N: ...") for a truncated or malformed file:
// a header other than MThd's 6 bytes, a track running past the file, an event with no
// status, a data byte of 128 or more, an unknown status, a meta event other than the
// tempo of the wrong length, a song longer than kLongestMidiSongUs. Chunks other than
// MTrk are skipped, as the standard says.
MidiSong read_midi(std::span<const uint8_t> bytes, const std::string& what);

}  // namespace p3d::wad
