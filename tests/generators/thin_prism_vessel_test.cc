#include "getme/meshgen/thin_prism_vessel.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <set>
#include <utility>
#include <vector>

#include "mesh_checks.h"

namespace getme::meshgen {
namespace {

using ::getme::NodePosition;
using ::getme::testing::CensusFaces;
using ::getme::testing::InvalidElements;
using ::getme::testing::MeanRatios;

std::vector<NodeId> SortedTriangle(std::span<const NodeId> nodes, int first) {
  std::vector<NodeId> key(nodes.begin() + first, nodes.begin() + first + 3);
  std::sort(key.begin(), key.end());
  return key;
}

// One generated vessel shared by the tests: gmsh meshing is the slow part.
class ThinPrismVesselTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    absl::StatusOr<Mesh> generated = ThinPrismVessel(ThinPrismVesselOptions{});
    ASSERT_TRUE(generated.ok()) << generated.status();
    mesh_ = new Mesh(*std::move(generated));
  }
  static void TearDownTestSuite() {
    delete mesh_;
    mesh_ = nullptr;
  }
  static const Mesh* mesh_;
};
const Mesh* ThinPrismVesselTest::mesh_ = nullptr;

TEST_F(ThinPrismVesselTest, HasTetrahedraAndPrismsOnlyAndATestSizedCount) {
  const Mesh& mesh = *mesh_;
  const std::int64_t tets = mesh.element_count(ElementType::kTetrahedron);
  const std::int64_t prisms = mesh.element_count(ElementType::kPrism);
  EXPECT_GT(tets, 1000);
  EXPECT_GT(prisms, 1000);
  EXPECT_EQ(mesh.element_count(ElementType::kHexahedron), 0);
  EXPECT_EQ(mesh.element_count(ElementType::kPyramid), 0);
  EXPECT_EQ(prisms % 6, 0) << "six layers of the same wall triangles";
  EXPECT_GE(mesh.element_count(), 10000);
  EXPECT_LE(mesh.element_count(), 20000);
}

TEST_F(ThinPrismVesselTest, EveryElementIsValidAndNoNodeIsFixed) {
  EXPECT_TRUE(InvalidElements(*mesh_).empty());
  for (NodeId node = 0; node < mesh_->node_count(); ++node) {
    ASSERT_FALSE(mesh_->is_fixed(node)) << "node " << node;
  }
}

TEST_F(ThinPrismVesselTest, FacesConformTrianglesToTrianglesQuadsToQuads) {
  for (const auto& [key, use] : CensusFaces(*mesh_)) {
    ASSERT_LE(use.elements.size(), 2u) << "face shared by " << use.elements.size();
  }
}

// Walks each prism stack from the tetrahedra outward: a stack starts at a prism whose bottom is a
// tetrahedron face, continues through prisms whose bottom is the previous top, and ends at an
// outer boundary face. Every stack must be exactly `layers` = 6 prisms high, every prism
// `layer_height_ratio` × (mean wall edge length) thick along its three vertical edges.
TEST_F(ThinPrismVesselTest, PrismsFormSixLayersOfTheExpectedThickness) {
  const Mesh& mesh = *mesh_;
  std::set<std::vector<NodeId>> tet_faces;
  std::map<std::vector<NodeId>, ElementId> prism_by_bottom;
  std::vector<ElementId> prisms;
  for (ElementId e = 0; e < mesh.element_count(); ++e) {
    const auto nodes = mesh.element_nodes(e);
    if (mesh.type(e) == ElementType::kTetrahedron) {
      for (const auto& face :
           std::vector<std::array<int, 3>>{{0, 1, 2}, {0, 1, 3}, {1, 2, 3}, {0, 2, 3}}) {
        std::vector<NodeId> key = {nodes[face[0]], nodes[face[1]], nodes[face[2]]};
        std::sort(key.begin(), key.end());
        tet_faces.insert(key);
      }
    } else {
      prism_by_bottom[SortedTriangle(nodes, 0)] = e;
      prisms.push_back(e);
    }
  }
  std::vector<ElementId> stack_bases;
  for (const ElementId prism : prisms) {
    if (tet_faces.contains(SortedTriangle(mesh.element_nodes(prism), 0))) {
      stack_bases.push_back(prism);
    }
  }
  ASSERT_EQ(stack_bases.size() * 6, prisms.size());

  // Mean length of the distinct wall edges (the stack bases' bottom triangles).
  std::set<std::pair<NodeId, NodeId>> wall_edges;
  for (const ElementId base : stack_bases) {
    const auto n = mesh.element_nodes(base);
    for (int k = 0; k < 3; ++k) wall_edges.insert(std::minmax(n[k], n[(k + 1) % 3]));
  }
  double total = 0.0;
  for (const auto& [a, b] : wall_edges)
    total += (NodePosition(mesh, a) - NodePosition(mesh, b)).norm();
  const double layer_height = 0.01 * total / static_cast<double>(wall_edges.size());

  for (const ElementId base : stack_bases) {
    int height = 0;
    ElementId prism = base;
    while (true) {
      ++height;
      const auto n = mesh.element_nodes(prism);
      for (int k = 0; k < 3; ++k) {
        ASSERT_NEAR((NodePosition(mesh, n[k + 3]) - NodePosition(mesh, n[k])).norm(), layer_height,
                    1e-12)
            << "prism " << prism << " edge " << k;
      }
      const auto next = prism_by_bottom.find(SortedTriangle(n, 3));
      if (next == prism_by_bottom.end()) break;
      prism = next->second;
      ASSERT_LE(height, 6);
    }
    ASSERT_EQ(height, 6) << "stack from prism " << base;
  }
}

