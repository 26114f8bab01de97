// Doom's arithmetic: 16.16 fixed point, the trigonometry tables and binary angles,
// and the random table. The tables are Doom's numbers, not a formula's: the tests
// bound them against the standard library and check the values Doom's sources and
// documentation name.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "engine/play/angle.h"
#include "engine/play/fixed.h"
#include "engine/play/random.h"
#include "engine/util/rng.h"

namespace p3d::play {
namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;

TEST(Fixed, MultipliesAndDividesAsSixteenSixteen) {
  Rng rng(7);
  for (int i = 0; i < 10000; ++i) {
    // Up to 256 by 64 units: products within 16.16 range.
    const Fixed a = Fixed(rng.next() % (1u << 25)) - (1 << 24), b = Fixed(rng.next() % (1u << 23)) - (1 << 22);
    const double product = to_double(a) * to_double(b);
    EXPECT_LE(std::abs(to_double(fixed_mul(a, b)) - product), 1.0 / kFracUnit) << a << " * " << b;
    EXPECT_LE(to_double(fixed_mul(a, b)), product) << "the product rounds down, as an arithmetic shift does";
    if (b == 0 || std::abs(double(a)) / 16384 >= std::abs(double(b))) continue;
    EXPECT_LE(std::abs(to_double(fixed_div(a, b)) - to_double(a) / to_double(b)), 1.0 / kFracUnit) << a << " / " << b;
  }
  EXPECT_EQ(fixed_mul(to_fixed(3), kFracUnit / 2), to_fixed(3) / 2);
  EXPECT_EQ(fixed_div(to_fixed(1), to_fixed(4)), kFracUnit / 4);
  // Doom's overflow test saturates: to the largest value of the quotient's sign.
  EXPECT_EQ(fixed_div(to_fixed(20000), 3), std::numeric_limits<Fixed>::max());
  EXPECT_EQ(fixed_div(to_fixed(-20000), 3), std::numeric_limits<Fixed>::min());
  EXPECT_EQ(fixed_div(5, 0), std::numeric_limits<Fixed>::max());
  EXPECT_EQ(wrap_add(std::numeric_limits<Fixed>::max(), 1), std::numeric_limits<Fixed>::min()) << "sums wrap";
}

TEST(Fixed, ApproximateDistanceIsTheLongerLegPlusHalfTheShorter) {
  EXPECT_EQ(approx_distance(to_fixed(3), to_fixed(-4)), to_fixed(4) + to_fixed(3) - to_fixed(3) / 2);
  EXPECT_EQ(approx_distance(to_fixed(-10), 0), to_fixed(10));
  Rng rng(3);
  for (int i = 0; i < 1000; ++i) {
    const Fixed dx = Fixed(rng.next() % (1u << 28)) - (1 << 27), dy = Fixed(rng.next() % (1u << 28)) - (1 << 27);
    const double exact = std::hypot(double(dx), double(dy));
    EXPECT_GE(approx_distance(dx, dy), exact * 0.99);  // never much shorter,
    EXPECT_LE(approx_distance(dx, dy), exact * 1.12);  // at most 12% longer
  }
}

TEST(Tables, SineAndCosineAreSinesOfTheFineAnglesCentres) {
  for (int i = 0; i < kFineAngles * 5 / 4; ++i) {
    const double exact = std::sin((i + 0.5) * kTwoPi / kFineAngles) * kFracUnit;
    EXPECT_LE(std::abs(kFineSine[i] - exact), 1.01) << i;  // truncated, from single precision
  }
  for (int i = 0; i < kFineAngles; ++i) EXPECT_EQ(fine_cosine(i), kFineSine[i + kFineAngles / 4]);
  EXPECT_EQ(kFineSine[0], 25);  // Doom's first entries
  EXPECT_EQ(kFineSine[1], 75);
  EXPECT_EQ(sine(kAngle90), 65535) << "the sine of 90 degrees falls short of one";
  EXPECT_EQ(cosine(0), 65535);
  EXPECT_EQ(sine(kAngle270), -65535);
}

TEST(Tables, TangentAndTheSlopeToAngleTable) {
  for (int i = 0; i < kFineAngles / 2; ++i) {
    const double exact = std::tan((i - kFineAngles / 4 + 0.5) * std::numbers::pi / (kFineAngles / 2)) * kFracUnit;
    EXPECT_LE(std::abs(kFineTangent[i] - exact), std::max(2.0, std::abs(exact) * 2e-4)) << i;
  }
  EXPECT_EQ(kFineTangent[0], -170910304);
  EXPECT_EQ(kFineTangent[2048], 25);
  for (int i = 0; i <= kSlopeRange; ++i) {
    const double exact = std::atan(double(i) / kSlopeRange) / kTwoPi * 4294967296.0;
    EXPECT_LE(std::abs(double(kTanToAngle[i]) - exact), 32.0) << i;  // single precision: 2^29 * 2^-24
    if (i) {
      EXPECT_GT(kTanToAngle[i], kTanToAngle[i - 1]);
    }
  }
  EXPECT_EQ(kTanToAngle[0], 0u);
  EXPECT_EQ(kTanToAngle[kSlopeRange], kAngle45);
}

TEST(Angles, VectorAngleFollowsAtanWithinOneSlopeStep) {
  Rng rng(11);
  for (int i = 0; i < 20000; ++i) {
    const Fixed dx = Fixed(rng.next() % (1u << 30)) - (1 << 29), dy = Fixed(rng.next() % (1u << 30)) - (1 << 29);
    if (std::abs(dx) < kFracUnit && std::abs(dy) < kFracUnit) continue;  // Doom's slopes need a unit or more
    double exact = std::atan2(double(dy), double(dx)) / kTwoPi * 4294967296.0;
    if (exact < 0) exact += 4294967296.0;
    double error = std::abs(double(vector_angle(dx, dy)) - exact);
    error = std::min(error, 4294967296.0 - error);  // across 0
    EXPECT_LE(error / 4294967296.0 * 360, 0.03) << dx << ", " << dy;
  }
  EXPECT_EQ(vector_angle(0, 0), 0u);
  EXPECT_EQ(vector_angle(kFracUnit, 0), 0u);
  EXPECT_EQ(vector_angle(0, kFracUnit), kAngle90 - 1) << "Doom's octant 1 is one short";
  EXPECT_EQ(vector_angle(-kFracUnit, 0), kAngle180 - 1);
  EXPECT_EQ(vector_angle(kFracUnit, kFracUnit), kAngle90 - 1 - kAngle45) << "the diagonal falls in octant 1";
  EXPECT_EQ(point_to_angle(to_fixed(10), to_fixed(10), to_fixed(10), to_fixed(5)), kAngle270);
  // The most negative x negates to itself, as in Doom, whose signed comparison then
  // puts it in octant 2 with a saturated slope: 135 degrees (without UB here).
  EXPECT_EQ(vector_angle(std::numeric_limits<Fixed>::min(), 0), kAngle90 + kAngle45);
}

TEST(Random, PlayStreamReadsTheTableInOrderAndRepeatsEvery256) {
  Random r;
  EXPECT_EQ(kRandomTable[0], 0);
  EXPECT_EQ(r.play(), 8) << "Doom's first number after a clear: the table's second entry";
  EXPECT_EQ(r.play(), 109);
  EXPECT_EQ(r.play(), 220);
  r.clear();
  std::vector<int> first;
  for (int i = 0; i < 256; ++i) first.push_back(r.play());
  for (int i = 0; i < 256; ++i) EXPECT_EQ(r.play(), first[i]);
  int sum = 0, zeros = 0;
  for (int v : first) sum += v, zeros += v == 0;
  EXPECT_NEAR(sum / 256.0, 127.5, 2) << "uniform on average";
  EXPECT_EQ(zeros, 2) << "0 appears twice in Doom's table";
}

TEST(Random, StreamsAreIndependentAndTheDifferenceCallsLeftFirst) {
  Random a, b;
  for (int i = 0; i < 10; ++i) a.other();  // menus and sounds draw from their own stream
  for (int i = 0; i < 100; ++i) ASSERT_EQ(a.play(), b.play());
  a.clear();
  const int left = kRandomTable[1], right = kRandomTable[2];
  EXPECT_EQ(a.play_difference(), left - right);
  EXPECT_EQ(a.play_index(), 2);
}

}  // namespace
}  // namespace p3d::play
