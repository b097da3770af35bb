#pragma once

// The cube root every mean ratio needs (Def. 3, eq. 9: q_k = 3 det(S_k)^{2/3} / |S_k|_F², so one
// ∛(det²) per node tetrahedron), written with + − × ÷ and bit operations only.
//
// Why not std::cbrt. libm's cbrt is an out-of-line call that splits and rebuilds its argument
// with frexp and scalbn, lane by lane: it was 35–45 % of a whole default run on the shared meshes
// (perf; docs/design.md), and it cannot share a vector register with the rest of a kernel.
// Here the same operations act on one double or on every lane of Lanes at once, so the two
// instantiations give the same bits lane for lane (lanes.h's rule), on every machine with IEEE
// 754 doubles, without a library call.
//
// How. x = m · 2^(3q + r) with m ∈ [1, 2), r ∈ {0, 1, 2}; then ∛x = ∛m · ∛(2^r) · 2^q. A degree-6
// polynomial seeds ∛m to a relative error ε ≤ 2.2·10⁻⁷ (scripts/fit_cube_root.py prints its
// coefficients and that bound), and one Halley step for y³ = x,
//   y ← y + y (x − y³) / (2y³ + x),
// converges cubically: the error after it is about ε³ ≈ 10⁻²⁰, far below a double's rounding,
// so the result is within one unit in the last place of the exact root (faithfully rounded;
// tests/elements/cube_root_test.cc checks it against long double on millions of arguments).
// glibc's own cbrt is allowed up to 4 ulps on x86-64 (its libm-test-ulps).
//
// Outside [2^-959, 2^1017) — zero, negative, subnormal, huge, infinite or NaN arguments, none of
// which a valid element of a sane mesh produces — the argument goes to std::cbrt, lane by lane,
// so every input still gets libm's answer.

#include <cmath>
#include <cstdint>
#include <type_traits>

#include "getme/elements/lanes.h"

