#include "getme/meshgen/hybrid_block.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "mesh_checks.h"

namespace getme::meshgen {
namespace {

using ::getme::testing::CheckBlockFaces;
using ::getme::testing::InvalidElements;
using ::getme::testing::MeanRatios;

struct ExpectedCounts {
  int nx, ny, nz;
  std::int64_t hexahedra, prisms, pyramids, tetrahedra, nodes;
};

// Derived by hand from the documented layout (hybrid_block.h):
// 6×6×6: hex layer k=0, prism layer k=5, centred-tet layers k=1..4; islands at k=2 (offset 1,
//   not the top tet layer), i,j ∈ {1,4}: 4 islands, each with 6 centred-tet neighbours.
//   hex 36+4, prisms 2·36, tet cubes 4·36−4 = 140, pyramids 36 (over the hex layer) + 4·6,
//   tetrahedra 2·(6·140 − 60) = 1560, nodes 7³ + 140.
// 5×4×8: hex layers k=0,1, prism layers k=6,7, tet layers k=2..5; islands at k=3 with i ∈ {1,4},
//   j = 1: (1,1,3) has 6 tet neighbours, (4,1,3) sits on the x = 5 face and has 5.
//   hex 40+2, prisms 2·2·20, tet cubes 80−2 = 78, pyramids 20+6+5 = 31,
//   tetrahedra 2·(6·78 − 31) = 874, nodes 6·5·9 + 78.
constexpr ExpectedCounts kCases[] = {
    {6, 6, 6, 40, 72, 60, 1560, 343 + 140},
    {5, 4, 8, 42, 80, 31, 874, 270 + 78},
};

TEST(HybridBlockTest, ElementCountsPerTypeMatchTheLayout) {
  for (const ExpectedCounts& c : kCases) {
    absl::StatusOr<Mesh> mesh = HybridBlock(c.nx, c.ny, c.nz, 0.3, 1);
    ASSERT_TRUE(mesh.ok()) << mesh.status();
    SCOPED_TRACE(::testing::Message() << c.nx << "x" << c.ny << "x" << c.nz);
    EXPECT_EQ(mesh->element_count(ElementType::kHexahedron), c.hexahedra);
    EXPECT_EQ(mesh->element_count(ElementType::kPrism), c.prisms);
    EXPECT_EQ(mesh->element_count(ElementType::kPyramid), c.pyramids);
    EXPECT_EQ(mesh->element_count(ElementType::kTetrahedron), c.tetrahedra);
    EXPECT_EQ(mesh->node_count(), c.nodes);
  }
}

TEST(HybridBlockTest, UndistortedAndDistortedElementsAreAllValid) {
  for (const double distortion : {0.0, 0.3, 1.0}) {
    absl::StatusOr<Mesh> mesh = HybridBlock(6, 5, 7, distortion, 4);
    ASSERT_TRUE(mesh.ok()) << mesh.status();
    EXPECT_TRUE(InvalidElements(*mesh).empty()) << "distortion " << distortion;
  }
}

TEST(HybridBlockTest, FacesConformAcrossAllElementTypes) {
  for (const ExpectedCounts& c : kCases) {
    absl::StatusOr<Mesh> mesh = HybridBlock(c.nx, c.ny, c.nz, 0.35, 17);
    ASSERT_TRUE(mesh.ok()) << mesh.status();
    SCOPED_TRACE(::testing::Message() << c.nx << "x" << c.ny << "x" << c.nz);
    const auto report = CheckBlockFaces(*mesh, c.nx, c.ny, c.nz);
    EXPECT_EQ(report.overused_faces, 0);
    // A triangle meeting a quad, or two different diagonals, leaves unmatched inner faces.
    EXPECT_EQ(report.inner_boundary_faces, 0);
    const double box_area = 2.0 * (c.nx * c.ny + c.ny * c.nz + c.nz * c.nx);
    EXPECT_NEAR(report.boundary_area, box_area, 1e-9);
    // Face incidences: every element's faces are either shared (counted twice) or boundary.
    const std::int64_t incidences =
        4 * c.tetrahedra + 6 * c.hexahedra + 5 * c.pyramids + 5 * c.prisms;
    EXPECT_EQ(2 * report.shared_faces + report.boundary_faces, incidences);
  }
}

TEST(HybridBlockTest, DistortionLowersQualityButKeepsBoundaryNodesOnTheBox) {
  absl::StatusOr<Mesh> regular = HybridBlock(6, 6, 6, 0.0, 1);
  absl::StatusOr<Mesh> distorted = HybridBlock(6, 6, 6, 0.4, 1);
  ASSERT_TRUE(regular.ok() && distorted.ok());
  const std::vector<double> q0 = MeanRatios(*regular);
  const std::vector<double> q1 = MeanRatios(*distorted);
  EXPECT_LT(*std::min_element(q1.begin(), q1.end()), *std::min_element(q0.begin(), q0.end()));
  // Grid nodes on the box surface keep their integer coordinates.
  for (int k = 0; k <= 6; ++k) {
    for (int j = 0; j <= 6; ++j) {
      for (int i = 0; i <= 6; ++i) {
        if (i != 0 && j != 0 && k != 0 && i != 6 && j != 6 && k != 6) continue;
        const NodeId node = i + 7 * (j + 7 * k);
        EXPECT_EQ(distorted->x()[node], i);
        EXPECT_EQ(distorted->y()[node], j);
        EXPECT_EQ(distorted->z()[node], k);
      }
    }
  }
}

TEST(HybridBlockTest, SameSeedGivesBitIdenticalCoordinates) {
  absl::StatusOr<Mesh> a = HybridBlock(5, 5, 6, 0.4, 12345);
  absl::StatusOr<Mesh> b = HybridBlock(5, 5, 6, 0.4, 12345);
  ASSERT_TRUE(a.ok() && b.ok());
  EXPECT_TRUE(std::ranges::equal(a->x(), b->x()));
  EXPECT_TRUE(std::ranges::equal(a->y(), b->y()));
  EXPECT_TRUE(std::ranges::equal(a->z(), b->z()));
}

TEST(HybridBlockTest, RejectsGridsTooFlatForThreeLayerKinds) {
  const absl::Status status = HybridBlock(4, 4, 2, 0.1, 1).status();
  EXPECT_EQ(status.code(), absl::StatusCode::kInvalidArgument);
  EXPECT_NE(status.message().find("nz"), std::string_view::npos) << status;
}

}  // namespace
}  // namespace getme::meshgen
