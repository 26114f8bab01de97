// Doom's 16.16 fixed-point numbers: the simulation's only arithmetic, so that a
// demo plays as Doom played it. Sums wrap as Doom's did on its 32-bit machines.
#pragma once

#include <cstdint>
#include <cstdlib>
#include <limits>

namespace p3d::play {

using Fixed = int32_t;
constexpr int kFracBits = 16;
constexpr Fixed kFracUnit = 1 << kFracBits;

constexpr Fixed to_fixed(int units) { return Fixed(uint32_t(units) << kFracBits); }
constexpr double to_double(Fixed f) { return f / double(kFracUnit); }

// Wrapping add and subtract: Doom's int arithmetic overflowed silently, and demos
// that cross the map's far edges depend on it.
constexpr Fixed wrap_add(Fixed a, Fixed b) { return Fixed(uint32_t(a) + uint32_t(b)); }
constexpr Fixed wrap_sub(Fixed a, Fixed b) { return Fixed(uint32_t(a) - uint32_t(b)); }

constexpr Fixed fixed_mul(Fixed a, Fixed b) { return Fixed((int64_t(a) * b) >> kFracBits); }

// a / b, saturating where the quotient would not fit (Doom's overflow test, kept
// exactly: it also saturates some quotients that would just fit).
constexpr Fixed fixed_div(Fixed a, Fixed b) {
  const int64_t abs_a = a < 0 ? -int64_t(a) : a, abs_b = b < 0 ? -int64_t(b) : b;
  if ((abs_a >> 14) >= abs_b)
    return (a ^ b) < 0 ? std::numeric_limits<Fixed>::min() : std::numeric_limits<Fixed>::max();
  return Fixed((int64_t(a) << kFracBits) / b);
}

// Doom's distance estimate (P_AproxDistance): the larger leg plus half the smaller.
constexpr Fixed approx_distance(Fixed dx, Fixed dy) {
  dx = dx < 0 ? wrap_sub(0, dx) : dx;
  dy = dy < 0 ? wrap_sub(0, dy) : dy;
  return dx < dy ? wrap_sub(wrap_add(dx, dy), dx >> 1) : wrap_sub(wrap_add(dx, dy), dy >> 1);
}

}  // namespace p3d::play
