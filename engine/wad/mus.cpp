// MUS to MIDI. A MUS score is a header (id, score length and start, channel counts,
// the instruments used) and a stream of events in groups: each event a descriptor
// byte (last-in-group flag 0x80, event type 0x70, channel 0x0F) and its data, each
// group followed by a delay in 140 Hz ticks (7 bits a byte, high bit: more follows).
// The MIDI file is one track whose events are the score's, delays carried over.
#include "engine/wad/mus.h"

#include <algorithm>
#include <array>
#include <cstring>

#include "engine/util/error.h"
#include "engine/wad/midi.h"

namespace p3d::wad {

namespace {

constexpr size_t kMusHeaderSize = 16;
constexpr uint8_t kMusId[4] = {'M', 'U', 'S', 0x1A};

// A type-0 MIDI file of one track, 70 ticks a quarter note; the track's length
// (bytes 18..21, big-endian) is filled in at the end.
constexpr uint8_t kMidiHeader[] = {'M', 'T', 'h', 'd', 0, 0, 0, 6, 0, 0, 0, 1, 0, 0x46,
                                   'M', 'T', 'r', 'k', 0, 0, 0, 0};
constexpr size_t kTrackLengthAt = 18;

// MUS event types (descriptor bits 4..6).
enum : uint8_t {
  kReleaseKey = 0x00,
  kPressKey = 0x10,
  kPitchWheel = 0x20,
  kSystemEvent = 0x30,
  kController = 0x40,
  kScoreEnd = 0x60,
};
// MIDI channel messages.
enum : uint8_t {
  kMidiNoteOff = 0x80,
  kMidiNoteOn = 0x90,
  kMidiController = 0xB0,
  kMidiProgram = 0xC0,
  kMidiPitchBend = 0xE0,
};

// MUS controller numbers 1..14 as MIDI's (0 is the instrument: a program change):
// bank select, modulation, volume, pan, expression, reverb, chorus, sustain, soft
// pedal; then the valueless system events 10..14: all sounds off, all notes off,
// mono, poly, reset all controllers.
constexpr std::array<uint8_t, 15> kControllers = {0x00, 0x20, 0x01, 0x07, 0x0A, 0x0B, 0x5B, 0x5D,
                                                  0x40, 0x43, 0x78, 0x7B, 0x7E, 0x7F, 0x79};
constexpr int kFirstSystemEvent = 10, kLastSystemEvent = 14, kLastValuedController = 9;
constexpr uint8_t kAllNotesOff = 0x7B;

constexpr int kChannels = 16;
constexpr int kMusPercussion = 15, kMidiPercussion = 9;
constexpr uint32_t kLongestDelay = 0x0FFFFFFF;  // MIDI's variable-length numbers hold 28 bits
// MIDI's default tempo (microseconds a quarter note) and our ticks a quarter: 1/140 s a tick.
constexpr uint64_t kMidiTempo = 500000, kDivision = 70;

class MusReader {
 public:
  MusReader(std::span<const uint8_t> bytes, const std::string& what) : bytes_(bytes), what_(what) {}
  size_t position() const { return pos_; }
  void seek(size_t pos) { pos_ = pos; }
  uint8_t u8(const char* field) {
    if (pos_ >= bytes_.size()) fail(pos_, std::string("the lump ends before ") + field);
    return bytes_[pos_++];
  }
  uint16_t u16_at(size_t at) const { return uint16_t(bytes_[at] | bytes_[at + 1] << 8); }
  [[noreturn]] void fail(size_t at, const std::string& message) const {
    throw Error(what_ + ": byte " + std::to_string(at) + ": " + message);
  }

 private:
  std::span<const uint8_t> bytes_;
  const std::string& what_;
  size_t pos_ = 0;
};

// The MIDI track as mus2mid writes it: each event after the delay queued since the
// last one.
class TrackWriter {
 public:
  TrackWriter() : out_(std::begin(kMidiHeader), std::end(kMidiHeader)) {
    channels_.fill(-1);
    velocities_.fill(127);
  }

  void delay(uint32_t ticks) { queued_ += ticks; }

