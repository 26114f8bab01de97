// Reading a standard MIDI file: the header chunk, then each track's events (a delay
// in ticks, a status byte or the last one again, its data) with absolute ticks; the
// tracks merged in tick order and the ticks turned into microseconds through the
// tempo changes met on the way.
#include "engine/wad/midi.h"

#include <algorithm>
#include <cstring>

#include "engine/util/error.h"

namespace p3d::wad {

namespace {

constexpr uint32_t kDefaultTempo = 500000;  // microseconds a quarter note (120 a minute)
constexpr size_t kChunkHeader = 8;
constexpr uint8_t kMeta = 0xFF, kSysEx = 0xF0, kSysExContinued = 0xF7;
constexpr uint8_t kEndOfTrack = 0x2F, kSetTempo = 0x51;

// An event of a track at its tick: a channel message, a tempo change or the track's end.
struct TrackEvent {
  enum Kind : uint8_t { kMessage, kTempo, kEnd };
  uint64_t tick = 0;
  Kind kind = kMessage;
  uint8_t status = 0, a = 0, b = 0;
  uint32_t tempo = 0;
};

class Reader {
 public:
  Reader(std::span<const uint8_t> bytes, const std::string& what) : bytes_(bytes), what_(what) {}
  size_t pos = 0;
  size_t end = 0;              // where the current chunk ends
  const char* part = "file";  // what ends there

  uint8_t u8(const char* field) {
    if (pos >= end) fail(pos, std::string("the ") + part + " ends before " + field);
    return bytes_[pos++];
  }
  uint8_t peek(const char* field) {
    const uint8_t b = u8(field);
    --pos;
    return b;
  }
  uint32_t be(int n, const char* field) {
    uint32_t v = 0;
    for (int i = 0; i < n; ++i) v = v << 8 | u8(field);
    return v;
  }
  // A variable-length number: 7 bits a byte, at most 4 bytes (28 bits).
  uint32_t vlq(const char* field) {
    const size_t at = pos;
    uint32_t v = 0;
    for (int i = 0; i < 4; ++i) {
      const uint8_t b = u8(field);
      v = v << 7 | (b & 0x7F);
      if (!(b & 0x80)) return v;
    }
    fail(at, std::string(field) + " longer than 4 bytes");
  }
  void skip(size_t n, const char* field) {
    if (n > end - pos) fail(pos, std::string(field) + " of " + std::to_string(n) + " bytes runs past the track's end");
    pos += n;
  }
  [[noreturn]] void fail(size_t at, const std::string& message) const {
    throw Error(what_ + ": byte " + std::to_string(at) + ": " + message);
  }
  size_t size() const { return bytes_.size(); }
  bool tag_is(size_t at, const char* tag) const { return std::memcmp(bytes_.data() + at, tag, 4) == 0; }

 private:
  std::span<const uint8_t> bytes_;
  const std::string& what_;
};

// One MTrk chunk's events, from `in.pos` to `in.end`, appended to `out`.
void read_track(Reader& in, std::vector<TrackEvent>& out) {
  uint64_t tick = 0;
  uint8_t running = 0;  // the last channel status (kept across meta and system exclusive events)
  while (in.pos < in.end) {
    tick += in.vlq("an event's delay");
    const size_t at = in.pos;
    uint8_t status = in.peek("an event");
    if (status & 0x80) {
      ++in.pos;
    } else {
      if (!running) in.fail(at, "data byte " + std::to_string(status) + " with no status before it");
      status = running;
    }
    if (status < 0xF0) {  // a channel message
      running = status;
      TrackEvent e{tick, TrackEvent::kMessage, status, 0, 0, 0};
      const int kind = status >> 4;
      const int data = kind == 0xC || kind == 0xD ? 1 : 2;
      for (int i = 0; i < data; ++i) {
        const size_t data_at = in.pos;
        const uint8_t d = in.u8("a message's data");
        if (d & 0x80) in.fail(data_at, "data byte " + std::to_string(d) + " of a message (0..127)");
        (i == 0 ? e.a : e.b) = d;
      }
      out.push_back(e);
    } else if (status == kSysEx || status == kSysExContinued) {
      in.skip(in.vlq("a system exclusive message's length"), "a system exclusive message");
    } else if (status == kMeta) {
      const uint8_t type = in.u8("a meta event's type");
      const size_t length_at = in.pos;
      const uint32_t length = in.vlq("a meta event's length");
      if (type == kEndOfTrack) {
        out.push_back({tick, TrackEvent::kEnd, 0, 0, 0, 0});
        in.pos = in.end;  // anything after the end is not played
        return;
      }
      if (type == kSetTempo) {
        if (length != 3) in.fail(length_at, "a tempo of " + std::to_string(length) + " bytes (3)");
        const uint32_t tempo = in.be(3, "a tempo");
        if (tempo == 0) in.fail(length_at + 1, "a tempo of 0 microseconds a quarter note");
        out.push_back({tick, TrackEvent::kTempo, 0, 0, 0, tempo});
      } else {
        in.skip(length, "a meta event");
      }
    } else {
      in.fail(at, "status " + std::to_string(status) + " is no event of a MIDI file");
    }
  }
  out.push_back({tick, TrackEvent::kEnd, 0, 0, 0, 0});  // no end-of-track event: the chunk's end
}

// Ticks to microseconds: a tick lasts tempo / division microseconds (quarter-note
// ticks) or a fraction of a second (SMPTE frames). Sums are kept in microseconds times
// `division`, so no rounding piles up.
struct Clock {
  uint64_t division = 0;
  uint32_t tempo = kDefaultTempo;
  bool smpte = false;
  uint64_t segment_tick = 0, segment_scaled = 0;  // the last tempo change: its tick, its time x division

