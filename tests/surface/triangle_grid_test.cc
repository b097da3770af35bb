// The triangle grid's bounded nearest-point search (surface/getme_surface/triangle_grid.h)
// against a brute-force search over every triangle: on an evenly faceted sphere, and on a graded
// set where a few triangles are a hundred times larger than the rest (so the grid needs levels).
// Queries start as the smoothers' do, from a point of the surface moved a little.

#include "getme_surface/triangle_grid.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

#include "brute_force_nearest.h"

namespace getme::surface {
namespace {

using test::BruteForceDistance;
using test::ClosestOnTriangle;
using test::Triangle3;

// A UV sphere of radius 1: `rings` × `sectors` quads split into triangles (the poles' quads
// degenerate into triangles and are left as such).
std::vector<Triangle3> UvSphere(int rings, int sectors) {
  const auto at = [&](int ring, int sector) {
    const double polar = std::numbers::pi * ring / rings;
    const double azimuth = 2.0 * std::numbers::pi * sector / sectors;
    return Vec3(std::sin(polar) * std::cos(azimuth), std::sin(polar) * std::sin(azimuth),
                std::cos(polar));
  };
  std::vector<Triangle3> triangles;
  for (int ring = 0; ring < rings; ++ring) {
    for (int sector = 0; sector < sectors; ++sector) {
      const Vec3 a = at(ring, sector), b = at(ring + 1, sector), c = at(ring + 1, sector + 1),
                 d = at(ring, sector + 1);
      if (ring + 1 < rings) triangles.push_back({a, b, c});
      if (ring > 0) triangles.push_back({a, c, d});
    }
  }
  return triangles;
}

// Small triangles tiling the square [0, 1]² at z = 0 (a 20 × 20 grid split along diagonals)
// beside four large ones a hundred times their size, tilted, over [2, 102] × [0, 100].
std::vector<Triangle3> GradedSet() {
  std::vector<Triangle3> triangles;
  const int n = 20;
  const double h = 1.0 / n;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const Vec3 a(i * h, j * h, 0.0), b((i + 1) * h, j * h, 0.0), c((i + 1) * h, (j + 1) * h, 0.0),
          d(i * h, (j + 1) * h, 0.0);
      triangles.push_back({a, b, c});
      triangles.push_back({a, c, d});
    }
  }
  const Vec3 a(2.0, 0.0, 0.0), b(52.0, 0.0, 10.0), c(102.0, 0.0, 0.0), d(2.0, 50.0, 5.0),
      e(52.0, 50.0, 15.0), f(102.0, 50.0, 5.0), g(52.0, 100.0, 20.0);
  for (const Triangle3& t :
       {Triangle3{a, b, e}, Triangle3{a, e, d}, Triangle3{b, c, f}, Triangle3{d, e, g}}) {
    triangles.push_back(t);
  }
  return triangles;
}

std::vector<std::array<Vec3, 3>> Corners(const std::vector<Triangle3>& triangles) {
  std::vector<std::array<Vec3, 3>> corners;
  for (const Triangle3& t : triangles) corners.push_back({t.a, t.b, t.c});
  return corners;
}

// From a random point of a random triangle, moved by up to `step` in each coordinate: the
// grid, bounded by the move's length, finds the brute-force distance (or declines, only when
// the move spans more cells than kMaxCells), and its point lies on the triangles.
void ExpectBoundedSearchMatchesBruteForce(const std::vector<Triangle3>& triangles, double step,
                                          int trials, int& answered) {
  const TriangleGrid grid(Corners(triangles));
  std::mt19937_64 random(11);
  std::uniform_int_distribution<std::size_t> pick(0, triangles.size() - 1);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::uniform_real_distribution<double> move(-step, step);
  answered = 0;
  for (int trial = 0; trial < trials; ++trial) {
    const Triangle3& t = triangles[pick(random)];
    double u = unit(random), v = unit(random);
    if (u + v > 1.0) u = 1.0 - u, v = 1.0 - v;
    const Vec3 near = t.a + u * (t.b - t.a) + v * (t.c - t.a);
    const Vec3 point = near + Vec3(move(random), move(random), move(random));
    const std::optional<Vec3> found = grid.NearestWithin(point, (point - near).norm());
    if (!found) continue;
    ++answered;
    const double expected = BruteForceDistance(point, triangles);
    EXPECT_NEAR((*found - point).norm(), expected, 1e-12 * (1.0 + expected)) << "trial " << trial;
    EXPECT_LE(BruteForceDistance(*found, triangles), 1e-12) << "trial " << trial;
  }
}

TEST(TriangleGridTest, ShortMovesOnAFacetedSphereFindTheNearestPoint) {
  const std::vector<Triangle3> sphere = UvSphere(12, 24);
  const TriangleGrid grid(Corners(sphere));
  int answered = 0;
  // A tenth of the cell: the smoothers' moves. Every query must be answered.
  ExpectBoundedSearchMatchesBruteForce(sphere, 0.1 * grid.cell_size(), 500, answered);
  EXPECT_EQ(answered, 500);
  // Moves of several cells: some are left to the tree, the ones answered are right.
  ExpectBoundedSearchMatchesBruteForce(sphere, 3.0 * grid.cell_size(), 500, answered);
  EXPECT_GT(answered, 0);
  EXPECT_LT(answered, 500);
}

