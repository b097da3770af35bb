#pragma once

#include <functional>
#include <initializer_list>
#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "getme/mesh/mesh.h"
#include "getme/smoothing/smoother.h"

namespace getme::testing {

// A shared Mesquite mesh (../shared/meshes/mesquite/NAME) as an engine mesh; fails the test on
// error.
Mesh LoadSharedMesh(const std::string& name);

// Copies of the coordinates, for bit-identity checks.
struct CoordinateSnapshot {
  std::vector<double> x, y, z;
  explicit CoordinateSnapshot(const Mesh& mesh);
  bool operator==(const CoordinateSnapshot&) const = default;
};

// One Smooth() run per thread count, each on a fresh mesh from `make_mesh`: what the
// thread-determinism tests compare. A failed generation or run is a test failure and ends the
// list early.
struct ThreadCountRun {
  CoordinateSnapshot coordinates;
  SmoothingResult result;
};
std::vector<ThreadCountRun> SmoothAtThreadCounts(
    const std::function<absl::StatusOr<Mesh>()>& make_mesh, SmoothingParams params,
    std::initializer_list<int> thread_counts);
// Each run reports its thread count, and has the first run's coordinates, q_min and q_mean, bit
// for bit.
void ExpectSameForEveryThreadCount(const std::vector<ThreadCountRun>& runs,
                                   std::initializer_list<int> thread_counts);

// Nodes a smoother must leave untouched under `params`: caller-fixed, or boundary if fix_boundary.
std::vector<NodeId> ImmovableNodes(const Mesh& mesh, const SmoothingParams& params);

// Invalid elements recounted from scratch with the Def. 2 kernel.
std::int64_t CountInvalid(const Mesh& mesh);

}  // namespace getme::testing
