#include "engine/play/sound.h"

#include <algorithm>
#include <cctype>

#include "engine/util/error.h"

namespace p3d::play {

namespace {
constexpr Fixed kClippingDistance = 1200 * kFracUnit;  // heard no farther
constexpr Fixed kCloseDistance = 200 * kFracUnit;      // heard at full volume nearer
constexpr int kAttenuator = (kClippingDistance - kCloseDistance) >> kFracBits;
constexpr Fixed kStereoSwing = 96 * kFracUnit;
constexpr size_t kDmxHeader = 8, kDmxPadding = 16;
constexpr uint32_t kDmxShortest = 48;
}  // namespace

SoundClip decode_dmx(std::span<const uint8_t> lump, const std::string& what) {
  if (lump.size() < kDmxHeader || lump[0] != 3 || lump[1] != 0)
    throw Error(what + ": not a Doom sound (DMX format 3)");
  const int rate = lump[2] | lump[3] << 8;
  const uint32_t length = uint32_t(lump[4]) | uint32_t(lump[5]) << 8 | uint32_t(lump[6]) << 16 | uint32_t(lump[7]) << 24;
  if (length > lump.size() - kDmxHeader)
    throw Error(what + ": " + std::to_string(length) + " samples do not fit in " + std::to_string(lump.size()) + " bytes");
  if (length <= kDmxShortest) throw Error(what + ": " + std::to_string(length) + " samples, too short to play");
  if (rate < 1000 || rate > 96000) throw Error(what + ": bad sample rate " + std::to_string(rate));
  SoundClip clip;
  clip.rate = rate;
  const auto first = lump.begin() + std::ptrdiff_t(kDmxHeader + kDmxPadding);
  clip.samples.assign(first, first + std::ptrdiff_t(length - 2 * kDmxPadding));
  return clip;
}

std::string sound_lump_name(Sound sound) {
  std::string name = "DS";
  for (const char* c = kSounds[size_t(sound)].name; *c; ++c) name += char(std::toupper(static_cast<unsigned char>(*c)));
  return name;
}

std::optional<Heard> hear(const Listener& listener, Fixed x, Fixed y, int volume, bool boss_level) {
  const Fixed adx = std::abs(wrap_sub(listener.x, x)), ady = std::abs(wrap_sub(listener.y, y));
  Fixed distance = adx + ady - (std::min(adx, ady) >> 1);
  if (!boss_level && distance > kClippingDistance) return std::nullopt;
  // The source's direction from the listener's facing, counter-clockwise (Doom
  // subtracts the facing with a quirk: off by one angle unit the other way round).
  Angle angle = point_to_angle(listener.x, listener.y, x, y);
  angle = angle > listener.angle ? angle - listener.angle : angle + (0xffffffffu - listener.angle);
  Heard h;
  h.separation = kCentre - (fixed_mul(kStereoSwing, kFineSine[fine(angle)]) >> kFracBits);
  if (distance < kCloseDistance) {
    h.volume = volume;
  } else if (boss_level) {
    distance = std::min(distance, kClippingDistance);
    h.volume = 15 + (volume - 15) * ((kClippingDistance - distance) >> kFracBits) / kAttenuator;
  } else {
    h.volume = volume * ((kClippingDistance - distance) >> kFracBits) / kAttenuator;
  }
  if (h.volume <= 0) return std::nullopt;
  return h;
}

int linked_volume(Sound sound, int volume) {
  const SoundInfo& s = kSounds[size_t(sound)];
  if (s.link == Sound::kNone) return volume;
  return std::clamp(volume + s.link_volume, 0, volume);
}

std::vector<geom::Vec2> sector_sound_origins(const level::Level& level) {
  std::vector<geom::BBox> boxes(level.sectors.size());
  for (const level::Wall& w : level.walls)
    for (const level::Side& side : w.sides)
      if (side.sector != level::kNone) {
        boxes[size_t(side.sector)].add(geom::to_world(w.p1));
        boxes[size_t(side.sector)].add(geom::to_world(w.p2));
      }
  std::vector<geom::Vec2> out;
  for (const geom::BBox& b : boxes) out.push_back(b.empty() ? geom::Vec2{0, 0} : (b.min + b.max) * 0.5);
  return out;
}

int Channels::start(Sound sound, uint64_t origin) {
  // An origin makes one sound at a time: its new one replaces the old (sounds from
  // nowhere in particular count as one origin, as Doom's S_StopSound(NULL) does).
  for (Channel& c : channels_)
    if (c.busy() && c.origin == origin) c = {};
  int chosen = -1;
  for (int i = 0; i < kCount && chosen < 0; ++i)
    if (!channels_[size_t(i)].busy()) chosen = i;
  for (int i = 0; i < kCount && chosen < 0; ++i)
    if (kSounds[size_t(channels_[size_t(i)].sound)].priority >= kSounds[size_t(sound)].priority) chosen = i;
  if (chosen >= 0) channels_[size_t(chosen)] = {sound, origin};
  return chosen;
}

}  // namespace p3d::play
