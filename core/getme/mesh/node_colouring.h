#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "getme/mesh/mesh.h"

namespace getme {

// A partition of selected nodes into independent sets: no two nodes of one colour belong to a
// common element. A node-local optimisation (the polish stage of issue 14) may then move all nodes
// of one colour at once, on any number of threads, each reading and writing only its own elements,
// and get the same bits as one thread: within a colour no node's move can see another's.
struct NodeColouring {
  // Colour c holds nodes[offsets[c] .. offsets[c + 1]), in ascending node id.
  std::vector<std::int64_t> offsets = {0};
  std::vector<NodeId> nodes;

  int colour_count() const { return static_cast<int>(offsets.size()) - 1; }
  std::span<const NodeId> Colour(int colour) const {
    return std::span<const NodeId>(nodes).subspan(offsets[colour],
                                                  offsets[colour + 1] - offsets[colour]);
  }
};

// Greedy first-fit colouring of the nodes with selected[node] != 0 (unselected nodes get no
// colour and constrain nothing: they never move), visiting nodes in ascending id so the result is
// a function of the mesh alone. Each node takes the smallest colour no already coloured node of
// its elements has; the count is at most one more than the largest number of selected nodes that
// share an element with one node. Serial: it runs once per Smooth() call.
NodeColouring ColourNodes(const Mesh& mesh, std::span<const std::uint8_t> selected);

// Row c: the elements whose last coloured node (in colour order) has colour c, ascending. A sweep
// that moves the colours in order leaves these elements alone once colour c has had its turn, so
// their qualities are then final for the sweep (the polish's worst-element stage stops a sweep it
// would drop on that). Elements without a coloured node are in no row.
CompressedRows ElementsByLastColour(const Mesh& mesh, const NodeColouring& colouring);

}  // namespace getme
