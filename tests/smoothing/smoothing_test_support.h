#pragma once

#include <cstdint>
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

// Fails the test, naming the first node, unless every one of `nodes` has its `before`
// coordinates in `mesh` bit for bit.
void ExpectUnmoved(const CoordinateSnapshot& before, const Mesh& mesh,
                   const std::vector<NodeId>& nodes);

// Fixes every node of the element of lowest mean ratio among those of at least `at_least` and
// returns that quality: a minimum no smoother can move, which GETMe lifts the worse elements to.
double PinElementOfQualityAtLeast(Mesh& mesh, double at_least);

// Invalid elements recounted from scratch with the Def. 2 kernel.
std::int64_t CountInvalid(const Mesh& mesh);

// A generated mesh by name, made afresh on each call (property tests smooth two copies).
struct NamedMesh {
  std::string name;
  std::function<absl::StatusOr<Mesh>()> make;
};

// For each seed, a hybrid block of n × n × (n − 1) cells and a hexahedral block of n × n × n cells,
// interior nodes displaced by 0.35 of a cell: distorted meshes of every element type.
std::vector<NamedMesh> DistortedBlocks(int n, std::initializer_list<std::uint64_t> seeds);

// Marks every seventh node fixed, as a caller's `fixed` array would.
void FixSomeInteriorNodes(Mesh& mesh);

}  // namespace getme::testing
