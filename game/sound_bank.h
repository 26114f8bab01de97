// The sound effects of a WAD stack, decoded from their DMX lumps when first played
// and kept. A lump missing or broken is said once on stderr and stays silent.
#pragma once

#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <vector>

#include "engine/play/sound.h"
#include "engine/wad/wad.h"

namespace p3d::game {

class SoundBank {
 public:
  explicit SoundBank(std::vector<std::filesystem::path> wads) : wads_(std::move(wads)) {}
  // The sound's samples, or nullptr.
  const play::SoundClip* clip(play::Sound sound);

 private:
  std::vector<std::filesystem::path> wads_;
  std::unique_ptr<wad::Stack> stack_;  // read when a first sound is asked for
  std::map<play::Sound, std::optional<play::SoundClip>> clips_;
};

}  // namespace p3d::game