TEST(TriangleGridTest, AGradedSetNeedsLevelsAndFindsTheNearestPointOnEither) {
  const std::vector<Triangle3> graded = GradedSet();
  const TriangleGrid grid(Corners(graded));
  EXPECT_GE(grid.level_count(), 2);
  int answered = 0;
  ExpectBoundedSearchMatchesBruteForce(graded, 0.2 * grid.cell_size(), 1000, answered);
  EXPECT_EQ(answered, 1000);
  // Just off a large triangle, far from every small one: its own level finds it.
  const Triangle3& large = graded[graded.size() - 4];
  const Vec3 centre = (large.a + large.b + large.c) / 3.0;
  const Vec3 normal = (large.b - large.a).cross(large.c - large.a).normalized();
  const Vec3 off = centre + 0.01 * normal;
  const std::optional<Vec3> found = grid.NearestWithin(off, 0.02);
  ASSERT_TRUE(found);
  EXPECT_NEAR((*found - centre).norm(), 0.0, 1e-12);
}

// The lists node_triangles.h builds: every triangle within the radius, and no other, nearest
// first, against the brute-force distances (triangles within 1e-12 of the radius either way are
// not asked about). Radii of a fraction of a cell to a few cells, on both sets.
TEST(TriangleGridTest, TrianglesWithinARadiusAreExactlyTheBruteForceOnes) {
  for (const std::vector<Triangle3>& triangles : {UvSphere(12, 24), GradedSet()}) {
    const TriangleGrid grid(Corners(triangles));
    std::mt19937_64 random(5);
    std::uniform_int_distribution<std::size_t> pick(0, triangles.size() - 1);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::uniform_real_distribution<double> scale(0.1, 3.0);
    std::vector<TriangleGrid::Reach> within;
    std::vector<std::uint32_t> scratch;
    int listed = 0;
    for (int trial = 0; trial < 200; ++trial) {
      const Triangle3& t = triangles[pick(random)];
      const double radius = scale(random) * grid.cell_size();
      const Vec3 point = t.a + 0.5 * radius * Vec3(unit(random), unit(random), unit(random));
      ASSERT_TRUE(grid.TrianglesWithin(point, radius, within, scratch)) << "trial " << trial;
      for (std::size_t k = 1; k < within.size(); ++k) {
        EXPECT_LE(within[k - 1].distance, within[k].distance) << "trial " << trial;
      }
      std::vector<bool> in_list(triangles.size(), false);
      for (const TriangleGrid::Reach& reach : within) {
        in_list[reach.triangle] = true;
        const double expected =
            (ClosestOnTriangle(point, triangles[reach.triangle]) - point).norm();
        EXPECT_NEAR(reach.distance, expected, 1e-12) << "trial " << trial;
      }
      for (std::size_t k = 0; k < triangles.size(); ++k) {
        const double distance = (ClosestOnTriangle(point, triangles[k]) - point).norm();
        if (std::abs(distance - radius) < 1e-12) continue;
        EXPECT_EQ(in_list[k], distance < radius) << "trial " << trial << ", triangle " << k;
      }
      listed += static_cast<int>(within.size());
    }
    EXPECT_GT(listed, 200);
  }
}

TEST(TriangleGridTest, NothingWithinTheBoundIsNoAnswer) {
  const std::vector<Triangle3> sphere = UvSphere(12, 24);
  const TriangleGrid grid(Corners(sphere));
  // The origin is nearly 1 from every triangle; within 0.5 there is none (and within 0.99 the
  // bound spans too many cells: no answer either way).
  EXPECT_FALSE(grid.NearestWithin(Vec3::Zero(), 0.5));
  // A point just off the surface, with a bound just above its distance: answered, and exact.
  const Vec3 on = ClosestOnTriangle(Vec3(0.3, 0.4, 2.0), sphere[5]);
  const Vec3 off = on * 1.0001;
  const double distance = BruteForceDistance(off, sphere);
  const std::optional<Vec3> found = grid.NearestWithin(off, distance * 1.01);
  ASSERT_TRUE(found);
  EXPECT_NEAR((*found - off).norm(), distance, 1e-15);
  // ...and just below it, none.
  EXPECT_FALSE(grid.NearestWithin(off, distance * 0.99));
}

TEST(TriangleGridTest, NonFiniteQueriesAndAnEmptyGridGiveNoAnswer) {
  const TriangleGrid grid(Corners(UvSphere(6, 12)));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(grid.NearestWithin(Vec3(nan, 0.0, 0.0), 0.1));
  EXPECT_FALSE(grid.NearestWithin(Vec3(1.0, 0.0, 0.0), nan));
  EXPECT_FALSE(grid.NearestWithin(Vec3(1.0, 0.0, 0.0), -1.0));
  EXPECT_FALSE(grid.NearestWithin(Vec3(1.0, 0.0, 0.0), std::numeric_limits<double>::infinity()));
  const TriangleGrid empty(std::span<const std::array<Vec3, 3>>{});
  EXPECT_FALSE(empty.NearestWithin(Vec3::Zero(), 1.0));
}

}  // namespace
}  // namespace getme::surface
