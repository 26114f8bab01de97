// The inline floor, ceil and llround against the standard functions, to the bit: on
// halves and their neighbours (where rounding rules differ), around every power of
// two up to 2^62, and on random doubles of every magnitude in range.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "engine/util/rng.h"
#include "engine/util/rounding.h"

namespace p3d {
namespace {

void expect_as_standard(double v) {
  EXPECT_EQ(floor_to_int(v), static_cast<int64_t>(std::floor(v))) << v;
  EXPECT_EQ(ceil_to_int(v), static_cast<int64_t>(std::ceil(v))) << v;
  EXPECT_EQ(round_to_int(v), std::llround(v)) << v;
}

TEST(Rounding, GivesTheStandardFunctionsIntegers) {
  std::vector<double> values = {0.0, -0.0, 0.5, -0.5, 1.5, -1.5, 2.5, -2.5, 0.49999999999999994, -0.49999999999999994,
                                1e-300, -1e-300, 4503599627370495.5, -4503599627370495.5, 0x1p52, 0x1p53 + 2};
  for (int e = 0; e <= 62; ++e) {
    const double p = std::ldexp(1.0, e);
    for (const double v : {p, std::nextafter(p, 0.0), std::nextafter(p, INFINITY), p + 0.5, p - 0.5})
      if (v < 0x1p63) values.push_back(v), values.push_back(-v);
  }
  for (int i = -40; i <= 40; ++i)
    for (const double v : {i + 0.5, std::nextafter(i + 0.5, -INFINITY), std::nextafter(i + 0.5, INFINITY)}) values.push_back(v);
  Rng rng(11);
  for (int i = 0; i < 200000; ++i) {
    const double v = std::ldexp(rng.uniform(-1, 1), int(rng.below(63)));
    values.push_back(v);
  }
  for (const double v : values) expect_as_standard(v);
}

}  // namespace
}  // namespace p3d
