// MEDIT's node order per element type, established with files written by gmsh's and meshio's
// own MEDIT writers: a regular element of each type (unit edges, oriented per
// docs/node-orders.md) must read back valid with mean ratio 1 through GridToMesh and the core
// kernels.

#include <gtest/gtest.h>

#include <cmath>
#include <ostream>
#include <string>

#include "formats/grid_mesh.h"
#include "formats/medit/medit_reader.h"
#include "getme/elements/element_quality.h"
#include "medit_test_util.h"
#include "vtk_test_util.h"

namespace getme::formats {
namespace {

using testing::ExpectContent;
using testing::ExpectedContent;
using testing::FixturePath;
using testing::ReadExpected;
using testing::ReadText;

struct RegularCase {
  const char* file;  // fixture name without extension
  int vtk_type;
  ElementType element_type;
};

void PrintTo(const RegularCase& param, std::ostream* out) { *out << param.file; }

class MeditRegularElementTest : public ::testing::TestWithParam<RegularCase> {};

TEST_P(MeditRegularElementTest, ReadsBackValidWithMeanRatioOne) {
  const RegularCase& param = GetParam();
  const std::string text = ReadText(FixturePath(std::string(param.file) + ".mesh"));
  ASSERT_FALSE(text.empty()) << "missing fixture " << param.file;
  const absl::StatusOr<MeshDocument> document = ParseMedit(text);
  ASSERT_TRUE(document.ok()) << document.status();

  ExpectedContent expected;
  std::string error;
  ASSERT_TRUE(ReadExpected(FixturePath(std::string(param.file) + ".expected"), &expected, &error))
      << error;
  ExpectContent(expected, document->grid);
  ASSERT_EQ(document->grid.cells.size(), 1);
  EXPECT_EQ(document->grid.cells.types[0], param.vtk_type);

  const absl::StatusOr<GridMesh> mesh = GridToMesh(document->grid);
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  ASSERT_EQ(mesh->mesh.element_count(), 1);
  EXPECT_EQ(mesh->mesh.type(0), param.element_type);
  DispatchElementType(mesh->mesh.type(0), [&]<ElementType kType>() {
    const auto nodes = GatherNodes<kType>(mesh->mesh, mesh->mesh.element_nodes(0).data());
    EXPECT_TRUE(IsValid<kType>(nodes));
    EXPECT_NEAR(MeanRatio<kType>(nodes), 1.0, 1e-12);
  });
}

INSTANTIATE_TEST_SUITE_P(
    WrittenByMeshioAndGmsh, MeditRegularElementTest,
    ::testing::Values(RegularCase{"regular_meshio_tetra", 10, ElementType::kTetrahedron},
                      RegularCase{"regular_meshio_hexahedron", 12, ElementType::kHexahedron},
                      RegularCase{"regular_meshio_pyramid", 14, ElementType::kPyramid},
                      RegularCase{"regular_meshio_wedge", 13, ElementType::kPrism},
                      // gmsh's MEDIT writer drops prisms and pyramids (GModelIO_MESH.cpp).
                      RegularCase{"regular_gmsh_tetra", 10, ElementType::kTetrahedron},
                      RegularCase{"regular_gmsh_hexahedron", 12, ElementType::kHexahedron}),
    [](const ::testing::TestParamInfo<RegularCase>& info) { return std::string(info.param.file); });

// A regular prism in Gmsh's order (bottom counter-clockwise seen from the top), hand-written.
constexpr char kRegularPrismGmshOrder[] = R"(MeshVersionFormatted 2
Dimension 3
Vertices
6
0 0 0 0
1 0 0 0
0.5 0.86602540378443865 0 0
0 0 1 0
1 0 1 0
0.5 0.86602540378443865 1 0
Prisms
1
1 2 3 4 5 6 0
End
)";

TEST(MeditPrismOrder, PrismBecomesMirroredVtkWedge) {
  const absl::StatusOr<MeshDocument> document = ParseMedit(kRegularPrismGmshOrder);
  ASSERT_TRUE(document.ok()) << document.status();
  EXPECT_EQ(document->grid.cells.types, std::vector<std::uint8_t>{13});
  EXPECT_EQ(document->grid.cells.connectivity, (std::vector<std::int64_t>{0, 2, 1, 3, 5, 4}));
}

TEST(MeditPrismOrder, PrismInVtkOrderReadsBackInverted) {
  // The same prism listed in VTK's wedge order is the mirror image: not valid.
  std::string text = kRegularPrismGmshOrder;
  text.replace(text.find("1 2 3 4 5 6 0"), 13, "1 3 2 4 6 5 0");
  const absl::StatusOr<MeshDocument> document = ParseMedit(text);
  ASSERT_TRUE(document.ok()) << document.status();
  const absl::StatusOr<GridMesh> mesh = GridToMesh(document->grid);
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  const auto nodes =
      GatherNodes<ElementType::kPrism>(mesh->mesh, mesh->mesh.element_nodes(0).data());
  EXPECT_FALSE(IsValid<ElementType::kPrism>(nodes));
}

}  // namespace
}  // namespace getme::formats
