#include "game/sound_bank.h"

#include <cstdio>

#include "engine/bsp/load.h"

namespace p3d::game {

const play::SoundClip* SoundBank::clip(play::Sound sound) {
  if (wads_.empty()) return nullptr;
  if (const auto it = clips_.find(sound); it != clips_.end()) return it->second ? &*it->second : nullptr;
  std::optional<play::SoundClip>& clip = clips_[sound];
  const std::string lump_name = play::sound_lump_name(sound);
  try {
    if (!stack_) stack_ = std::make_unique<wad::Stack>(bsp::read_wads(wads_));
    if (const wad::Lump* lump = stack_->find(lump_name))
      clip = play::decode_dmx(lump->bytes, wads_.back().filename().string() + ": " + lump_name);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "pseudo3d: %s (not played)\n", e.what());
  }
  return clip ? &*clip : nullptr;
}

}  // namespace p3d::game
