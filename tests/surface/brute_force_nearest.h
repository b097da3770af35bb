#pragma once

// Nearest points on triangles by the plainest computation there is, written independently of
// the library's: the projection on the triangle's plane if it falls inside, otherwise the
// nearest of the three edges' clamped projections; and over a set, the minimum over every
// triangle. What the projector and the triangle grid are checked against.

#include <vector>

#include "getme/elements/vec3.h"

namespace getme::test {

struct Triangle3 {
  Vec3 a, b, c;
};

Vec3 ClosestOnTriangle(const Vec3& p, const Triangle3& t);

double BruteForceDistance(const Vec3& p, const std::vector<Triangle3>& triangles);

}  // namespace getme::test
