// Doom's sound effects without a sound card: the DMX lumps decoded, how loud and
// how far left or right a sound is heard from where the player stands (Doom's
// S_AdjustSoundParams), and Doom's eight channels shared by priority (S_GetChannel).
// The game's mixer (game/audio) plays what these decide; headless runs ignore them.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "engine/level/level.h"
#include "engine/play/angle.h"
#include "engine/play/info.h"

namespace p3d::play {

// A sound lump's samples: unsigned 8-bit mono at `rate` samples a second.
struct SoundClip {
  int rate = 11025;
  std::vector<uint8_t> samples;
};
// Doom's DMX format (u16 3, u16 rate, u32 length, then the samples, of which DMX skips
// the first and last 16). Throws Error("<what>: ...") for a lump that is not one, or
// one of 48 samples or fewer (which DMX does not play).
SoundClip decode_dmx(std::span<const uint8_t> lump, const std::string& what);
// The lump of a sound effect: "DS" and its name in upper case ("DSPISTOL").
std::string sound_lump_name(Sound sound);

constexpr int kMaxVolume = 127;   // Doom's sound effect volume at its loudest (15 on its menu's scale)
constexpr int kCentre = 128;      // separation straight ahead (0..255: lower is to the left)

struct Heard {
  int volume = kMaxVolume;  // 0..kMaxVolume
  int separation = kCentre;
};
struct Listener {
  Fixed x = 0, y = 0;
  Angle angle = 0;
};
// How a sound from (x, y) is heard: louder within 200 units, fading to nothing at
// 1200 (on a boss level, map 8, never below 15), panned by the direction it comes
// from. nullopt when it is too far to hear.
std::optional<Heard> hear(const Listener& listener, Fixed x, Fixed y, int volume = kMaxVolume, bool boss_level = false);
// The volume a linked sound plays at (kChgun's is kPistol's, changed by its link's
// volume); 0: not played.
int linked_volume(Sound sound, int volume = kMaxVolume);

// Where sounds of a sector come from: the middle of the box around its walls (Doom's
// sector sound origin), in map units; (0, 0) for a sector with no wall.
std::vector<geom::Vec2> sector_sound_origins(const level::Level& level);

// Doom's channels: a sound starts on a free channel, or in place of the sound its
// origin is already making, or else in place of one of lower or equal priority
// (Doom's priority numbers: a lower number matters more); else not at all.
class Channels {
 public:
  static constexpr int kCount = 8;
  static constexpr uint64_t kNoOrigin = 0;  // sounds from nowhere in particular (the player's pickups)
  struct Channel {
    Sound sound = Sound::kNone;
    uint64_t origin = kNoOrigin;
    bool busy() const { return sound != Sound::kNone; }
  };
  // The channel the sound goes to, or -1 if none will have it.
  int start(Sound sound, uint64_t origin);
  void stop(int channel) { channels_[size_t(channel)] = {}; }
  const Channel& operator[](int channel) const { return channels_[size_t(channel)]; }

 private:
  std::array<Channel, kCount> channels_{};
};

}  // namespace p3d::play
