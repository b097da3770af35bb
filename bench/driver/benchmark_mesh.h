#pragma once

#include <cstdint>
#include <vector>

#include "absl/status/statusor.h"
#include "bench_options.h"
#include "getme/mesh/mesh.h"

namespace getme::bench {

// A mesh ready to be smoothed again and again: the engine mesh plus its initial coordinates,
// which every repeat restores. Only the engine mesh is kept (no file document), so the memory
// measured during a run is the engine's.
struct BenchmarkMesh {
  MeshSpec spec;
  Mesh mesh;
  double load_seconds = 0.0;  // reading or generating, including the topology build
  // Process RSS before loading and after (the loader's freed memory handed back to the system):
  // the difference is the mesh as the engine holds it, plus the initial coordinates kept here.
  std::int64_t rss_before_load_bytes = 0;
  std::int64_t rss_after_load_bytes = 0;
  std::vector<double> initial_x, initial_y, initial_z;

  void RestoreInitialCoordinates();
};

// Reads the file or runs the generator the spec names. Errors name the file or the arguments.
absl::StatusOr<BenchmarkMesh> LoadBenchmarkMesh(const MeshSpec& spec);

}  // namespace getme::bench
