#include "game/sound_mixer.h"

#include <algorithm>
#include <cmath>

namespace p3d::game {

namespace {
play::Fixed to_fixed(double units) { return play::Fixed(std::llround(units * play::kFracUnit)); }
}  // namespace

play::Listener listener_at(geom::Vec2 pos, double angle_degrees) {
  const double turns = angle_degrees / 360 - std::floor(angle_degrees / 360);
  return {to_fixed(pos.x), to_fixed(pos.y), play::Angle(uint64_t(std::llround(turns * 4294967296.0)) & 0xffffffffu)};
}

// Doom's panning through SDL_mixer, as Chocolate Doom sets it: separation 0..254
// shares the volume between the ears.
void SoundMixer::set_gains(Voice& v, const play::Heard& h) {
  v.left = std::clamp((254 - h.separation) * h.volume / 127, 0, 255);
  v.right = std::clamp(h.separation * h.volume / 127, 0, 255);
}

std::optional<play::Heard> SoundMixer::place(const Voice& v, const play::Listener& listener) const {
  if (!v.at) return play::Heard{v.volume, play::kCentre};
  const play::Fixed x = to_fixed(v.at->x), y = to_fixed(v.at->y);
  std::optional<play::Heard> h = play::hear(listener, x, y, v.volume);
  if (h && x == listener.x && y == listener.y) h->separation = play::kCentre;
  return h;
}

bool SoundMixer::start(play::Sound sound, uint64_t origin, std::optional<geom::Vec2> at,
                       const play::Listener& listener) {
  const play::SoundInfo& info = play::kSounds[size_t(sound)];
  const int volume = play::linked_volume(sound, volume_);
  if (volume < 1) return false;
  const play::SoundClip* clip = clips_(info.link != play::Sound::kNone ? info.link : sound);
  if (!clip || clip->samples.empty()) return false;
  Voice v{clip, 0, (uint64_t(clip->rate) << 32) / uint64_t(rate_), at, volume, 0, 0};
  const std::optional<play::Heard> heard = place(v, listener);
  if (!heard) return false;
  for (int c = 0; c < play::Channels::kCount; ++c)  // the origin's old sound stops, even if this one finds no channel
    if (channels_[c].busy() && channels_[c].origin == origin) channels_.stop(c), voices_[size_t(c)] = {};
  const int channel = channels_.start(sound, origin);
  if (channel < 0) return false;
  set_gains(v, *heard);
  voices_[size_t(channel)] = v;
  return true;
}

void SoundMixer::update(const play::Listener& listener, const Whereabouts& where) {
  for (int c = 0; c < play::Channels::kCount; ++c) {
    Voice& v = voices_[size_t(c)];
    if (!channels_[c].busy()) continue;
    if (where && v.at && channels_[c].origin != play::Channels::kNoOrigin) {
      const std::optional<geom::Vec2> now = where(channels_[c].origin);
      if (!now) {  // its thing is gone
        channels_.stop(c);
        v = {};
        continue;
      }
      v.at = now;
    }
    const std::optional<play::Heard> heard = v.clip && (v.position >> 32) < v.clip->samples.size()
                                                 ? place(v, listener)
                                                 : std::nullopt;
    if (!heard) {
      channels_.stop(c);
      v = {};
      continue;
    }
    set_gains(v, *heard);
  }
}

void SoundMixer::mix(std::span<int16_t> stereo) {
  std::fill(stereo.begin(), stereo.end(), int16_t(0));
  for (Voice& v : voices_) {
    if (!v.clip) continue;
    const std::vector<uint8_t>& samples = v.clip->samples;
    for (size_t i = 0; i + 1 < stereo.size(); i += 2) {
      const size_t at = size_t(v.position >> 32);
      if (at >= samples.size()) break;
      // An 8-bit sample centred on 0, at a quarter of full scale per channel; sums
      // of several loud channels are clamped, as SDL_mixer clamps them.
      const int s = (int(samples[at]) - 128) * 64;
      stereo[i] = int16_t(std::clamp(stereo[i] + s * v.left / 255, -32768, 32767));
      stereo[i + 1] = int16_t(std::clamp(stereo[i + 1] + s * v.right / 255, -32768, 32767));
      v.position += v.step;
    }
  }
}

int SoundMixer::playing() const {
  int n = 0;
  for (int c = 0; c < play::Channels::kCount; ++c) n += channels_[c].busy();
  return n;
}

}  // namespace p3d::game
