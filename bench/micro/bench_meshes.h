#pragma once

#include <cstdint>
#include <vector>

#include "getme/mesh/mesh.h"

namespace getme::bench {

// Element counts the size-dependent benchmarks run at: 10k, 100k, 1M, ... up to the
// --max_elements flag of micro_main.cc (default 1M; 10M needs about 6 GB).
std::vector<std::int64_t> BenchmarkSizes();
void SetMaxBenchmarkElements(std::int64_t max_elements);

// A distorted meshgen::HybridBlock (all four element types, about 88% tetrahedra) with close to
// `elements` elements. The last one asked for is kept, so benchmarks registered size by size
// generate each mesh once.
const Mesh& HybridMeshNear(std::int64_t elements);

// Frees the mesh HybridMeshNear keeps.
void ReleaseHybridMesh();

// Generates the mesh HybridMeshNear(elements) would return, without keeping it.
Mesh GenerateHybridMeshNear(std::int64_t elements);

// Copies the coordinates of `from` into `to` (the same mesh topology).
void RestoreCoordinates(const Mesh& from, Mesh& to);

}  // namespace getme::bench
