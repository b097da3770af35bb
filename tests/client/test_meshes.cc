#include "test_meshes.h"

#include <array>
#include <random>

namespace getme::remote::testing {

Mesh DistortedHexBlock(int n, double distortion, std::uint64_t seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> move(-distortion, distortion);
  MeshBuilder builder;
  const auto id = [n](int i, int j, int k) { return (k * (n + 1) + j) * (n + 1) + i; };
  for (int k = 0; k <= n; ++k) {
    for (int j = 0; j <= n; ++j) {
      for (int i = 0; i <= n; ++i) {
        const bool interior = i > 0 && i < n && j > 0 && j < n && k > 0 && k < n;
        const double dx = interior ? move(random) : 0.0;
        const double dy = interior ? move(random) : 0.0;
        const double dz = interior ? move(random) : 0.0;
        builder.AddNode(i + dx, j + dy, k + dz);
      }
    }
  }
  for (int k = 0; k < n; ++k) {
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) {
        const std::array<std::int64_t, 8> nodes = {
            id(i, j, k),     id(i + 1, j, k),     id(i + 1, j + 1, k),     id(i, j + 1, k),
            id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)};
        builder.AddElement(ElementType::kHexahedron, nodes);
      }
    }
  }
  return *std::move(builder).Build();
}

}  // namespace getme::remote::testing
