#pragma once

// The element kernels of transform.h and element_quality.h are written once over a lane type S:
// double (one element: the API the smoothers and tests call) or Lanes (kLanes elements side by
// side, for the simultaneous substep's passes over the whole mesh). Only operations that IEEE 754
// rounds exactly (+ − × ÷ √, comparisons, bit operations) act on whole lanes — the cube root is
// built from them (cube_root.h) — and pow goes through libm lane by lane. So each lane holds
// exactly the bits the double instantiation gives for its element, and a mesh smooths to the same
// coordinates whichever path evaluated an element.

#include <cmath>
#include <cstdint>
#include <type_traits>

namespace getme {

// kWidth doubles side by side as one GCC vector. Every operation the kernels apply to them acts
// lane by lane, so the width changes only how many elements one pass of a kernel evaluates, never
// the bits of any element's result.
// (Typedefs in a class template: GCC ignores vector_size on an alias template with a dependent
// size.)
template <int kWidth>
struct LaneTypes {
  typedef double Values __attribute__((vector_size(kWidth * sizeof(double))));
  typedef std::int64_t Mask __attribute__((vector_size(kWidth * sizeof(double))));
  typedef std::uint64_t Bits __attribute__((vector_size(kWidth * sizeof(double))));
};
template <int kWidth>
using LanesOf = typename LaneTypes<kWidth>::Values;
template <int kWidth>
using LaneMaskOf = typename LaneTypes<kWidth>::Mask;

// The reference width: two doubles, one SSE2 register on every x86-64, which the build assumes.
// The wider passes (4 lanes with AVX2, 8 with AVX-512) are compiled and chosen at run time in
// smoothing/element_passes_dispatch.cc and tested against this one.
inline constexpr int kLanes = 2;
using Lanes = LanesOf<kLanes>;
using LaneMask = LaneMaskOf<kLanes>;

// The number of elements one value of lane type S holds: 1 for double.
template <typename S>
inline constexpr int kLaneCount = static_cast<int>(sizeof(S) / sizeof(double));

// Every function that takes or returns lanes is forced inline. The 4- and 8-lane passes are
// compiled inside Highway's AVX2 and AVX-512 regions (smoothing/element_passes_dispatch.cc), but
// these templates are defined outside them: a call that stayed a call would pass a 32- or 64-byte
// vector between code compiled with and without AVX, whose calling conventions differ, and the
// upper lanes would arrive as garbage. GCC inlines them anyway ([[gnu::flatten]] on the passes);
// clang at the sanitizer stages' -O1 did not, and the 4- and 8-lane mean ratios read zeros in
// their upper lanes. tests/elements/element_passes_test.cc, run in the clang builds too, is the
// check (clang's -Wpsabi cannot be: it warns at every such call before inlining).
#define GETME_LANE_INLINE [[gnu::always_inline]] inline

template <typename S>
GETME_LANE_INLINE S Splat(double value) {
  if constexpr (std::is_same_v<S, double>) {
    return value;
  } else {
    S lanes;
    for (int l = 0; l < kLaneCount<S>; ++l) lanes[l] = value;
    return lanes;
  }
}

inline double Sqrt(double x) { return std::sqrt(x); }
template <typename S>
requires(kLaneCount<S> > 1) GETME_LANE_INLINE S Sqrt(S x) {
  S root;
  for (int l = 0; l < kLaneCount<S>; ++l) root[l] = std::sqrt(x[l]);  // one (v)sqrtpd
  return root;
}

// condition ? a : b, lane by lane.
inline double Select(bool condition, double a, double b) { return condition ? a : b; }
template <typename Mask, typename S>
requires(kLaneCount<S> > 1) GETME_LANE_INLINE S Select(Mask condition, S a, S b) {
  return condition ? a : b;
}

// A condition true in every lane.
template <typename S>
GETME_LANE_INLINE auto AllLanes() {
  if constexpr (std::is_same_v<S, double>) {
    return true;
  } else {
    return Splat<S>(0.0) == Splat<S>(0.0);
  }
}

// Both conditions, lane by lane.
inline bool Both(bool a, bool b) { return a && b; }
template <typename Mask>
requires(!std::is_same_v<Mask, bool>) GETME_LANE_INLINE Mask Both(Mask a, Mask b) { return a & b; }

// Either condition, lane by lane.
inline bool Either(bool a, bool b) { return a || b; }
template <typename Mask>
requires(!std::is_same_v<Mask, bool>) GETME_LANE_INLINE Mask Either(Mask a, Mask b) {
  return a | b;
}

// True if the condition holds in no lane (for a skip that changes no lane's result).
inline bool NoLane(bool condition) { return !condition; }
template <typename Mask>
requires(!std::is_same_v<Mask, bool>) GETME_LANE_INLINE bool NoLane(Mask condition) {
  for (int l = 0; l < static_cast<int>(sizeof(Mask) / sizeof(condition[0])); ++l) {
    if (condition[l] != 0) return false;
  }
  return true;
}

// A point or vector in 3D whose coordinates are lanes. The operations evaluate in the order
// Eigen's fixed-size 3-vectors use (sums left to right), so Point3<double> results equal the
// Eigen::Vector3d results of the same expressions bit for bit.
template <typename S>
struct Point3 {
  S x, y, z;

  GETME_LANE_INLINE Point3& operator+=(const Point3& other) {
    x += other.x;
    y += other.y;
    z += other.z;
    return *this;
  }
};

template <typename S>
GETME_LANE_INLINE Point3<S> operator+(const Point3<S>& a, const Point3<S>& b) {
  return {a.x + b.x, a.y + b.y, a.z + b.z};
}
template <typename S>
GETME_LANE_INLINE Point3<S> operator-(const Point3<S>& a, const Point3<S>& b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
template <typename S, typename Factor>
GETME_LANE_INLINE Point3<S> operator*(const Factor& factor, const Point3<S>& a) {
  return {factor * a.x, factor * a.y, factor * a.z};
}
template <typename S, typename Factor>
GETME_LANE_INLINE Point3<S> operator*(const Point3<S>& a, const Factor& factor) {
  return {a.x * factor, a.y * factor, a.z * factor};
}
template <typename S, typename Divisor>
GETME_LANE_INLINE Point3<S> operator/(const Point3<S>& a, const Divisor& divisor) {
  return {a.x / divisor, a.y / divisor, a.z / divisor};
}

template <typename S>
GETME_LANE_INLINE Point3<S> Cross(const Point3<S>& a, const Point3<S>& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
template <typename S>
GETME_LANE_INLINE S Dot(const Point3<S>& a, const Point3<S>& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
template <typename S>
GETME_LANE_INLINE S SquaredNorm(const Point3<S>& a) {
  return a.x * a.x + a.y * a.y + a.z * a.z;
}
template <typename S>
GETME_LANE_INLINE S Norm(const Point3<S>& a) {
  return Sqrt(SquaredNorm(a));
}

}  // namespace getme
