// Doom's binary angles (a full turn is 2^32) and its trigonometry tables: 8192
// fine angles for sine, cosine and tangent, and a slope-to-angle table for
// point_to_angle. The tables' numbers live in tables.cpp.
#pragma once

#include <cstdint>

#include "engine/play/fixed.h"

namespace p3d::play {

using Angle = uint32_t;
constexpr Angle kAngle45 = 0x20000000, kAngle90 = 0x40000000, kAngle180 = 0x80000000, kAngle270 = 0xc0000000;
constexpr Angle kAngle1 = kAngle45 / 45;

constexpr int kFineAngles = 8192;
constexpr int kFineMask = kFineAngles - 1;
constexpr int kAngleToFineShift = 19;  // a binary angle's top 13 bits are its fine angle
constexpr int kSlopeRange = 2048;
constexpr int kSlopeBits = 11;

extern const Fixed kFineSine[kFineAngles * 5 / 4];
extern const Fixed kFineTangent[kFineAngles / 2];
extern const Angle kTanToAngle[kSlopeRange + 1];

constexpr int fine(Angle a) { return int(a >> kAngleToFineShift); }
inline Fixed fine_sine(int fine_angle) { return kFineSine[fine_angle & kFineMask]; }
inline Fixed fine_cosine(int fine_angle) { return kFineSine[(fine_angle & kFineMask) + kFineAngles / 4]; }
inline Fixed sine(Angle a) { return kFineSine[fine(a)]; }
inline Fixed cosine(Angle a) { return kFineSine[fine(a) + kFineAngles / 4]; }

// Doom's slope of num over den as an index into kTanToAngle (SlopeDiv): 0..2048,
// where small denominators saturate.
constexpr int slope_index(uint32_t num, uint32_t den) {
  if (den < 512) return kSlopeRange;
  const uint32_t ans = (num << 3) / (den >> 8);
  return ans <= uint32_t(kSlopeRange) ? int(ans) : kSlopeRange;
}

// The angle of the vector (dx, dy), by octant and table, as Doom works it out
// (R_PointToAngle2 with its origin subtracted): 0 for a zero vector.
Angle vector_angle(Fixed dx, Fixed dy);
inline Angle point_to_angle(Fixed x1, Fixed y1, Fixed x2, Fixed y2) {
  return vector_angle(wrap_sub(x2, x1), wrap_sub(y2, y1));
}

}  // namespace p3d::play