  uint64_t scaled(uint64_t tick) const {
    const uint64_t ticks = tick - segment_tick;
    if (ticks > (UINT64_MAX - segment_scaled) / tempo) return UINT64_MAX;
    return segment_scaled + ticks * tempo;
  }
  uint64_t time_us(uint64_t tick) const {
    const uint64_t s = scaled(tick);
    return s == UINT64_MAX ? UINT64_MAX : s / division;
  }
  void change_tempo(uint64_t tick, uint32_t new_tempo) {
    if (smpte) return;  // SMPTE time has no tempo
    segment_scaled = scaled(tick);
    segment_tick = tick;
    tempo = new_tempo;
  }
};

}  // namespace

MidiSong read_midi(std::span<const uint8_t> bytes, const std::string& what) {
  Reader in(bytes, what);
  in.end = bytes.size();
  // ---- the header chunk
  if (bytes.size() < kChunkHeader + 6 || !in.tag_is(0, "MThd"))
    in.fail(0, "not a MIDI file (no 14-byte \"MThd\" header)");
  in.pos = 4;
  const uint32_t header_length = in.be(4, "the header's length");
  if (header_length < 6 || header_length > bytes.size() - kChunkHeader)
    in.fail(4, "a header of " + std::to_string(header_length) + " bytes (6, in a file of " +
                   std::to_string(bytes.size()) + ")");
  const uint16_t format = uint16_t(in.be(2, "the format"));
  const uint16_t tracks = uint16_t(in.be(2, "the number of tracks"));
  const uint16_t division = uint16_t(in.be(2, "the division"));
  if (format > 2) in.fail(8, "format " + std::to_string(format) + " (0, 1 or 2)");
  if (tracks == 0) in.fail(10, "no tracks");
  Clock clock;
  if (division & 0x8000) {  // SMPTE: frames a second (negative), ticks a frame
    const int fps = -int(int8_t(division >> 8)), per_frame = division & 0xFF;
    if ((fps != 24 && fps != 25 && fps != 29 && fps != 30) || per_frame == 0)
      in.fail(12, "SMPTE division of " + std::to_string(fps) + " frames a second, " + std::to_string(per_frame) +
                      " ticks a frame");
    clock.smpte = true;
    // 29 stands for 30 drop-frame: 29.97 frames a second.
    clock.tempo = fps == 29 ? 100100 : 1000000;
    clock.division = uint64_t(fps == 29 ? 3 : fps) * uint64_t(per_frame);
  } else {
    if (division == 0) in.fail(12, "a division of 0 ticks a quarter note");
    clock.division = division;
  }
  in.pos = kChunkHeader + header_length;

  // ---- the tracks, each event at its tick
  std::vector<TrackEvent> events;
  int found = 0;
  while (found < tracks) {
    const size_t at = in.pos;
    if (bytes.size() - at < kChunkHeader)
      in.fail(at, "the file ends after " + std::to_string(found) + " of its " + std::to_string(tracks) + " tracks");
    const bool is_track = in.tag_is(at, "MTrk");
    in.pos += 4;
    const uint32_t length = in.be(4, "a chunk's length");
    if (length > bytes.size() - in.pos)
      in.fail(at + 4, "a chunk of " + std::to_string(length) + " bytes runs past the file's end (" +
                          std::to_string(bytes.size() - in.pos) + " bytes left)");
    if (!is_track) {  // not ours to read
      in.pos += length;
      continue;
    }
    in.end = in.pos + length;
    in.part = "track";
    read_track(in, events);
    in.end = bytes.size();
    in.part = "file";
    ++found;
  }

  // ---- merged in tick order, ticks made time
  std::stable_sort(events.begin(), events.end(),
                   [](const TrackEvent& x, const TrackEvent& y) { return x.tick < y.tick; });
  MidiSong song;
  song.tracks = tracks;
  for (const TrackEvent& e : events) {
    const uint64_t t = clock.time_us(e.tick);
    if (t > kLongestMidiSongUs)
      throw Error(what + ": longer than " + std::to_string(kLongestMidiSongUs / 3600000000) +
                  " hours (an event at tick " + std::to_string(e.tick) + ")");
    switch (e.kind) {
      case TrackEvent::kMessage: song.messages.push_back({t, e.status, e.a, e.b}); break;
      case TrackEvent::kTempo: clock.change_tempo(e.tick, e.tempo); break;
      case TrackEvent::kEnd: song.length_us = std::max(song.length_us, t); break;
    }
  }
  return song;
}

}  // namespace p3d::wad
