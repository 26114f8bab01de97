// Doom's player colours (r_draw.c's R_InitTranslationTables): a sprite of player 2, 3
// or 4 shows the green ramp (palette 0x70..0x7f) as gray, brown or red. The renderers
// draw such a sprite from a translated copy of its picture, made once per level.
#pragma once

#include <cstddef>
#include <cstdint>

#include "engine/level/level.h"

namespace p3d::render {

constexpr int kTranslations = 3;  // gray, brown, red (0: none)

// Palette index i as translation t (1..3) shows it.
constexpr uint8_t translate_index(uint8_t i, int t) {
  constexpr uint8_t kRamps[kTranslations] = {0x60, 0x40, 0x20};
  return (t >= 1 && t <= kTranslations && i >= 0x70 && i <= 0x7f) ? uint8_t(kRamps[t - 1] + (i & 0xf)) : i;
}

// The level's texture `texture` in translation t (1..3): the texture itself on a level
// without a palette. Thread-safe; the copy lives as long as the program.
const level::Texture& translated_texture(const level::Level& level, size_t texture, int t);

}  // namespace p3d::render
