// ColourNodes (core/getme/mesh/node_colouring.h): the independent sets the polish stage moves in
// parallel. No two nodes of one colour may share an element, every selected node is coloured once,
// unselected nodes not at all, and the sets are ascending so the order of node steps is fixed.
// ElementsByLastColour: each element under the largest colour among its nodes, checked element by
// element against that maximum.

#include "getme/mesh/node_colouring.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>
#include <vector>

#include "getme/meshgen/distorted_hex_block.h"
#include "getme/meshgen/hybrid_block.h"

namespace getme {
namespace {

void ExpectProperColouring(const Mesh& mesh, const std::vector<std::uint8_t>& selected) {
  const NodeColouring colouring = ColourNodes(mesh, selected);
  std::vector<int> colour(mesh.node_count(), -1);
  for (int c = 0; c < colouring.colour_count(); ++c) {
    const auto nodes = colouring.Colour(c);
    EXPECT_FALSE(nodes.empty()) << "colour " << c;
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      if (i > 0) {
        EXPECT_LT(nodes[i - 1], nodes[i]) << "colour " << c << " not ascending";
      }
      EXPECT_EQ(colour[nodes[i]], -1) << "node " << nodes[i] << " coloured twice";
      colour[nodes[i]] = c;
    }
  }
  for (NodeId node = 0; node < mesh.node_count(); ++node) {
    EXPECT_EQ(colour[node] >= 0, selected[node] != 0) << "node " << node;
  }
  for (ElementId e = 0; e < mesh.element_count(); ++e) {
    const auto nodes = mesh.element_nodes(e);
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      for (std::size_t j = i + 1; j < nodes.size(); ++j) {
        if (colour[nodes[i]] < 0) continue;
        EXPECT_NE(colour[nodes[i]], colour[nodes[j]])
            << "nodes " << nodes[i] << " and " << nodes[j] << " of element " << e;
      }
    }
  }
}

TEST(NodeColouringTest, NoTwoNodesOfOneColourShareAnElement) {
  for (std::uint64_t seed : {1, 2, 3}) {
    auto mesh = meshgen::HybridBlock(6, 5, 4, 0.3, seed);
    ASSERT_TRUE(mesh.ok()) << mesh.status();
    ExpectProperColouring(*mesh, std::vector<std::uint8_t>(mesh->node_count(), 1));
  }
}

TEST(NodeColouringTest, OnlySelectedNodesAreColoured) {
  auto mesh = meshgen::DistortedHexBlock(5, 5, 5, 0.3, 4);
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  std::vector<std::uint8_t> selected(mesh->node_count(), 0);
  for (NodeId node = 0; node < mesh->node_count(); ++node) {
    selected[node] = !mesh->is_boundary(node) && node % 3 != 0 ? 1 : 0;
  }
  ExpectProperColouring(*mesh, selected);
}

TEST(NodeColouringTest, HexGridNeedsFewColours) {
  // A node of a hexahedral grid shares elements with 26 others; first fit needs at most 27 colours
  // (a structured grid admits 8).
  auto mesh = meshgen::DistortedHexBlock(6, 6, 6, 0.0, 1);
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  const NodeColouring colouring =
      ColourNodes(*mesh, std::vector<std::uint8_t>(mesh->node_count(), 1));
  EXPECT_GE(colouring.colour_count(), 8);
  EXPECT_LE(colouring.colour_count(), 27);
}

// First fit in node order, by brute force: each selected node, in ascending id, takes the
// smallest colour no node sharing an element with it has taken. The polish's node steps, and so
// its results, follow this colouring, so ColourNodes must give exactly it.
std::vector<int> FirstFitColours(const Mesh& mesh, const std::vector<std::uint8_t>& selected) {
  std::vector<int> colour(mesh.node_count(), -1);
  for (NodeId node = 0; node < mesh.node_count(); ++node) {
    if (!selected[node]) continue;
    std::set<int> taken;
    for (ElementId e : mesh.node_elements(node)) {
      for (NodeId other : mesh.element_nodes(e)) {
        if (colour[other] >= 0) taken.insert(colour[other]);
      }
    }
    int c = 0;
    while (taken.count(c) != 0) ++c;
    colour[node] = c;
  }
  return colour;
}

