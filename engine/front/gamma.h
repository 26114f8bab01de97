// Doom's gamma correction (F11 and the gamma setting): five levels, each a table
// from a palette channel's value to the one shown, applied to the whole screen as
// Doom applies it to its palette.
#pragma once

#include <cstdint>
#include <span>

namespace p3d::front {

constexpr int kGammaLevels = 5;

// The channel value shown at this level (0..4).
uint8_t gamma_channel(int level, uint8_t value);
// Every pixel's red, green and blue through the level's table. Level 0 leaves them
// as they are: its table differs from the identity only by one step in the darkest
// half, which Doom shows and a PNG of the frame should not.
void apply_gamma(int level, std::span<uint32_t> pixels);

}  // namespace p3d::front
