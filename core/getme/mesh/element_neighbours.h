#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "getme/mesh/mesh.h"

namespace getme {

// The elements sharing at least one node with an element, without the element itself, in
// canonical order (Mesh::canonical_order), collected from the node→element rows when asked.
// The smoothers use this instead of a stored table: a tetrahedron of a tetrahedral mesh has
// about 80 such neighbours, so a table costs over 300 bytes per element, more than the rest of
// the mesh and the smoother state together; collecting them costs a few percent of a sequential
// pick, which then evaluates every one of them.
class ElementNeighbourFinder {
 public:
  // Valid until the next call. With `through` non-empty (one flag per node), only the elements
  // sharing a node flagged in it: a step that moves only those nodes changes no other element.
  std::span<const ElementId> Find(const Mesh& mesh, ElementId element,
                                  std::span<const std::uint8_t> through = {});

 private:
  // One sorted row per node of the element: ids where they are canonical ranks, else
  // rank << 32 | id in keyed_.
  std::vector<std::size_t> row_ends_;
  std::vector<ElementId> neighbours_;
  std::vector<ElementId> merged_;
  std::vector<std::uint64_t> keyed_;
  std::vector<std::uint64_t> keyed_merged_;
};

}  // namespace getme
