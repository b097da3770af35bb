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

// Two doubles: one SSE2 register on every x86-64. Four would need AVX, which the build does not
// assume (and 32-byte vectors passed without AVX change the ABI).
inline constexpr int kLanes = 2;
using Lanes = double __attribute__((vector_size(kLanes * sizeof(double))));
using LaneMask = std::int64_t __attribute__((vector_size(kLanes * sizeof(double))));

template <typename S>
S Splat(double value) {
  if constexpr (std::is_same_v<S, double>) {
    return value;
  } else {
    S lanes;
    for (int l = 0; l < kLanes; ++l) lanes[l] = value;
    return lanes;
  }
}

inline double Sqrt(double x) { return std::sqrt(x); }
inline Lanes Sqrt(Lanes x) {
  Lanes root;
  for (int l = 0; l < kLanes; ++l) root[l] = std::sqrt(x[l]);  // one sqrtpd
  return root;
}

// condition ? a : b, lane by lane.
inline double Select(bool condition, double a, double b) { return condition ? a : b; }
inline Lanes Select(LaneMask condition, Lanes a, Lanes b) { return condition ? a : b; }

// A condition true in every lane.
template <typename S>
auto AllLanes() {
  if constexpr (std::is_same_v<S, double>) {
    return true;
  } else {
    return Splat<S>(0.0) == Splat<S>(0.0);
  }
}

// Both conditions, lane by lane.
inline bool Both(bool a, bool b) { return a && b; }
inline LaneMask Both(LaneMask a, LaneMask b) { return a & b; }

// A point or vector in 3D whose coordinates are lanes. The operations evaluate in the order
// Eigen's fixed-size 3-vectors use (sums left to right), so Point3<double> results equal the
// Eigen::Vector3d results of the same expressions bit for bit.
template <typename S>
struct Point3 {
  S x, y, z;

  Point3& operator+=(const Point3& other) {
    x += other.x;
    y += other.y;
    z += other.z;
    return *this;
  }
};

template <typename S>
Point3<S> operator+(const Point3<S>& a, const Point3<S>& b) {
  return {a.x + b.x, a.y + b.y, a.z + b.z};
}
template <typename S>
Point3<S> operator-(const Point3<S>& a, const Point3<S>& b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
template <typename S, typename Factor>
Point3<S> operator*(const Factor& factor, const Point3<S>& a) {
  return {factor * a.x, factor * a.y, factor * a.z};
}
template <typename S, typename Factor>
Point3<S> operator*(const Point3<S>& a, const Factor& factor) {
  return {a.x * factor, a.y * factor, a.z * factor};
}
template <typename S, typename Divisor>
Point3<S> operator/(const Point3<S>& a, const Divisor& divisor) {
  return {a.x / divisor, a.y / divisor, a.z / divisor};
}

template <typename S>
Point3<S> Cross(const Point3<S>& a, const Point3<S>& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
template <typename S>
S Dot(const Point3<S>& a, const Point3<S>& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
template <typename S>
S SquaredNorm(const Point3<S>& a) {
  return a.x * a.x + a.y * a.y + a.z * a.z;
}
template <typename S>
S Norm(const Point3<S>& a) {
  return Sqrt(SquaredNorm(a));
}

}  // namespace getme