  // A MUS channel's MIDI channel, given on first use (which first silences it, as
  // Chocolate does against notes left hanging on it by an earlier song).
  uint8_t channel(int mus_channel) {
    if (mus_channel == kMusPercussion) return kMidiPercussion;
    if (channels_[size_t(mus_channel)] < 0) {
      int next = *std::max_element(channels_.begin(), channels_.end()) + 1;
      if (next == kMidiPercussion) ++next;
      channels_[size_t(mus_channel)] = next;
      event(uint8_t(kMidiController | next), kAllNotesOff, 0);
    }
    return uint8_t(channels_[size_t(mus_channel)]);
  }
  uint8_t& velocity(uint8_t midi_channel) { return velocities_[midi_channel]; }

  void event(uint8_t status, uint8_t a) {
    write_delay();
    out_.insert(out_.end(), {status, a});
  }
  void event(uint8_t status, uint8_t a, uint8_t b) {
    write_delay();
    out_.insert(out_.end(), {status, a, b});
  }

  std::vector<uint8_t> finish() {
    write_delay();
    out_.insert(out_.end(), {0xFF, 0x2F, 0x00});  // end of track
    const uint32_t length = uint32_t(out_.size() - sizeof kMidiHeader);
    for (int i = 0; i < 4; ++i) out_[kTrackLengthAt + size_t(i)] = uint8_t(length >> (24 - 8 * i));
    return std::move(out_);
  }

 private:
  // The queued delay, 7 bits a byte, most significant first (all but the last byte
  // flagged 0x80).
  void write_delay() {
    uint8_t groups[4];
    int n = 0;
    uint32_t t = queued_;
    do {
      groups[n++] = uint8_t(t & 0x7F);
      t >>= 7;
    } while (t != 0);
    while (n-- > 0) out_.push_back(uint8_t(groups[n] | (n > 0 ? 0x80 : 0)));
    queued_ = 0;
  }

