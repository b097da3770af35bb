#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "absl/status/status.h"
#include "getme/mesh/mesh.h"
#include "getme/mesh/mesh_quality.h"
#include "getme/smoothing/boundary_slide.h"

namespace getme {

// The promise every successful Smooth() keeps, checked on the mesh it hands back rather than
// trusted (docs/reliability.md): every coordinate is finite, the nodes that had to stay put are
// bit-identical to the input, no element is invalid, and the reported quality is finite and is
// that of the returned coordinates. With a sliding boundary (boundary_slide.h), every sliding
// node also lies on the input's boundary surface, within 1e-9 of its bounding box's diagonal.
// Connectivity needs no check: the smoothers cannot change it (Mesh exposes coordinates only as
// mutable state).
class ResultCheck {
 public:
  // Records the immovable nodes' input coordinates (movable[i] == 0); call before smoothing.
  // `sliding` (with `slide`) marks the sliding nodes, all of them movable; the boundary ones among
  // them are checked against the input's surface.
  ResultCheck(const Mesh& mesh, std::span<const std::uint8_t> movable,
              const BoundarySlide* slide = nullptr, std::span<const std::uint8_t> sliding = {});

  // OK, or the first broken promise with the node or elements it concerns. `after` must be
  // EvaluateMeshQuality of `mesh` as it is now.
  absl::Status Check(const Mesh& mesh, const MeshQuality& after) const;

 private:
  std::vector<NodeId> immovable_;
  std::vector<double> x_, y_, z_;  // of immovable_, in the same order
  const BoundarySlide* slide_ = nullptr;
  std::vector<NodeId> sliding_;
  double surface_tolerance_ = 0.0;  // 1e-9 × the input's bounding-box diagonal
};

}  // namespace getme
