// Doom's eight sound channels mixed into stereo: the sounds a session starts are
// placed as Doom places them (play::hear), share the channels by Doom's priorities
// (play::Channels), follow the listener as it moves (Doom's S_UpdateSounds) and are
// mixed at the output rate. No SDL here: the window's audio device pulls samples.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>

#include "engine/geom/geom.h"
#include "engine/play/sound.h"

namespace p3d::game {

class SoundMixer {
 public:
  // clips: the decoded lump of a sound, or nullptr when it cannot be played.
  using Clips = std::function<const play::SoundClip*(play::Sound)>;
  SoundMixer(int output_rate, Clips clips) : rate_(output_rate), clips_(std::move(clips)) {}

  // A sound from `at` (map units), or from the listener itself (nullopt); origin
  // tells sound makers apart (each makes one sound at a time). False when it is not
  // heard (too far, no channel, no clip).
  bool start(play::Sound sound, uint64_t origin, std::optional<geom::Vec2> at, const play::Listener& listener);
  // Where a sound's maker is now: its place, or nullopt once it is gone (Doom stops the
  // sound of a thing removed).
  using Whereabouts = std::function<std::optional<geom::Vec2>(uint64_t origin)>;
  // Once a tic: sounds follow their makers (when `where` is given) and the listener,
  // and finished or distant ones stop (Doom's S_UpdateSounds).
  void update(const play::Listener& listener, const Whereabouts& where = {});
  // Adds the channels' next samples to `stereo` (interleaved left, right), which
  // it first clears.
  void mix(std::span<int16_t> stereo);

  // Doom's sound effects volume (snd_SfxVolume, 0..127: the menu's 0..15 times 8),
  // for the sounds started from now on.
  void set_volume(int volume) { volume_ = std::clamp(volume, 0, play::kMaxVolume); }

  int playing() const;  // busy channels
  const play::Channels& channels() const { return channels_; }

 private:
  struct Voice {
    const play::SoundClip* clip = nullptr;
    uint64_t position = 0, step = 0;  // in clip samples, 32.32 fixed
    std::optional<geom::Vec2> at;
    int volume = 0;            // before distance
    int left = 0, right = 0;   // gains 0..255
  };
  static void set_gains(Voice& v, const play::Heard& h);
  std::optional<play::Heard> place(const Voice& v, const play::Listener& listener) const;

  int rate_;
  int volume_ = play::kMaxVolume;
  Clips clips_;
  play::Channels channels_;
  std::array<Voice, play::Channels::kCount> voices_{};
};

// The listener at a player's place: map units and degrees to Doom's fixed point and angles.
play::Listener listener_at(geom::Vec2 pos, double angle_degrees);

}  // namespace p3d::game
