#include "tests/support/mus_writer.h"

#include <algorithm>
#include <array>
#include <set>

#include "engine/util/rng.h"

namespace p3d::test {

namespace {

constexpr int kMusPercussion = 15;

// A delay as MUS writes it: 7 bits a byte, the most significant first. `padding`
// leading zero groups are legal and read as nothing.
void put_delay(std::vector<uint8_t>& out, uint32_t ticks, int padding = 0) {
  uint8_t groups[5];
  int n = 0;
  do {
    groups[n++] = uint8_t(ticks & 0x7F);
    ticks >>= 7;
  } while (ticks != 0);
  for (int i = 0; i < padding; ++i) out.push_back(0x80);
  while (n-- > 0) out.push_back(uint8_t(groups[n] | (n > 0 ? 0x80 : 0)));
}

std::vector<uint8_t> with_header(const std::vector<uint8_t>& score, int primary, const std::set<int>& instruments,
                                 int score_length = -1) {
  std::vector<uint8_t> out = {'M', 'U', 'S', 0x1A};
  const auto u16 = [&](int v) {
    out.push_back(uint8_t(v & 0xFF));
    out.push_back(uint8_t((v >> 8) & 0xFF));
  };
  u16(score_length >= 0 ? score_length : int(score.size()));
  u16(16 + 2 * int(instruments.size()));
  u16(primary);
  u16(0);
  u16(int(instruments.size()));
  u16(0);  // reserved
  for (int i : instruments) u16(i);
  out.insert(out.end(), score.begin(), score.end());
  return out;
}

// MIDI controllers as MUS numbers (0: none).
int mus_controller(int midi) {
  switch (midi) {
    case 0: return 1;     // bank select
    case 1: return 2;     // modulation
    case 7: return 3;     // volume
    case 10: return 4;    // pan
    case 11: return 5;    // expression
    case 91: return 6;    // reverb
    case 93: return 7;    // chorus
    case 64: return 8;    // sustain
    case 67: return 9;    // soft pedal
    case 120: return 10;  // all sounds off
    case 123: return 11;  // all notes off
    case 126: return 12;  // mono
    case 127: return 13;  // poly
    case 121: return 14;  // reset all controllers
    default: return 0;
  }
}

}  // namespace

std::vector<uint8_t> midi_to_mus(const wad::MidiSong& song) {
  struct Event {
    uint64_t tick;
    std::vector<uint8_t> bytes;  // descriptor (without the last-in-group flag) and data
  };
  std::vector<Event> events;
  std::array<int, 16> velocity;
  velocity.fill(-1);
  std::set<int> instruments, melodic;
  for (const wad::MidiMessage& m : song.messages) {
    const int midi_channel = m.status & 0x0F;
    const int channel = midi_channel == 9 ? kMusPercussion : midi_channel < 9 ? midi_channel : midi_channel - 1;
    const uint8_t c = uint8_t(channel);
    const uint64_t tick = m.time_us * 140 / 1000000;
    std::vector<uint8_t> bytes;
    switch (m.status >> 4) {
      case 0x8: bytes = {uint8_t(0x00 | c), m.a}; break;
      case 0x9:
        if (m.b == 0) {
          bytes = {uint8_t(0x00 | c), m.a};
        } else if (velocity[c] == m.b) {
          bytes = {uint8_t(0x10 | c), m.a};
        } else {
          bytes = {uint8_t(0x10 | c), uint8_t(m.a | 0x80), m.b};
          velocity[c] = m.b;
        }
        if (channel == kMusPercussion) instruments.insert(m.a + 100);
        break;
      case 0xB: {
        const int number = mus_controller(m.a);
        if (number >= 10) bytes = {uint8_t(0x30 | c), uint8_t(number)};
        else if (number > 0) bytes = {uint8_t(0x40 | c), uint8_t(number), m.b};
        break;
      }
      case 0xC:
        bytes = {uint8_t(0x40 | c), 0, m.a};
        if (channel != kMusPercussion) instruments.insert(m.a);
        break;
      case 0xE: bytes = {uint8_t(0x20 | c), uint8_t((m.b << 7 | m.a) >> 6)}; break;
      default: break;  // key and channel pressure: none in MUS
    }
    if (bytes.empty()) continue;
    if (channel != kMusPercussion) melodic.insert(channel);
    events.push_back({tick, std::move(bytes)});
  }
  std::vector<uint8_t> score;
  for (size_t i = 0; i < events.size(); ++i) {
    const bool last = i + 1 == events.size() || events[i + 1].tick != events[i].tick;
    score.push_back(uint8_t(events[i].bytes[0] | (last ? 0x80 : 0)));
    score.insert(score.end(), events[i].bytes.begin() + 1, events[i].bytes.end());
    if (last) {
      const uint64_t next =
          i + 1 < events.size() ? events[i + 1].tick : std::max(events[i].tick, song.length_us * 140 / 1000000);
      put_delay(score, uint32_t(next - events[i].tick));
    }
  }
  score.push_back(0x60);  // the score's end
  return with_header(score, int(melodic.size()), instruments);
}

std::vector<uint8_t> random_mus(uint64_t seed, int groups) {
  Rng rng(seed);
  std::vector<uint8_t> score;
  std::set<int> instruments;
  for (int g = 0; g < groups; ++g) {
    const int n = rng.range(1, 4);
    for (int e = 0; e < n; ++e) {
      const uint8_t flag = e + 1 == n ? 0x80 : 0;
      // Channels: mostly a few, sometimes any of the 16 (all of them get opened).
      const uint8_t c = uint8_t(rng.below(10) < 7 ? rng.range(0, 3) : rng.range(0, 15));
      switch (rng.below(6)) {
        case 0: score.insert(score.end(), {uint8_t(flag | 0x00 | c), uint8_t(rng.below(256))}); break;
        case 1: {
          const uint8_t key = uint8_t(rng.below(256));
          score.insert(score.end(), {uint8_t(flag | 0x10 | c), key});
          if (key & 0x80) score.push_back(uint8_t(rng.below(256)));  // velocities over 127 are masked
          break;
        }
        case 2: score.insert(score.end(), {uint8_t(flag | 0x20 | c), uint8_t(rng.below(256))}); break;
        case 3: score.insert(score.end(), {uint8_t(flag | 0x30 | c), uint8_t(rng.range(10, 14))}); break;
        default: {
          const uint8_t number = uint8_t(rng.range(0, 9)), value = uint8_t(rng.below(256));
          score.insert(score.end(), {uint8_t(flag | 0x40 | c), number, value});
          if (number == 0) instruments.insert(value & 0x7F);
        }
      }
    }
    // Delays: mostly short, some of two or three bytes, one of four (the score stays
    // within a day), some with leading zero groups.
    const uint64_t kind = rng.below(10);
    uint32_t ticks = uint32_t(kind < 6 ? rng.below(40) : kind < 9 ? rng.below(1u << 14) : rng.below(1u << 17));
    if (g == groups / 2) ticks = (1u << 21) + uint32_t(rng.below(1u << 21));
    put_delay(score, ticks, rng.below(8) == 0 ? rng.range(1, 2) : 0);
  }
  score.push_back(uint8_t(0x60 | rng.below(16)));  // on any channel: a new one is opened first
  const size_t length = score.size();
  if (rng.below(2)) score.insert(score.end(), size_t(rng.range(1, 8)), 0);  // padding after the end
  return with_header(score, 4, instruments, int(length));
}

}  // namespace p3d::test
