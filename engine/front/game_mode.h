// Doom's game modes, as it tells them from the IWAD's maps (Chocolate Doom's
// D_IdentifyVersion): Doom II (MAPxx), the Ultimate Doom (a fourth episode),
// registered Doom (three), shareware (one). Menus, the title loop and the music
// follow the mode.
#pragma once

#include "engine/wad/wad.h"

namespace p3d::front {

enum class GameMode { kShareware, kRegistered, kRetail, kCommercial };

inline GameMode game_mode(const wad::Stack& wads) {
  if (wads.map("MAP01")) return GameMode::kCommercial;
  if (wads.map("E4M1")) return GameMode::kRetail;
  if (wads.map("E3M1")) return GameMode::kRegistered;
  return GameMode::kShareware;
}

}  // namespace p3d::front