void ExpectFirstFit(const Mesh& mesh, const std::vector<std::uint8_t>& selected) {
  const NodeColouring colouring = ColourNodes(mesh, selected);
  std::vector<int> colour(mesh.node_count(), -1);
  for (int c = 0; c < colouring.colour_count(); ++c) {
    for (NodeId node : colouring.Colour(c)) colour[node] = c;
  }
  EXPECT_EQ(colour, FirstFitColours(mesh, selected));
}

TEST(NodeColouringTest, TheColouringIsFirstFitInNodeOrder) {
  auto mesh = meshgen::HybridBlock(6, 5, 4, 0.3, 2);
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  std::vector<std::uint8_t> selected(mesh->node_count(), 0);
  for (NodeId node = 0; node < mesh->node_count(); ++node) {
    selected[node] = !mesh->is_boundary(node) || node % 2 == 0 ? 1 : 0;
  }
  ExpectFirstFit(*mesh, selected);
}

// Nodes 0..69 pairwise in a tetrahedron (each pair with two nodes of its own): first fit gives
// them 70 colours, more than a 64-bit word of taken colours could hold.
TEST(NodeColouringTest, FirstFitHoldsPastSixtyFourColours) {
  constexpr int kClique = 70;
  MeshBuilder builder;
  std::mt19937 random(5);
  std::uniform_real_distribution<double> coordinate(0.0, 1.0);
  const auto add_node = [&] {
    return builder.AddNode(coordinate(random), coordinate(random), coordinate(random));
  };
  for (int i = 0; i < kClique; ++i) add_node();
  for (std::int64_t i = 0; i < kClique; ++i) {
    for (std::int64_t j = i + 1; j < kClique; ++j) {
      const std::int64_t p = add_node();
      const std::int64_t q = add_node();
      builder.AddElement(ElementType::kTetrahedron, std::vector<std::int64_t>{i, j, p, q});
    }
  }
  const absl::StatusOr<Mesh> mesh = std::move(builder).Build();
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  const std::vector<std::uint8_t> selected(mesh->node_count(), 1);
  EXPECT_EQ(ColourNodes(*mesh, selected).colour_count(), kClique);
  ExpectFirstFit(*mesh, selected);
}

TEST(ElementsByLastColourTest, EachElementUnderTheLastColourOfItsNodes) {
  auto mesh = meshgen::HybridBlock(5, 4, 4, 0.3, 7);
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  // Boundary nodes unselected, so boundary elements see fewer colours and corner elements may have
  // none (they must then be in no row).
  std::vector<std::uint8_t> selected(mesh->node_count(), 0);
  for (NodeId node = 0; node < mesh->node_count(); ++node) {
    selected[node] = mesh->is_boundary(node) ? 0 : 1;
  }
  const NodeColouring colouring = ColourNodes(*mesh, selected);
  std::vector<int> colour(mesh->node_count(), -1);
  for (int c = 0; c < colouring.colour_count(); ++c) {
    for (NodeId node : colouring.Colour(c)) colour[node] = c;
  }
  const CompressedRows rows = ElementsByLastColour(*mesh, colouring);
  ASSERT_EQ(rows.RowCount(), colouring.colour_count());
  std::vector<int> row_of(mesh->element_count(), -1);
  for (int c = 0; c < rows.RowCount(); ++c) {
    const auto elements = rows.Row(c);
    for (std::size_t i = 0; i < elements.size(); ++i) {
      if (i > 0) {
        EXPECT_LT(elements[i - 1], elements[i]) << "row " << c << " not ascending";
      }
      EXPECT_EQ(row_of[elements[i]], -1) << "element " << elements[i] << " in two rows";
      row_of[elements[i]] = c;
    }
  }
  int without_colour = 0;
  for (ElementId e = 0; e < mesh->element_count(); ++e) {
    int last = -1;
    for (NodeId node : mesh->element_nodes(e)) last = std::max(last, colour[node]);
    EXPECT_EQ(row_of[e], last) << "element " << e;
    without_colour += last < 0;
  }
  EXPECT_GT(without_colour, 0) << "the mesh should have elements with only boundary nodes";
}

}  // namespace
}  // namespace getme
