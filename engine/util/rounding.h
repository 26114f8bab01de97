// floor, ceil and llround of doubles whose integer part fits in an int64, inline:
// x86-64's baseline has no rounding instruction (SSE4.1's roundsd), so std::floor and
// std::ceil become a sequence of compares and masks and std::llround a call into libm,
// in the renderer's per-column arithmetic. These are exact, the same integers as the
// standard functions give: truncation (cvttsd2si) is exact, and so is the fraction
// v - trunc(v), for every double below 2^63 in magnitude. NaN and larger magnitudes
// are the caller's to exclude.
#pragma once

#include <cstdint>

namespace p3d {

inline int64_t floor_to_int(double v) {
  const int64_t t = static_cast<int64_t>(v);
  return t - (static_cast<double>(t) > v);
}

inline int64_t ceil_to_int(double v) {
  const int64_t t = static_cast<int64_t>(v);
  return t + (static_cast<double>(t) < v);
}

// As std::llround: halves away from zero.
inline int64_t round_to_int(double v) {
  const int64_t t = static_cast<int64_t>(v);
  const double fraction = v - static_cast<double>(t);
  return t + (fraction >= 0.5) - (fraction <= -0.5);
}

}  // namespace p3d