namespace getme {

// ∛x = numerator / denominator (CubeRootAsRatio).
template <typename S>
struct CubeRootRatio {
  S numerator;
  S denominator;
};

namespace internal {

template <typename S>
using LaneBits = typename LaneTypes<kLaneCount<S>>::Bits;

// The integer type with the bits of S: one word for a double, a word per lane for lanes.
template <typename S>
struct CubeRootBitsOf {
  using type = typename LaneTypes<kLaneCount<S>>::Bits;
};
template <>
struct CubeRootBitsOf<double> {
  using type = std::uint64_t;
};
template <typename S>
using CubeRootBits = typename CubeRootBitsOf<S>::type;

// Biased exponents of the arguments the polynomial-and-Halley path takes: 2^-959 ≤ x < 2^1017, so
// y³ and 2y³ + x stay finite and normal.
inline constexpr std::uint64_t kCubeRootLowestExponent = 64;
inline constexpr std::uint64_t kCubeRootHighestExponent = 2039;

// ∛m ≈ Σ_j kCubeRootSeed[j] (m − 1.5)^j on [1, 2) (scripts/fit_cube_root.py).
inline constexpr double kCubeRootSeed[] = {
    1.1447142687179805,     0.25438349240779462,   -0.056532407709572081,  0.020856527059752702,
    -0.0092403117947731303, 0.0051686995389332024, -0.0027580818605115907,
};
inline constexpr double kCubeRootOfTwo = 1.2599210498948732;   // ∛2
inline constexpr double kCubeRootOfFour = 1.5874010519681994;  // ∛4

// The polynomial seed of ∛x, relative error ≤ 2.2·10⁻⁷ (before the Halley step).
// __builtin_bit_cast rather than std::bit_cast: a builtin is never a call, and no call that passes
// lanes may be left (GETME_LANE_INLINE, lanes.h).
template <typename S>
GETME_LANE_INLINE S CubeRootSeed(S x) {
  using Bits = CubeRootBits<S>;
  constexpr std::uint64_t kMantissa = (std::uint64_t{1} << 52) - 1;
  constexpr std::uint64_t kExponentOfOne = std::uint64_t{1023} << 52;
  const Bits bits = __builtin_bit_cast(Bits, x);
  const Bits biased = bits >> 52;
  // x = m · 2^(biased − 1023) and biased − 1023 = 3q + r: with t = biased + 2046 (so that
  // t − 3·1023 = biased − 1023), q = ⌊t/3⌋ − 1023. ⌊t/3⌋ = (t · 43691) >> 17 for t < 2^16.
  const Bits t = biased + 2046;
  const Bits third = (t * 43691) >> 17;
  const Bits remainder = t - third * 3;
  const S u = __builtin_bit_cast(S, (bits & kMantissa) | kExponentOfOne) - 1.5;
  // Estrin's scheme rather than Horner's: three levels of dependent multiplies instead of six,
  // which is what the latency-bound node steps of the polish wait for.
  const S u2 = u * u;
  const S u4 = u2 * u2;
  const S low = kCubeRootSeed[0] + kCubeRootSeed[1] * u;
  const S middle = kCubeRootSeed[2] + kCubeRootSeed[3] * u;
  const S high = kCubeRootSeed[4] + kCubeRootSeed[5] * u + kCubeRootSeed[6] * u2;
  S seed = low + u2 * middle + u4 * high;
  seed = seed * Select(remainder == 0, Splat<S>(1.0),
                       Select(remainder == 1, Splat<S>(kCubeRootOfTwo), Splat<S>(kCubeRootOfFour)));
  // · 2^q by adding q to the exponent field (modulo 2^64, so a negative q subtracts).
  seed = __builtin_bit_cast(S, __builtin_bit_cast(Bits, seed) + ((third - 1023) << 52));
  return seed;
}

// The Halley step from the seed, y + y (x − y³) / (2y³ + x), as the fraction
// y (y³ + 2x) / (2y³ + x) (CubeRootAsRatio below).
template <typename S>
GETME_LANE_INLINE CubeRootRatio<S> CubeRootFraction(S x) {
  const S seed = CubeRootSeed(x);
  const S cube = seed * seed * seed;
  return {seed * (cube + (x + x)), cube + cube + x};
}

template <typename S>
GETME_LANE_INLINE S FastCubeRoot(S x) {
  const S seed = CubeRootSeed(x);
  const S cube = seed * seed * seed;
  return seed + seed * ((x - cube) / (cube + cube + x));
}

// Where CubeRootAsRatio's fraction is used: x ∈ [2^-300, 2^300], so that its numerator (about
// x^{4/3}) and the products callers form of it with |S|_F² and det S stay far from overflow and
// underflow. A node tetrahedron's det S² is there for every edge length between about 10⁻¹⁵ and
// 10¹⁵.
inline constexpr std::uint64_t kCubeRootRatioLowestExponent = 1023 - 300;
inline constexpr std::uint64_t kCubeRootRatioHighestExponent = 1023 + 300;

}  // namespace internal

// ∛x, within one ulp of the exact root; the same bits for a double and for each lane of Lanes.
// Forced inline: GCC stopped inlining it into the polish's kernels once they grew, and the call
// then took a seventh of a polish on knowles-mixed-beam.vtk.
[[gnu::always_inline]] inline double CubeRoot(double x) {
  const std::uint64_t biased = __builtin_bit_cast(std::uint64_t, x) >> 52;
  if (biased < internal::kCubeRootLowestExponent || biased > internal::kCubeRootHighestExponent) {
    return std::cbrt(x);  // also every negative x: its sign bit makes `biased` ≥ 2048
  }
  return internal::FastCubeRoot(x);
}

template <typename S>
requires(kLaneCount<S> > 1) GETME_LANE_INLINE S CubeRoot(S x) {
  S root = internal::FastCubeRoot(x);
  const internal::LaneBits<S> biased = __builtin_bit_cast(internal::LaneBits<S>, x) >> 52;
  for (int l = 0; l < kLaneCount<S>; ++l) {
    if (biased[l] < internal::kCubeRootLowestExponent ||
        biased[l] > internal::kCubeRootHighestExponent) {
      root[l] = std::cbrt(x[l]);
    }
  }
  return root;
}

// ∛x = numerator / denominator, for a caller that divides by something anyway: the Halley step
// y + y (x − y³) / (2y³ + x) is the fraction y (y³ + 2x) / (2y³ + x), and a caller that computes
// 3∛x / N (the mean ratio) divides once, by denominator · N, instead of twice: the divisions,
// with their long latency and the one divider per core they share, were what the quality kernels
// waited for (perf annotate). Within a few ulps of ∛x, where CubeRoot is within one. Outside
// [2^-300, 2^300] the fraction is CubeRoot(x) / 1, so every argument CubeRoot takes works here.
[[gnu::always_inline]] inline CubeRootRatio<double> CubeRootAsRatio(double x) {
  const std::uint64_t biased = __builtin_bit_cast(std::uint64_t, x) >> 52;
  if (biased < internal::kCubeRootRatioLowestExponent ||
      biased > internal::kCubeRootRatioHighestExponent) {
    return {CubeRoot(x), 1.0};
  }
  return internal::CubeRootFraction(x);
}

template <typename S>
requires(kLaneCount<S> > 1) GETME_LANE_INLINE CubeRootRatio<S> CubeRootAsRatio(S x) {
  CubeRootRatio<S> ratio = internal::CubeRootFraction(x);
  const internal::LaneBits<S> biased = __builtin_bit_cast(internal::LaneBits<S>, x) >> 52;
  for (int l = 0; l < kLaneCount<S>; ++l) {
    if (biased[l] < internal::kCubeRootRatioLowestExponent ||
        biased[l] > internal::kCubeRootRatioHighestExponent) {
      ratio.numerator[l] = CubeRoot(x[l]);
      ratio.denominator[l] = 1.0;
    }
  }
  return ratio;
}

}  // namespace getme