// The prisms wrap the lateral wall outward: the outer surface lies about radius + 6 layers from
// the axis, and every other boundary face lies on an end cap (z = 0 or z = length).
TEST_F(ThinPrismVesselTest, BoundaryIsTheOuterPrismSurfaceAndTheEndCaps) {
  const ThinPrismVesselOptions options;
  const Mesh& mesh = *mesh_;
  std::int64_t outer = 0, cap = 0, other = 0;
  const double tolerance = 0.05 * options.mesh_size;
  for (const auto& [key, face_use] : CensusFaces(mesh)) {
    // A plain reference: clang 14 cannot capture a structured binding in the lambdas below.
    const auto& use = face_use;
    if (use.elements.size() != 1) continue;
    const auto radial = [&](NodeId n) { return std::hypot(mesh.x()[n], mesh.y()[n]); };
    const bool on_outer_surface = std::all_of(use.nodes.begin(), use.nodes.end(), [&](NodeId n) {
      return radial(n) > options.radius * (1.0 + 1e-3);
    });
    const auto on_plane = [&](double z) {
      return std::all_of(use.nodes.begin(), use.nodes.end(),
                         [&](NodeId n) { return std::abs(mesh.z()[n] - z) < tolerance; });
    };
    if (use.nodes.size() == 3 && on_outer_surface) {
      ++outer;
    } else if (on_plane(0.0) || on_plane(options.length)) {
      ++cap;
    } else {
      ++other;
    }
  }
  EXPECT_EQ(outer, mesh.element_count(ElementType::kPrism) / 6);
  EXPECT_GT(cap, 0);
  EXPECT_EQ(other, 0);
}

// Thin prisms make the paper's hard case: q_min of a few hundredths, q_mean around 0.3 (paper
// aorta: 0.0413 / 0.3077), while the tetrahedra are of ordinary quality.
TEST_F(ThinPrismVesselTest, ThinPrismsHaveSmallQualityAndTetrahedraDoNot) {
  const std::vector<double> q = MeanRatios(*mesh_);
  double prism_max = 0.0, tet_sum = 0.0;
  for (ElementId e = 0; e < mesh_->element_count(); ++e) {
    if (mesh_->type(e) == ElementType::kPrism) {
      prism_max = std::max(prism_max, q[e]);
    } else {
      tet_sum += q[e];
    }
  }
  const double q_min = *std::min_element(q.begin(), q.end());
  const double q_mean = std::accumulate(q.begin(), q.end(), 0.0) / static_cast<double>(q.size());
  RecordProperty("q_min", std::to_string(q_min));
  RecordProperty("q_mean", std::to_string(q_mean));
  EXPECT_LT(prism_max, 0.15);
  EXPECT_GT(tet_sum / mesh_->element_count(ElementType::kTetrahedron), 0.6);
  EXPECT_GT(q_min, 0.005);
  EXPECT_LT(q_min, 0.1);
  EXPECT_GT(q_mean, 0.15);
  EXPECT_LT(q_mean, 0.5);
}

TEST(ThinPrismVesselDeterminismTest, SameOptionsGiveBitIdenticalMeshes) {
  ThinPrismVesselOptions options;
  options.mesh_size = 0.4;
  absl::StatusOr<Mesh> a = ThinPrismVessel(options);
  absl::StatusOr<Mesh> b = ThinPrismVessel(options);
  ASSERT_TRUE(a.ok() && b.ok());
  ASSERT_EQ(a->element_count(), b->element_count());
  EXPECT_TRUE(std::ranges::equal(a->x(), b->x()));
  EXPECT_TRUE(std::ranges::equal(a->y(), b->y()));
  EXPECT_TRUE(std::ranges::equal(a->z(), b->z()));
  for (ElementId e = 0; e < a->element_count(); ++e) {
    ASSERT_TRUE(std::ranges::equal(a->element_nodes(e), b->element_nodes(e))) << "element " << e;
  }
}

TEST(ThinPrismVesselBentTest, BentVesselIsValidWithTheRequestedLayers) {
  ThinPrismVesselOptions options;
  options.mesh_size = 0.4;
  options.bend_angle = 0.8;
  options.layers = 3;
  absl::StatusOr<Mesh> mesh = ThinPrismVessel(options);
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  EXPECT_TRUE(InvalidElements(*mesh).empty());
  EXPECT_GT(mesh->element_count(ElementType::kPrism), 0);
  EXPECT_EQ(mesh->element_count(ElementType::kPrism) % 3, 0);
}

TEST(ThinPrismVesselOptionsTest, RejectsNonPositiveSizesNamingTheField) {
  ThinPrismVesselOptions options;
  options.mesh_size = 0.0;
  absl::Status status = ThinPrismVessel(options).status();
  EXPECT_EQ(status.code(), absl::StatusCode::kInvalidArgument);
  EXPECT_NE(status.message().find("mesh_size"), std::string_view::npos) << status;
  options = {};
  options.layer_height_ratio = -1.0;
  status = ThinPrismVessel(options).status();
  EXPECT_EQ(status.code(), absl::StatusCode::kInvalidArgument);
  EXPECT_NE(status.message().find("layer_height_ratio"), std::string_view::npos) << status;
}

}  // namespace
}  // namespace getme::meshgen
