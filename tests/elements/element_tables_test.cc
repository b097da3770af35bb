// The library's compile-time tables (core/getme/elements/element_tables.h) against the paper's
// tables typed in independently (paper_tables.h): F, F̄, N, W⁻¹ and the edge lists.

#include "getme/elements/element_tables.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <utility>
#include <vector>

#include "element_type_tags.h"
#include "paper_tables.h"

namespace getme::test {
namespace {

template <typename Tag>
class ElementTablesTest : public ::testing::Test {};
TYPED_TEST_SUITE(ElementTablesTest, AllElementTypes, ElementTypeName);

template <typename Faces>
std::vector<IndexTuple> ToTuples(const Faces& faces) {
  std::vector<IndexTuple> tuples;
  for (const FaceIndices& face : faces) {
    tuples.emplace_back(face.nodes.begin(), face.nodes.begin() + face.size);
  }
  return tuples;
}

TYPED_TEST(ElementTablesTest, NodeCountMatchesPaper) {
  constexpr ElementType kType = TypeParam::kType;
  EXPECT_EQ(ElementTable<kType>::kNodes, Paper(kType).node_count);
  EXPECT_EQ(NodeCount(kType), Paper(kType).node_count);
}

TYPED_TEST(ElementTablesTest, FacesMatchPaper) {
  constexpr ElementType kType = TypeParam::kType;
  EXPECT_EQ(ToTuples(ElementTable<kType>::kFaces), Paper(kType).faces);
}

TYPED_TEST(ElementTablesTest, DualFacesMatchPaper) {
  constexpr ElementType kType = TypeParam::kType;
  EXPECT_EQ(ToTuples(ElementTable<kType>::kDualFaces), Paper(kType).dual_faces);
}

TYPED_TEST(ElementTablesTest, NodeTetrahedraMatchPaper) {
  constexpr ElementType kType = TypeParam::kType;
  std::vector<IndexTuple> node_tets;
  for (const NodeTetIndices& t : ElementTable<kType>::kNodeTets) {
    node_tets.emplace_back(t.begin(), t.end());
  }
  EXPECT_EQ(node_tets, Paper(kType).node_tets);
}

TYPED_TEST(ElementTablesTest, TargetInverseTimesPaperTargetIsIdentity) {
  constexpr ElementType kType = TypeParam::kType;
  Eigen::Matrix3d target_inverse;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) target_inverse(i, j) = ElementTable<kType>::kTargetInverse[i][j];
  }
  const Eigen::Matrix3d product = Paper(kType).target * target_inverse;
  EXPECT_LT((product - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff(), 1e-15) << "W · W⁻¹ =\n"
                                                                                  << product;
}

TYPED_TEST(ElementTablesTest, EdgesAreTheFaceBoundaryEdges) {
  constexpr ElementType kType = TypeParam::kType;
  std::vector<std::pair<int, int>> library_edges;
  for (const EdgeIndices& edge : ElementTable<kType>::kEdges) {
    library_edges.emplace_back(std::min(edge[0], edge[1]), std::max(edge[0], edge[1]));
  }
  std::vector<std::pair<int, int>> paper_edges = PaperEdges(kType);
  std::sort(library_edges.begin(), library_edges.end());
  std::sort(paper_edges.begin(), paper_edges.end());
  EXPECT_EQ(library_edges, paper_edges);
}

TEST(PaperEdgesTest, CountsAreThoseOfTheGeometricElements) {
  EXPECT_EQ(PaperEdges(ElementType::kTetrahedron).size(), 6u);
  EXPECT_EQ(PaperEdges(ElementType::kHexahedron).size(), 12u);
  EXPECT_EQ(PaperEdges(ElementType::kPyramid).size(), 8u);
  EXPECT_EQ(PaperEdges(ElementType::kPrism).size(), 9u);
}

}  // namespace
}  // namespace getme::test
