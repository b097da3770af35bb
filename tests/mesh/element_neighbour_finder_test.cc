// ElementNeighbourFinder with a node filter (`through`): the sequential substep asks only for the
// elements that share a movable node with its pick. Checked against a brute-force scan over all
// elements, in canonical order, for every element of mixed and hexahedral meshes and several
// node filters.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <vector>

#include "getme/mesh/element_neighbours.h"
#include "getme/mesh/mesh.h"
#include "mesh_spec.h"

namespace getme::mesh_test {
namespace {

// Elements other than `element` with a node that is in `element` and flagged, by canonical rank.
std::vector<ElementId> BruteForce(const Mesh& mesh, ElementId element,
                                  const std::vector<std::uint8_t>& through) {
  const std::span<const NodeId> own = mesh.element_nodes(element);
  std::vector<ElementId> found;
  for (ElementId other : mesh.canonical_order()) {
    if (other == element) continue;
    for (NodeId node : mesh.element_nodes(other)) {
      if (through[node] && std::find(own.begin(), own.end(), node) != own.end()) {
        found.push_back(other);
        break;
      }
    }
  }
  return found;
}

void ExpectMatchesBruteForce(const Mesh& mesh, const std::vector<std::uint8_t>& through) {
  ElementNeighbourFinder finder;
  for (ElementId e = 0; e < mesh.element_count(); ++e) {
    const std::span<const ElementId> found = finder.Find(mesh, e, through);
    EXPECT_EQ(std::vector<ElementId>(found.begin(), found.end()), BruteForce(mesh, e, through))
        << "element " << e;
  }
}

class ElementNeighbourFinderTest : public ::testing::TestWithParam<MeshSpec (*)()> {};

TEST_P(ElementNeighbourFinderTest, FilteredNeighboursMatchABruteForceScan) {
  absl::StatusOr<Mesh> mesh = BuildMesh(GetParam()());
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  const auto nodes = static_cast<std::size_t>(mesh->node_count());
  // Every node (the unfiltered neighbours), interior nodes only (the sequential substep's movable
  // nodes with the boundary fixed), no node, and a pattern that splits elements.
  std::vector<std::uint8_t> all(nodes, 1), interior(nodes), none(nodes, 0), every_third(nodes);
  for (std::size_t i = 0; i < nodes; ++i) {
    interior[i] = mesh->is_boundary(static_cast<NodeId>(i)) ? 0 : 1;
    every_third[i] = i % 3 == 0 ? 1 : 0;
  }
  for (const auto* through : {&all, &interior, &none, &every_third}) {
    ExpectMatchesBruteForce(*mesh, *through);
  }
}

TEST_P(ElementNeighbourFinderTest, AnEmptyFilterMeansEveryNode) {
  absl::StatusOr<Mesh> mesh = BuildMesh(GetParam()());
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  ElementNeighbourFinder finder;
  for (ElementId e = 0; e < mesh->element_count(); ++e) {
    const std::span<const ElementId> found = finder.Find(*mesh, e);
    const std::span<const ElementId> table = mesh->element_neighbours(e);
    EXPECT_EQ(std::vector<ElementId>(found.begin(), found.end()),
              std::vector<ElementId>(table.begin(), table.end()))
        << "element " << e;
  }
}

MeshSpec HexBlockOfThree() { return HexBlock(3); }

INSTANTIATE_TEST_SUITE_P(Meshes, ElementNeighbourFinderTest,
                         ::testing::Values(&HexBlockOfThree, &PrismCubeWithPyramidAndTet,
                                           &HexBlockWithPyramidCell, &HexBlockWithPrismCell));

}  // namespace
}  // namespace getme::mesh_test
