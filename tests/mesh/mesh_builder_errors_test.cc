// MeshBuilder::Build rejects malformed input with InvalidArgument and a message naming the element
// (by insertion index and type) or node at fault.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "absl/strings/str_cat.h"
#include "getme/mesh/mesh.h"
#include "getme/mesh/mesh_quality.h"
#include "getme/parallel/thread_pool.h"

namespace getme {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;
using ::testing::Not;

// Nodes of the unit cube in hex order, so elements can be made from them.
MeshBuilder CubeNodes() {
  MeshBuilder builder;
  const double corners[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  for (const auto& c : corners) builder.AddNode(c[0], c[1], c[2]);
  return builder;
}

void AddElement(MeshBuilder& builder, ElementType type, std::vector<std::int64_t> nodes) {
  builder.AddElement(type, nodes);
}

std::string Message(const absl::StatusOr<Mesh>& mesh) {
  return std::string(mesh.status().message());
}

TEST(MeshBuilderErrors, NoNodesAndNoElementsIsAnEmptyMesh) {
  const absl::StatusOr<Mesh> mesh = MeshBuilder().Build();
  ASSERT_EQ(mesh.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(Message(mesh), AllOf(HasSubstr("empty mesh"), HasSubstr("0 nodes")));
}

TEST(MeshBuilderErrors, NodesWithoutElementsIsAnEmptyMesh) {
  const absl::StatusOr<Mesh> mesh = CubeNodes().Build();
  ASSERT_EQ(mesh.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(Message(mesh),
              AllOf(HasSubstr("empty mesh"), HasSubstr("8 nodes"), HasSubstr("0 volume elements")));
}

TEST(MeshBuilderErrors, ElementsWithoutNodesIsAnEmptyMesh) {
  MeshBuilder builder;
  AddElement(builder, ElementType::kTetrahedron, {0, 1, 2, 3});
  const absl::StatusOr<Mesh> mesh = std::move(builder).Build();
  ASSERT_EQ(mesh.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(Message(mesh), AllOf(HasSubstr("empty mesh"), HasSubstr("0 nodes")));
}

// The bad element is the third inserted but the second hexahedron: the message must use its
// global (insertion) index, not its position in the hexahedron block.
TEST(MeshBuilderErrors, NegativeNodeIdNamesElementLocalNodeAndId) {
  MeshBuilder builder = CubeNodes();
  AddElement(builder, ElementType::kTetrahedron, {0, 1, 3, 4});
  AddElement(builder, ElementType::kHexahedron, {0, 1, 2, 3, 4, 5, 6, 7});
  AddElement(builder, ElementType::kHexahedron, {0, 1, 2, -1, 4, 5, 6, 7});
  const absl::StatusOr<Mesh> mesh = std::move(builder).Build();
  ASSERT_EQ(mesh.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(Message(mesh), AllOf(HasSubstr("element 2 (hexahedron)"), HasSubstr("node 3"),
                                   HasSubstr("id -1"), HasSubstr("[0, 8)")));
}

TEST(MeshBuilderErrors, NodeIdEqualToNodeCountIsOutOfRange) {
  MeshBuilder builder = CubeNodes();
  AddElement(builder, ElementType::kPyramid, {0, 1, 2, 3, 8});
  const absl::StatusOr<Mesh> mesh = std::move(builder).Build();
  ASSERT_EQ(mesh.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(Message(mesh), AllOf(HasSubstr("element 0 (pyramid)"), HasSubstr("node 4"),
                                   HasSubstr("id 8"), HasSubstr("out of range")));
}

TEST(MeshBuilderErrors, HugeNodeIdIsOutOfRangeNotTruncated) {
  MeshBuilder builder = CubeNodes();
  const std::int64_t huge = std::int64_t{1} << 32;  // would alias node 0 if cut to 32 bits
  AddElement(builder, ElementType::kTetrahedron, {huge, 1, 3, 4});
  const absl::StatusOr<Mesh> mesh = std::move(builder).Build();
  ASSERT_EQ(mesh.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(Message(mesh), AllOf(HasSubstr("element 0 (tetrahedron)"), HasSubstr("node 0"),
                                   HasSubstr("id 4294967296")));
}

TEST(MeshBuilderErrors, TooFewNodesForTheTypeNamesGivenAndExpectedCounts) {
  MeshBuilder builder = CubeNodes();
  AddElement(builder, ElementType::kTetrahedron, {0, 1, 3, 4});
  AddElement(builder, ElementType::kPrism, {0, 1, 2, 4, 5});
  const absl::StatusOr<Mesh> mesh = std::move(builder).Build();
  ASSERT_EQ(mesh.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(Message(mesh), AllOf(HasSubstr("element 1 (prism)"), HasSubstr("has 5 nodes"),
                                   HasSubstr("expected 6")));
}

TEST(MeshBuilderErrors, TooManyNodesForTheTypeNamesGivenAndExpectedCounts) {
  MeshBuilder builder = CubeNodes();
  AddElement(builder, ElementType::kTetrahedron, {0, 1, 3, 4, 5});
  const absl::StatusOr<Mesh> mesh = std::move(builder).Build();
  ASSERT_EQ(mesh.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(Message(mesh), AllOf(HasSubstr("element 0 (tetrahedron)"), HasSubstr("has 5 nodes"),
                                   HasSubstr("expected 4")));
}

TEST(MeshBuilderErrors, RepeatedNodeNamesElementNodeAndBothLocalPositions) {
  MeshBuilder builder = CubeNodes();
  AddElement(builder, ElementType::kHexahedron, {0, 1, 2, 3, 4, 5, 6, 7});
  AddElement(builder, ElementType::kPyramid, {0, 3, 2, 1, 3});
  const absl::StatusOr<Mesh> mesh = std::move(builder).Build();
  ASSERT_EQ(mesh.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(Message(mesh), AllOf(HasSubstr("element 1 (pyramid)"), HasSubstr("node 3 twice"),
                                   HasSubstr("local nodes 1 and 4")));
}

// The same hexahedron again, its nodes listed from the top face: its outer faces would count two
// elements each and drop out of the boundary.
TEST(MeshBuilderErrors, RepeatedElementNamesBothElementsAndTheNodes) {
  MeshBuilder builder = CubeNodes();
  builder.AddNode(0.5, 0.5, -1.0);
  AddElement(builder, ElementType::kHexahedron, {0, 1, 2, 3, 4, 5, 6, 7});
  AddElement(builder, ElementType::kPyramid, {0, 3, 2, 1, 8});
  AddElement(builder, ElementType::kHexahedron, {4, 5, 6, 7, 0, 1, 2, 3});
  const absl::StatusOr<Mesh> mesh = std::move(builder).Build();
  ASSERT_EQ(mesh.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(Message(mesh), AllOf(HasSubstr("element 2 (hexahedron) repeats element 0"),
                                   HasSubstr("{0, 1, 2, 3, 4, 5, 6, 7}")));
}

// Elements sharing all but one node are neighbours, not repeats.
TEST(MeshBuilderErrors, TetrahedraSharingThreeNodesAreNoRepeat) {
  MeshBuilder builder = CubeNodes();
  AddElement(builder, ElementType::kTetrahedron, {0, 1, 3, 4});
  AddElement(builder, ElementType::kTetrahedron, {1, 3, 4, 6});
  EXPECT_TRUE(std::move(builder).Build().ok());
}

// Three tetrahedra on one triangle (two above it, overlapping, one below).
TEST(MeshBuilderErrors, FaceOfThreeElementsNamesTheFaceAndTheElements) {
  MeshBuilder builder;
  for (const auto& p : std::vector<std::array<double, 3>>{
           {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.3, 0.3, 1}, {0.3, 0.3, -1}, {0.2, 0.2, 0.5}}) {
    builder.AddNode(p[0], p[1], p[2]);
  }
  AddElement(builder, ElementType::kTetrahedron, {0, 1, 2, 3});
  AddElement(builder, ElementType::kTetrahedron, {0, 2, 1, 4});
  AddElement(builder, ElementType::kTetrahedron, {0, 1, 2, 5});
  const absl::StatusOr<Mesh> mesh = std::move(builder).Build();
  ASSERT_EQ(mesh.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(Message(mesh), AllOf(HasSubstr("face with nodes {0, 1, 2} belongs to 3 elements"),
                                   HasSubstr("(0 (tetrahedron), 1 (tetrahedron), 2 (tetrahedron))"),
                                   HasSubstr("overlap")));
}

// The same overlap twice, the face with the higher node ids added first: the error names the
// face with the lowest ids, whatever order the boundary search meets them in.
TEST(MeshBuilderErrors, OfTwoOverlapsTheFaceWithTheLowestNodeIdsIsNamed) {
  MeshBuilder builder;
  for (const double shift : {0.0, 5.0}) {
    for (const auto& p : std::vector<std::array<double, 3>>{
             {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.3, 0.3, 1}, {0.3, 0.3, -1}, {0.2, 0.2, 0.5}}) {
      builder.AddNode(p[0] + shift, p[1], p[2]);
    }
  }
  for (const std::int64_t first : {6, 0}) {
    AddElement(builder, ElementType::kTetrahedron, {first, first + 1, first + 2, first + 3});
    AddElement(builder, ElementType::kTetrahedron, {first, first + 2, first + 1, first + 4});
    AddElement(builder, ElementType::kTetrahedron, {first, first + 1, first + 2, first + 5});
  }
  const absl::StatusOr<Mesh> mesh = std::move(builder).Build();
  ASSERT_EQ(mesh.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(Message(mesh),
              AllOf(HasSubstr("face with nodes {0, 1, 2} belongs to 3 elements"),
                    HasSubstr("(3 (tetrahedron), 4 (tetrahedron), 5 (tetrahedron))")));
}

// An n × n × n grid of unit cubes, each split into six tetrahedra around its main diagonal
// (conforming: neighbouring cubes split their shared face the same way).
MeshBuilder TetrahedralGrid(int n) {
  MeshBuilder builder;
  const auto id = [n](int i, int j, int k) -> std::int64_t {
    return (static_cast<std::int64_t>(k) * (n + 1) + j) * (n + 1) + i;
  };
  for (int k = 0; k <= n; ++k) {
    for (int j = 0; j <= n; ++j) {
      for (int i = 0; i <= n; ++i) builder.AddNode(i, j, k);
    }
  }
  // Paths from corner 0 to corner 7 of the cube, one axis at a time: each gives a tetrahedron.
  constexpr std::array<std::array<int, 3>, 6> kAxisOrders = {
      {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};
  for (int k = 0; k < n; ++k) {
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) {
        for (const auto& order : kAxisOrders) {
          std::array<int, 3> at = {i, j, k};
          std::vector<std::int64_t> nodes = {id(at[0], at[1], at[2])};
          for (const int axis : order) {
            ++at[axis];
            nodes.push_back(id(at[0], at[1], at[2]));
          }
          builder.AddElement(ElementType::kTetrahedron, nodes);
        }
      }
    }
  }
  return builder;
}

// On a mesh of tens of thousands of elements, where many elements share the sum of their node
// ids (Build's repeat search groups elements by a hash of their nodes first), a repeat far from
// its original is found, and of two repeats the one added first is named.
TEST(MeshBuilderErrors, RepeatsInALargeMeshAreFoundAndTheFirstIsNamed) {
  constexpr int kCubes = 16;  // 24,576 tetrahedra
  EXPECT_TRUE(TetrahedralGrid(kCubes).Build().ok());
  MeshBuilder builder = TetrahedralGrid(kCubes);
  // Element 17 and element 20,000, each again with its nodes in another order.
  const std::int64_t base = 6 * kCubes * kCubes * kCubes;
  MeshBuilder probe = TetrahedralGrid(kCubes);
  const absl::StatusOr<Mesh> grid = std::move(probe).Build();
  ASSERT_TRUE(grid.ok());
  for (const ElementId original : {20000, 17}) {
    const std::span<const NodeId> nodes = grid->element_nodes(original);
    builder.AddElement(ElementType::kTetrahedron,
                       std::vector<std::int64_t>{nodes[3], nodes[1], nodes[0], nodes[2]});
  }
  const absl::StatusOr<Mesh> mesh = std::move(builder).Build();
  ASSERT_EQ(mesh.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(Message(mesh),
              HasSubstr(absl::StrCat("element ", base, " (tetrahedron) repeats element 20000")));
}

struct NonFiniteCase {
  const char* name;
  int axis;
  double value;
};

class MeshBuilderNonFinite : public ::testing::TestWithParam<NonFiniteCase> {};

TEST_P(MeshBuilderNonFinite, NamesTheNodeWithTheBadCoordinate) {
  MeshBuilder builder = CubeNodes();
  double p[3] = {2, 2, 2};
  p[GetParam().axis] = GetParam().value;
  builder.AddNode(p[0], p[1], p[2]);  // node 8
  AddElement(builder, ElementType::kTetrahedron, {0, 1, 3, 4});
  const absl::StatusOr<Mesh> mesh = std::move(builder).Build();
  ASSERT_EQ(mesh.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(Message(mesh), AllOf(HasSubstr("node 8 "), HasSubstr("non-finite")));
  // It is the unused node 8 that is at fault, not any element.
  EXPECT_THAT(Message(mesh), Not(HasSubstr("element")));
}

INSTANTIATE_TEST_SUITE_P(
    Coordinates, MeshBuilderNonFinite,
    ::testing::Values(NonFiniteCase{"NanX", 0, std::numeric_limits<double>::quiet_NaN()},
                      NonFiniteCase{"NanZ", 2, std::numeric_limits<double>::quiet_NaN()},
                      NonFiniteCase{"PlusInfY", 1, std::numeric_limits<double>::infinity()},
                      NonFiniteCase{"MinusInfZ", 2, -std::numeric_limits<double>::infinity()}),
    [](const ::testing::TestParamInfo<NonFiniteCase>& info) { return info.param.name; });

TEST(MeshBuilderErrors, NegativeFixedNodeIdIsOutOfRange) {
  MeshBuilder builder = CubeNodes();
  AddElement(builder, ElementType::kHexahedron, {0, 1, 2, 3, 4, 5, 6, 7});
  builder.SetFixed(-1);
  const absl::StatusOr<Mesh> mesh = std::move(builder).Build();
  ASSERT_EQ(mesh.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(Message(mesh), AllOf(HasSubstr("fixed node id -1"), HasSubstr("[0, 8)")));
}

TEST(MeshBuilderErrors, FixedNodeIdEqualToNodeCountIsOutOfRange) {
  MeshBuilder builder = CubeNodes();
  AddElement(builder, ElementType::kHexahedron, {0, 1, 2, 3, 4, 5, 6, 7});
  builder.SetFixed(3);
  builder.SetFixed(8);
  const absl::StatusOr<Mesh> mesh = std::move(builder).Build();
  ASSERT_EQ(mesh.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(Message(mesh), AllOf(HasSubstr("fixed node id 8"), HasSubstr("out of range")));
}

}  // namespace
}  // namespace getme

namespace getme {
namespace {

// A slightly skewed hexahedron (q < 1) scaled by `scale`, as a one-element mesh.
absl::StatusOr<Mesh> ScaledHex(double scale, double offset = 0.0) {
  MeshBuilder builder;
  const double corners[8][3] = {{0, 0, 0}, {1, 0, 0}, {1.2, 1, 0}, {0, 1, 0},
                                {0, 0, 1}, {1, 0, 1}, {1, 1, 1.3}, {0, 1, 1}};
  for (const auto& c : corners) {
    builder.AddNode(c[0] * scale + offset, c[1] * scale + offset, c[2] * scale + offset);
  }
  const std::vector<std::int64_t> nodes = {0, 1, 2, 3, 4, 5, 6, 7};
  builder.AddElement(ElementType::kHexahedron, nodes);
  return std::move(builder).Build();
}

TEST(MeshBuilderErrors, ACoordinateBeyondTheComputableRangeNamesTheNode) {
  const absl::StatusOr<Mesh> mesh = ScaledHex(1.0, -1e41);
  ASSERT_EQ(mesh.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(Message(mesh), HasSubstr("node 0 has a coordinate of magnitude 1e+41, beyond 1e+40"));
  EXPECT_THAT(Message(mesh), HasSubstr("rescale or translate the mesh"));
}

TEST(MeshBuilderErrors, AnElementTooSmallToEvaluateNamesTheElement) {
  const absl::StatusOr<Mesh> mesh = ScaledHex(1e-41);
  ASSERT_EQ(mesh.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(Message(mesh), HasSubstr("element 0 (hexahedron) spans only 1.3e-41, below 1e-40"));
}

TEST(MeshBuilderErrors, ACollapsedElementIsAcceptedAsInvalidNotRefused) {
  const absl::StatusOr<Mesh> mesh = ScaledHex(0.0, 5.0);
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  ThreadPool pool(1);
  EXPECT_EQ(EvaluateMeshQuality(*mesh, pool).invalid, 1);
}

// The accepted range is one where the mean ratio is still scale-invariant (beyond about 1e±51 it
// silently read 1 or 0 before the bounds existed): near the bounds it equals the unit-scale value.
TEST(MeshBuilderErrors, QualityIsScaleInvariantAcrossTheAcceptedRange) {
  ThreadPool pool(1);
  const absl::StatusOr<Mesh> unit = ScaledHex(1.0);
  ASSERT_TRUE(unit.ok());
  const double q = EvaluateMeshQuality(*unit, pool).q_min;
  ASSERT_GT(q, 0.5);
  ASSERT_LT(q, 0.99);
  for (double scale : {1e-39, 1e-20, 1e20, 1e39}) {
    const absl::StatusOr<Mesh> scaled = ScaledHex(scale);
    ASSERT_TRUE(scaled.ok()) << scale << ": " << scaled.status();
    EXPECT_NEAR(EvaluateMeshQuality(*scaled, pool).q_min, q, 1e-12) << scale;
  }
}

}  // namespace
}  // namespace getme
