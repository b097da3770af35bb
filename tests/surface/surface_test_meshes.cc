#include "surface_test_meshes.h"

#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <utility>
#include <vector>

#include "getme/elements/vec3.h"

namespace getme::test {
namespace {

Mesh BuildOrDie(MeshBuilder& builder) {
  absl::StatusOr<Mesh> mesh = std::move(builder).Build();
  if (!mesh.ok()) std::abort();
  return *std::move(mesh);
}

}  // namespace

Mesh HexCube(int n) {
  MeshBuilder builder;
  const auto id = [n](int i, int j, int k) { return i + (n + 1) * (j + (n + 1) * k); };
  for (int k = 0; k <= n; ++k) {
    for (int j = 0; j <= n; ++j) {
      for (int i = 0; i <= n; ++i) builder.AddNode(i, j, k);
    }
  }
  for (int k = 0; k < n; ++k) {
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) {
        const std::array<std::int64_t, 8> hex = {
            id(i, j, k),     id(i + 1, j, k),     id(i + 1, j + 1, k),     id(i, j + 1, k),
            id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)};
        builder.AddElement(ElementType::kHexahedron, hex);
      }
    }
  }
  return BuildOrDie(builder);
}

Mesh PolygonPrism(int sides, int layers, double height) {
  MeshBuilder builder;
  // Per level: the centre, then the rim counter-clockwise.
  const int per_level = sides + 1;
  for (int level = 0; level <= layers; ++level) {
    const double z = height * level / layers;
    builder.AddNode(0.0, 0.0, z);
    for (int s = 0; s < sides; ++s) {
      const double angle = 2.0 * std::numbers::pi * s / sides;
      builder.AddNode(std::cos(angle), std::sin(angle), z);
    }
  }
  for (int level = 0; level < layers; ++level) {
    const std::int64_t bottom = static_cast<std::int64_t>(level) * per_level;
    const std::int64_t top = bottom + per_level;
    for (int s = 0; s < sides; ++s) {
      const std::int64_t a = 1 + s;
      const std::int64_t b = 1 + (s + 1) % sides;
      const std::array<std::int64_t, 6> prism = {bottom, bottom + a, bottom + b,
                                                 top,    top + a,    top + b};
      builder.AddElement(ElementType::kPrism, prism);
    }
  }
  return BuildOrDie(builder);
}

Mesh FacetedSphere() {
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Vec3> points = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0},
                              {0, -1, t}, {0, 1, t}, {0, -1, -t}, {0, 1, -t},
                              {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  for (Vec3& p : points) p.normalize();
  const std::vector<std::array<int, 3>> icosahedron = {
      {0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
      {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
      {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  std::map<std::pair<int, int>, int> midpoint;
  const auto middle = [&](int a, int b) {
    const std::pair<int, int> key(std::min(a, b), std::max(a, b));
    const auto found = midpoint.find(key);
    if (found != midpoint.end()) return found->second;
    points.push_back((points[a] + points[b]).normalized());
    return midpoint[key] = static_cast<int>(points.size()) - 1;
  };
  std::vector<std::array<int, 3>> faces;
  for (const auto& [a, b, c] : icosahedron) {
    const int ab = middle(a, b);
    const int bc = middle(b, c);
    const int ca = middle(c, a);
    faces.push_back({a, ab, ca});
    faces.push_back({b, bc, ab});
    faces.push_back({c, ca, bc});
    faces.push_back({ab, bc, ca});
  }
  MeshBuilder builder;
  for (const Vec3& p : points) builder.AddNode(p[0], p[1], p[2]);
  const std::int64_t centre = builder.AddNode(0.0, 0.0, 0.0);
  for (const auto& [a, b, c] : faces) {
    // The faces turn outward, so the centre goes last for a positive volume in the paper's order
    // (docs/node-orders.md: nodes 0, 1, 2 counter-clockwise seen from node 3).
    const std::array<std::int64_t, 4> tet = {a, c, b, centre};
    builder.AddElement(ElementType::kTetrahedron, tet);
  }
  return BuildOrDie(builder);
}

}  // namespace getme::test
