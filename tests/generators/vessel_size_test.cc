#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "getme/meshgen/thin_prism_vessel.h"
#include "mesh_checks.h"

namespace getme::meshgen {
namespace {

using ::getme::testing::CensusFaces;
using ::getme::testing::InvalidElements;

TEST(VesselSizeTest, ElementCountIsWithinTwentyPercentOfTheTarget) {
  for (const std::int64_t target : {10'000, 30'000}) {
    absl::StatusOr<Mesh> mesh = ThinPrismVessel(VesselOptionsForElements(target));
    ASSERT_TRUE(mesh.ok()) << mesh.status();
    EXPECT_NEAR(static_cast<double>(mesh->element_count()), target, 0.2 * target);
    // A longer vessel, not a finer one: the prism share stays about 60 %.
    EXPECT_NEAR(double(mesh->element_count(ElementType::kPrism)) / mesh->element_count(), 0.6,
                0.05);
  }
}

TEST(VesselSizeTest, LargeTargetsMakeLongerVesselsOfSegmentsUpToTheLimit) {
  const ThinPrismVesselOptions small = VesselOptionsForElements(50'000);
  const ThinPrismVesselOptions large = VesselOptionsForElements(10'000'000);
  EXPECT_EQ(small.segments, 1);
  EXPECT_EQ(large.segments, 100);
  EXPECT_NEAR(large.length / small.length, 200.0, 1e-9);
  EXPECT_EQ(large.mesh_size, ThinPrismVesselOptions{}.mesh_size);
  EXPECT_EQ(large.bend_angle, 0.0);
  // The cross-section and layers come from the base options.
  ThinPrismVesselOptions base;
  base.layers = 3;
  base.mesh_size = 0.3;
  const ThinPrismVesselOptions custom = VesselOptionsForElements(50'000, base);
  EXPECT_EQ(custom.layers, 3);
  EXPECT_EQ(custom.mesh_size, 0.3);
}

// Three copies of a segment: valid, joined without seams (no boundary face inside the vessel),
// each copy with the same tetrahedra and wall triangles.
TEST(VesselSizeTest, StackedSegmentsJoinIntoOneConformingVessel) {
  ThinPrismVesselOptions options;
  options.mesh_size = 0.4;
  options.length = 6.0;
  options.segments = 3;
  absl::StatusOr<Mesh> mesh = ThinPrismVessel(options);
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  EXPECT_TRUE(InvalidElements(*mesh).empty());
  EXPECT_EQ(mesh->element_count(ElementType::kTetrahedron) % 3, 0);
  EXPECT_EQ(mesh->element_count(ElementType::kPrism) % (3 * options.layers), 0);
  std::int64_t bottom = 0, top = 0, outer = 0, other = 0;
  for (const auto& [key, face_use] : CensusFaces(*mesh)) {
    // A plain reference: clang 14 cannot capture a structured binding in the lambdas below.
    const auto& use = face_use;
    ASSERT_LE(use.elements.size(), 2u);
    if (use.elements.size() == 2) continue;
    // Layer nodes over the caps' rims leave the cap plane slightly: the wall normals there are
    // averaged over tilted triangles (thin_prism_vessel_test.cc allows the same).
    const auto all_z = [&](double z) {
      return std::all_of(use.nodes.begin(), use.nodes.end(), [&](NodeId n) {
        return std::abs(mesh->z()[n] - z) < 0.05 * options.mesh_size;
      });
    };
    const bool outside = std::all_of(use.nodes.begin(), use.nodes.end(), [&](NodeId n) {
      return std::hypot(mesh->x()[n], mesh->y()[n]) > options.radius * (1.0 + 1e-3);
    });
    if (all_z(0.0)) {
      ++bottom;
    } else if (all_z(options.length)) {
      ++top;
    } else if (use.nodes.size() == 3 && outside) {
      ++outer;
    } else {
      ++other;
    }
  }
  EXPECT_GT(bottom, 0);
  EXPECT_EQ(top, bottom);  // the caps are triangulated alike
  EXPECT_EQ(outer, mesh->element_count(ElementType::kPrism) / options.layers);
  EXPECT_EQ(other, 0);
  // One gmsh segment of a third of the length holds a third of the tetrahedra (the same
  // geometry, only its caps constrained to match).
  ThinPrismVesselOptions single = options;
  single.length = 2.0;
  single.segments = 1;
  absl::StatusOr<Mesh> segment = ThinPrismVessel(single);
  ASSERT_TRUE(segment.ok()) << segment.status();
  EXPECT_NEAR(double(mesh->element_count(ElementType::kTetrahedron)) / 3,
              double(segment->element_count(ElementType::kTetrahedron)),
              0.15 * segment->element_count(ElementType::kTetrahedron));
}

TEST(VesselSizeTest, SegmentsNeedAStraightVessel) {
  ThinPrismVesselOptions options;
  options.segments = 2;
  options.bend_angle = 0.5;
  EXPECT_EQ(ThinPrismVessel(options).status().code(), absl::StatusCode::kInvalidArgument);
  options.bend_angle = 0.0;
  options.segments = 0;
  EXPECT_EQ(ThinPrismVessel(options).status().code(), absl::StatusCode::kInvalidArgument);
}

}  // namespace
}  // namespace getme::meshgen
