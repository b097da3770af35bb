#pragma once

// Test meshes described as plain data (coordinates and per-element node lists), so the reference
// computations of these tests read the same description the MeshBuilder gets and never the Mesh's
// own storage or topology.

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "absl/status/statusor.h"
#include "getme/elements/element_type.h"
#include "getme/mesh/mesh.h"

namespace getme::mesh_test {

struct ElementSpec {
  ElementType type;
  std::vector<std::int64_t> nodes;  // paper node order (Fig. 1, docs/node-orders.md)
};

struct MeshSpec {
  std::vector<Eigen::Vector3d> nodes;
  std::vector<ElementSpec> elements;

  std::int64_t AddNode(const Eigen::Vector3d& p);
  // Returns the element's insertion index, which is its global id after Build().
  std::int64_t AddElement(ElementType type, std::vector<std::int64_t> nodes);
  std::vector<Eigen::Vector3d> ElementPoints(std::int64_t element) const;
};

absl::StatusOr<Mesh> BuildMesh(const MeshSpec& spec);

// cells³ unit hexahedra on [0, cells]³. Node (i, j, k) has id i + (cells+1)·(j + (cells+1)·k);
// cell (a, b, c) has id a + cells·(b + cells·c).
MeshSpec HexBlock(int cells);
int HexBlockNodeId(int cells, int i, int j, int k);
int HexBlockCellId(int cells, int a, int b, int c);

// The unit cube split along its diagonal plane x = y into two prisms, a pyramid on the cube's
// x = 1 face (apex outside) and a tetrahedron on the pyramid's y-side triangle. Every interface
// is conforming. Insertion order: prism, tetrahedron, prism, pyramid.
MeshSpec PrismCubeWithPyramidAndTet();

// The 2×2×2 hex block with cell 7 (the one at [1,2]³) replaced by six pyramids around a new node
// at its centre: conforming, so the new centre node and the block centre are interior.
MeshSpec HexBlockWithPyramidCell();

// The 2×2×2 hex block with cell 0 replaced by two prisms (split along its diagonal plane x = y).
// The prisms' triangles on cell 0's top face meet cell 4's quad face: a non-conforming interface
// whose faces never match, so they count as boundary faces and the block centre becomes boundary.
MeshSpec HexBlockWithPrismCell();

}  // namespace getme::mesh_test
