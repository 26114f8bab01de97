#include "engine/play/angle.h"

namespace p3d::play {

Angle vector_angle(Fixed dx, Fixed dy) {
  if (dx == 0 && dy == 0) return 0;
  // Work in the first quadrant with unsigned magnitudes (Doom negated in int and
  // relied on the wrap of -INT_MIN; unsigned gives the same bits without the UB).
  const bool x_neg = dx < 0, y_neg = dy < 0;
  const uint32_t x = x_neg ? 0u - uint32_t(dx) : uint32_t(dx);
  const uint32_t y = y_neg ? 0u - uint32_t(dy) : uint32_t(dy);
  // Doom compared the magnitudes as signed ints: keep that for -INT_MIN.
  const bool flat = int32_t(x) > int32_t(y);  // nearer the x axis than the y axis
  // The angle from the nearer axis, within 45 degrees.
  const Angle t = flat ? kTanToAngle[slope_index(y, x)] : kTanToAngle[slope_index(x, y)];
  if (!x_neg && !y_neg) return flat ? t : kAngle90 - 1 - t;
  if (!x_neg) return flat ? 0u - t : kAngle270 + t;
  if (!y_neg) return flat ? kAngle180 - 1 - t : kAngle90 + t;
  return flat ? kAngle180 + t : kAngle270 - 1 - t;
}

}  // namespace p3d::play
