#pragma once

#include <cstdint>
#include <vector>

#include "getme/mesh/mesh.h"
#include "getme/mesh/node_positions.h"
#include "getme/parallel/element_tiles.h"
#include "getme/smoothing/element_passes.h"
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
  void TransformTile(const SmoothingContext& context, const ElementTiles::Tile& tile);
  void UpdateNodes(SmoothingContext& context);
  void UpdateNodeRange(SmoothingContext& context, std::int64_t begin, std::int64_t end);
  std::int64_t RepairInvalid(SmoothingContext& context);

  // The elements' visiting order and its node-disjoint tiles, built once per phase.
  ElementTiles tiles_;
  // Step 2's Σ w_j p'_{i,j} and Σ w_j per node, zero between iterations.
  std::vector<NodeSum> node_sums_;
  NodePositions previous_;
};

}  // namespace getme
