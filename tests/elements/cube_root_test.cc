// CubeRoot (cube_root.h) replaces libm's cbrt in every mean ratio. Checked here: it is within one
// unit in the last place of the exact root (decided in 113-bit arithmetic, independent of any
// cube-root code), exact where the root is a double, libm's answer outside its fast range, and the
// same bits for a double and for each lane of Lanes.

#include "getme/elements/cube_root.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

namespace getme::test {
namespace {

// The exact root of x lies strictly between the neighbours of `root` — |root − ∛x| < 1 ulp —
// exactly when prev(root)³ < x < next(root)³. The cubes of doubles carry 159 bits, so they are
// formed in __float128 (113 bits): its rounding is 2^-60 of the gap between a neighbour's cube
// and x, so the comparison is decided correctly.
bool WithinOneUlp(double x, double root) {
  const auto cube = [](double v) {
    const __float128 w = v;
    return w * w * w;
  };
  const double below = std::nextafter(root, -std::numeric_limits<double>::infinity());
  const double above = std::nextafter(root, std::numeric_limits<double>::infinity());
  const __float128 wide_x = x;
  return cube(below) < wide_x && wide_x < cube(above);
}

std::uint64_t RootBits(double value) { return std::bit_cast<std::uint64_t>(value); }

std::vector<double> Arguments() {
  std::mt19937_64 random(2026);
  std::uniform_real_distribution<double> mantissa(1.0, 2.0);
  std::uniform_int_distribution<int> exponent(-959, 1016);
  std::uniform_int_distribution<int> mesh_exponent(-120, 120);  // det² of elements of any size
  std::vector<double> arguments;
  for (int i = 0; i < 400000; ++i) {
    arguments.push_back(std::ldexp(mantissa(random), exponent(random)));
    arguments.push_back(std::ldexp(mantissa(random), mesh_exponent(random)));
  }
  // Both ends of every mantissa interval, for each exponent remainder mod 3.
  for (int e = -60; e <= 60; ++e) {
    arguments.push_back(std::ldexp(1.0, e));
    arguments.push_back(std::nextafter(std::ldexp(1.0, e), 0.0));
    arguments.push_back(std::nextafter(std::ldexp(1.0, e), 1e300));
  }
  // The fast range's own ends.
  arguments.push_back(std::ldexp(1.0, -959));
  arguments.push_back(std::nextafter(std::ldexp(1.0, 1017), 0.0));
  return arguments;
}

TEST(CubeRootTest, WithinOneUlpOfTheExactRoot) {
  int failures = 0;
  for (double x : Arguments()) {
    const double root = CubeRoot(x);
    if (!WithinOneUlp(x, root)) {
      if (++failures <= 5) ADD_FAILURE() << "CubeRoot(" << std::hexfloat << x << ") = " << root;
    }
  }
  EXPECT_EQ(failures, 0);
}

TEST(CubeRootTest, ExactWhereTheRootIsADouble) {
  for (int k = 1; k <= 2000; ++k) {
    const double root = k / 16.0;  // k³/4096 is exact in a double
    EXPECT_EQ(CubeRoot(root * root * root), root) << k;
  }
  for (int e = -300; e <= 300; ++e) {
    EXPECT_EQ(CubeRoot(std::ldexp(1.0, 3 * e)), std::ldexp(1.0, e)) << e;
  }
  // A regular tetrahedron's det(S) with the unit-edge target is 1: its mean ratio stays exactly 1.
  EXPECT_EQ(CubeRoot(1.0), 1.0);
}

TEST(CubeRootTest, LibmAnswersOutsideTheFastRange) {
  const double inf = std::numeric_limits<double>::infinity();
  const std::vector<double> outside = {0.0,
                                       -0.0,
                                       -8.0,
                                       -1e-3,
                                       std::numeric_limits<double>::denorm_min(),
                                       std::numeric_limits<double>::min(),
                                       std::ldexp(1.0, -960),
                                       std::ldexp(1.0, 1017),
                                       std::numeric_limits<double>::max(),
                                       inf,
                                       -inf};
  for (double x : outside) EXPECT_EQ(RootBits(CubeRoot(x)), RootBits(std::cbrt(x))) << x;
  EXPECT_TRUE(std::isnan(CubeRoot(std::numeric_limits<double>::quiet_NaN())));
}

TEST(CubeRootTest, EachLaneHasTheBitsOfTheScalarRoot) {
  std::vector<double> arguments = Arguments();
  arguments.resize(20000);
  // Lanes mixing the fast path with every kind of fallback argument.
  for (double special : {0.0, -27.0, 5e-324, 1e308, std::numeric_limits<double>::infinity(),
                         std::numeric_limits<double>::quiet_NaN()}) {
    arguments.push_back(special);
    arguments.push_back(0.3);
  }
  for (std::size_t i = 0; i + kLanes <= arguments.size(); i += kLanes) {
    Lanes x;
    for (int l = 0; l < kLanes; ++l) x[l] = arguments[i + l];
    const Lanes root = CubeRoot(x);
    for (int l = 0; l < kLanes; ++l) {
      EXPECT_EQ(RootBits(root[l]), RootBits(CubeRoot(x[l]))) << std::hexfloat << x[l];
    }
  }
}

// CubeRootAsRatio: the mean ratio's numerator / denominator form of the same Halley step.
// Relative error of the exact quotient numerator / denominator against ∛x, through its cube
// (3 × the root's relative error, to first order), all in 113-bit arithmetic.
double CubedRatioError(double x, const CubeRootRatio<double>& ratio) {
  const __float128 quotient = static_cast<__float128>(ratio.numerator) / ratio.denominator;
  const __float128 error = (quotient * quotient * quotient - x) / x;
  return static_cast<double>(error < 0 ? -error : error);
}

bool InRatioRange(double x) { return x >= std::ldexp(1.0, -300) && x < std::ldexp(1.0, 301); }

TEST(CubeRootAsRatioTest, TheFractionIsWithinAFewUlpsOfTheExactRoot) {
  // Rounding the numerator's two operations and the denominator's two, each within half an ulp
  // (2^-53): at most 4 · 2^-53 on the root to first order, 12 · 2^-53 on its cube.
  const double bound = 12.0 * std::ldexp(1.0, -53);
  int tested = 0;
  for (double x : Arguments()) {
    if (!InRatioRange(x)) continue;
    ++tested;
    const CubeRootRatio<double> ratio = CubeRootAsRatio(x);
    ASSERT_LE(CubedRatioError(x, ratio), bound) << std::hexfloat << x;
  }
  EXPECT_GT(tested, 400000);
}

TEST(CubeRootAsRatioTest, OutsideItsRangeTheFractionIsCubeRootOverOne) {
  const std::vector<double> outside = {0.0,
                                       -8.0,
                                       std::ldexp(1.0, -301),
                                       std::nextafter(std::ldexp(1.0, -300), 0.0),
                                       std::ldexp(1.0, 301),
                                       1e200,
                                       std::numeric_limits<double>::infinity()};
  for (double x : outside) {
    const CubeRootRatio<double> ratio = CubeRootAsRatio(x);
    EXPECT_EQ(RootBits(ratio.numerator), RootBits(CubeRoot(x))) << x;
    EXPECT_EQ(ratio.denominator, 1.0) << x;
  }
  // And inside it, both ends take the fraction.
  EXPECT_NE(CubeRootAsRatio(std::ldexp(1.0, -300)).denominator, 1.0);
  EXPECT_NE(CubeRootAsRatio(std::nextafter(std::ldexp(1.0, 301), 0.0)).denominator, 1.0);
}

TEST(CubeRootAsRatioTest, EachLaneHasTheBitsOfTheScalarFraction) {
  std::vector<double> arguments = Arguments();
  arguments.resize(20000);
  for (double special : {0.0, -27.0, 1e-100, 1e100, std::numeric_limits<double>::infinity()}) {
    arguments.push_back(special);
    arguments.push_back(0.3);
  }
  for (std::size_t i = 0; i + kLanes <= arguments.size(); i += kLanes) {
    Lanes x;
    for (int l = 0; l < kLanes; ++l) x[l] = arguments[i + l];
    const CubeRootRatio<Lanes> ratio = CubeRootAsRatio(x);
    for (int l = 0; l < kLanes; ++l) {
      const CubeRootRatio<double> scalar = CubeRootAsRatio(x[l]);
      EXPECT_EQ(RootBits(ratio.numerator[l]), RootBits(scalar.numerator)) << std::hexfloat << x[l];
      EXPECT_EQ(RootBits(ratio.denominator[l]), RootBits(scalar.denominator)) << x[l];
    }
  }
}

}  // namespace
}  // namespace getme::test