  std::vector<uint8_t> out_;
  uint32_t queued_ = 0;
  std::array<int, kChannels> channels_;
  std::array<uint8_t, kChannels> velocities_;
};

// The header's fields that mus2mid ignores, checked against the score.
void check_header(const MusReader& in, size_t size, size_t score_start, std::vector<std::string>* warnings) {
  if (!warnings) return;
  const auto warn = [&](size_t at, const std::string& message) {
    warnings->push_back("byte " + std::to_string(at) + ": " + message);
  };
  const uint16_t score_length = in.u16_at(4), primary = in.u16_at(8), secondary = in.u16_at(10),
                 instruments = in.u16_at(12);
  if (score_start + score_length > size)
    warn(4, "score length " + std::to_string(score_length) + " runs past the lump's end (" + std::to_string(size) +
                " bytes): the score is read to its end event");
  if (primary + secondary > kChannels)
    warn(8, std::to_string(primary) + " primary and " + std::to_string(secondary) +
                " secondary channels: more than 16");
  if (kMusHeaderSize + 2 * size_t(instruments) > score_start)
    warn(12, "the list of " + std::to_string(instruments) + " instruments runs into the score at byte " +
                 std::to_string(score_start));
}

}  // namespace

bool is_mus(std::span<const uint8_t> lump) {
  return lump.size() >= 4 && std::memcmp(lump.data(), kMusId, 4) == 0;
}

bool is_midi(std::span<const uint8_t> lump) { return lump.size() >= 4 && std::memcmp(lump.data(), "MThd", 4) == 0; }

std::vector<uint8_t> mus_to_midi(std::span<const uint8_t> mus, const std::string& what,
                                 std::vector<std::string>* warnings) {
  MusReader in(mus, what);
  // ---- the header
  if (mus.size() < kMusHeaderSize)
    in.fail(mus.size(), "the lump ends inside the 16-byte MUS header (" + std::to_string(mus.size()) + " bytes)");
  if (!is_mus(mus)) in.fail(0, "not a MUS score (no \"MUS\\x1A\" at its start)");
  const size_t score_start = in.u16_at(6);
  if (score_start < kMusHeaderSize)
    in.fail(6, "score start " + std::to_string(score_start) + " lies inside the 16-byte header");
  if (score_start >= mus.size())
    in.fail(6, "score start " + std::to_string(score_start) + " is past the lump's end (" +
                   std::to_string(mus.size()) + " bytes)");
  check_header(in, mus.size(), score_start, warnings);

  // ---- the score, group by group until its end
  TrackWriter track;
  uint64_t score_ticks = 0;
  in.seek(score_start);
  for (;;) {
    const size_t at = in.position();
    const uint8_t descriptor = in.u8("an event");
    // The channel is opened before the event is read, whatever the event (the score's
    // end included), as mus2mid does.
    const uint8_t channel = track.channel(descriptor & 0x0F);
    switch (descriptor & 0x70) {
      case kReleaseKey: {
        const uint8_t key = in.u8("a released key");
        track.event(kMidiNoteOff | channel, key & 0x7F, 0);
        break;
      }
      case kPressKey: {
        const uint8_t key = in.u8("a pressed key");
        if (key & 0x80) track.velocity(channel) = in.u8("a key's velocity") & 0x7F;  // else the channel's last
        track.event(kMidiNoteOn | channel, key & 0x7F, track.velocity(channel));
        break;
      }
      case kPitchWheel: {
        const int bend = in.u8("a pitch wheel's value") * 64;  // 0..255 to MIDI's 14 bits, 128 the centre
        track.event(kMidiPitchBend | channel, uint8_t(bend & 0x7F), uint8_t((bend >> 7) & 0x7F));
        break;
      }
      case kSystemEvent: {
        const size_t number_at = in.position();
        const uint8_t number = in.u8("a system event's number");
        if (number < kFirstSystemEvent || number > kLastSystemEvent)
          in.fail(number_at, "unknown system event " + std::to_string(number) + " (10..14)");
        track.event(kMidiController | channel, kControllers[number], 0);
        break;
      }
      case kController: {
        const size_t number_at = in.position();
        const uint8_t number = in.u8("a controller's number");
        const uint8_t value = in.u8("a controller's value");
        if (number == 0) {
          track.event(kMidiProgram | channel, value & 0x7F);
        } else {
          if (number > kLastValuedController)
            in.fail(number_at, "unknown controller " + std::to_string(number) + " (0..9)");
          // Values are 7 bits, yet some scores hold larger ones: mus2mid writes 127.
          track.event(kMidiController | channel, kControllers[number], value & 0x80 ? 0x7F : value);
        }
        break;
      }
      case kScoreEnd:
        return track.finish();
      default:
        in.fail(at, "unknown event type " + std::to_string((descriptor >> 4) & 7) + " (descriptor 0x" +
                        "0123456789ABCDEF"[descriptor >> 4] + "0123456789ABCDEF"[descriptor & 15] + ")");
    }
    if (descriptor & 0x80) {  // the group's last event: its delay follows
      const size_t delay_at = in.position();
      uint32_t delay = 0;
      uint8_t byte = 0;
      do {
        byte = in.u8("a delay");
        if (delay > kLongestDelay >> 7)  // another 7 bits would not fit in 28
          in.fail(delay_at, "a delay longer than MIDI can write (" + std::to_string(kLongestDelay) + " ticks)");
        delay = delay * 128 + (byte & 0x7F);
      } while (byte & 0x80);
      track.delay(delay);
      score_ticks += delay;
      if (score_ticks * kMidiTempo / kDivision > kLongestMidiSongUs)
        in.fail(delay_at, "the score runs longer than " + std::to_string(kLongestMidiSongUs / 3600000000) + " hours");
    }
  }
}

std::vector<uint8_t> music_to_midi(std::span<const uint8_t> lump, const std::string& what,
                                   std::vector<std::string>* warnings) {
  if (is_midi(lump)) return {lump.begin(), lump.end()};
  if (is_mus(lump)) return mus_to_midi(lump, what, warnings);
  throw Error(what + ": neither a MUS score nor a MIDI file (" + std::to_string(lump.size()) + " bytes)");
}

}  // namespace p3d::wad
