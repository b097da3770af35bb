#pragma once

#include <cstdint>
#include <vector>

#include "getme/mesh/mesh.h"
#include "getme/mesh/node_positions.h"
#include "getme/smoothing/smoothing_context.h"

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

  // Every node's position before the last Run: the previous state, kept anyway for Step 3, so
  // the caller need not copy the mesh to remember it.
  const NodePositions& previous_positions() const { return previous_; }

 private:
  void TransformAll(const SmoothingContext& context);
  template <ElementType kType>
  void TransformRange(const SmoothingContext& context, const ElementBlock& block,
                      std::int64_t begin, std::int64_t end);
  void UpdateNodes(SmoothingContext& context);
  void UpdateNodeRange(SmoothingContext& context, std::int64_t begin, std::int64_t end);
  std::int64_t RepairInvalid(SmoothingContext& context);

  std::vector<double> corner_xyz_;      // w_j·p'_{i,j} per corner (Mesh::node_corners numbering)
  std::vector<double> element_weight_;  // w_j per element
  NodePositions previous_;
};

}  // namespace getme
