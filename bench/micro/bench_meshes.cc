#include "bench_meshes.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>

#include "getme/meshgen/hybrid_block.h"

namespace getme::bench {
namespace {

std::int64_t max_elements = 1'000'000;

// HybridBlock(n, n, n) has about this many elements per unit cube (a quarter hexahedron layers,
// a quarter prism pairs, half cubes of 8–12 tetrahedra and pyramids); measured at n = 20.
constexpr double kElementsPerCube = 6.5;
constexpr double kDistortion = 0.3;
constexpr std::uint64_t kSeed = 5;

}  // namespace

std::vector<std::int64_t> BenchmarkSizes() {
  std::vector<std::int64_t> sizes;
  for (std::int64_t n = 10'000; n <= max_elements; n *= 10) sizes.push_back(n);
  return sizes;
}

void SetMaxBenchmarkElements(std::int64_t elements) { max_elements = elements; }

Mesh GenerateHybridMeshNear(std::int64_t elements) {
  const int n = std::max(
      3,
      static_cast<int>(std::lround(std::cbrt(static_cast<double>(elements) / kElementsPerCube))));
  auto mesh = meshgen::HybridBlock(n, n, n, kDistortion, kSeed);
  if (!mesh.ok()) {
    std::fprintf(stderr, "HybridBlock(%d): %s\n", n, mesh.status().ToString().c_str());
    std::abort();
  }
  return *std::move(mesh);
}

namespace {
std::int64_t cached_size = -1;
std::unique_ptr<Mesh> cached;
}  // namespace

void ReleaseHybridMesh() {
  cached.reset();
  cached_size = -1;
}

const Mesh& HybridMeshNear(std::int64_t elements) {
  if (cached_size != elements) {
    cached.reset();  // free the previous mesh before generating the next
    cached = std::make_unique<Mesh>(GenerateHybridMeshNear(elements));
    cached_size = elements;
  }
  return *cached;
}

void RestoreCoordinates(const Mesh& from, Mesh& to) {
  std::copy(from.x().begin(), from.x().end(), to.x().begin());
  std::copy(from.y().begin(), from.y().end(), to.y().begin());
  std::copy(from.z().begin(), from.z().end(), to.z().begin());
}

}  // namespace getme::bench
