#pragma once

#include "getme/mesh/mesh.h"

namespace getme {

// Node → node rows over the elements' geometric edges (ascending ids): the neighbours Laplacian
// smoothing averages over.
CompressedRows BuildEdgeNeighbours(const Mesh& mesh);

}  // namespace getme
