#include "brute_force_nearest.h"

#include <algorithm>
#include <limits>

namespace getme::test {
namespace {

Vec3 ClosestOnSegment(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return a + t * ab;
}

}  // namespace

Vec3 ClosestOnTriangle(const Vec3& p, const Triangle3& t) {
  const Vec3 normal = (t.b - t.a).cross(t.c - t.a);
  const Vec3 on_plane = p - normal * ((p - t.a).dot(normal) / normal.squaredNorm());
  const auto inside = [&](const Vec3& u, const Vec3& v) {
    return (v - u).cross(on_plane - u).dot(normal) >= 0.0;
  };
  if (inside(t.a, t.b) && inside(t.b, t.c) && inside(t.c, t.a)) return on_plane;
  Vec3 best = ClosestOnSegment(p, t.a, t.b);
  for (const Vec3& candidate : {ClosestOnSegment(p, t.b, t.c), ClosestOnSegment(p, t.c, t.a)}) {
    if ((candidate - p).squaredNorm() < (best - p).squaredNorm()) best = candidate;
  }
  return best;
}

double BruteForceDistance(const Vec3& p, const std::vector<Triangle3>& triangles) {
  double best = std::numeric_limits<double>::infinity();
  for (const Triangle3& t : triangles) best = std::min(best, (ClosestOnTriangle(p, t) - p).norm());
  return best;
}

}  // namespace getme::test
