#pragma once

#include "getme/mesh/mesh.h"

namespace getme {

// Node → node rows over the elements' geometric edges (ascending ids): the neighbours Laplacian
// smoothing averages over.
CompressedRows BuildEdgeNeighbours(const Mesh& mesh);

// The squared distance from a node to the nearest other node of its elements: the node's local
// length scale, for step sizes and finite differences that must not depend on the mesh's units.
// +∞ for a node in no element.
double NearestNodeDistance2(const Mesh& mesh, NodeId node);

}  // namespace getme
