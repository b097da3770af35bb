#pragma once

#include <string>
#include <vector>

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

// Nodes a smoother must leave untouched under `params`: caller-fixed, or boundary if fix_boundary.
std::vector<NodeId> ImmovableNodes(const Mesh& mesh, const SmoothingParams& params);

// Invalid elements recounted from scratch with the Def. 2 kernel.
std::int64_t CountInvalid(const Mesh& mesh);

}  // namespace getme::testing
