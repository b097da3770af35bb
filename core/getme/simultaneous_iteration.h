#pragma once

#include <cstdint>
#include <vector>

#include "getme/mesh.h"
#include "getme/smoothing_context.h"

namespace getme {

// One iteration of the simultaneous substep (Sec. 3.1, Steps 1–3) on context.mesh, with its
// buffers allocated once per phase rather than per iteration. RunSimultaneous drives it; the
// micro-benchmarks time it alone.
class SimultaneousIteration {
 public:
  explicit SimultaneousIteration(const Mesh& mesh);

  struct Outcome {
    SmoothingContext::Summary summary;  // of the mesh after the iteration
    std::int64_t reverted_nodes = 0;    // nodes moved back to repair invalid elements (Step 3)
  };
  // Moves every movable node once and leaves context.quality up to date.
  Outcome Run(SmoothingContext& context);

 private:
  struct Coordinates {
    std::vector<double> x, y, z;
    void CopyFrom(const Mesh& mesh);
  };
  void TransformAll(const SmoothingContext& context);
  void UpdateNodes(SmoothingContext& context);
  std::int64_t RepairInvalid(SmoothingContext& context);

  std::vector<double> corner_xyz_;      // w_j·p'_{i,j} per corner (Mesh::node_corners numbering)
  std::vector<double> element_weight_;  // w_j per element
  std::vector<std::uint8_t> halvings_;  // per node: step halvings of the repair (Step 3)
  std::vector<std::uint8_t> element_mark_;
  Coordinates old_position_, new_position_;
};

}  // namespace getme
