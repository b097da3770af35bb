// Hybrid meshes written by meshio and gmsh read with the content their sidecars describe: all
// element kinds, refs, both precisions, gmsh's free layout; sections in any order.

#include <gtest/gtest.h>

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

absl::StatusOr<MeshDocument> ReadFixture(const std::string& name, ExpectedContent* expected) {
  std::string error;
  EXPECT_TRUE(ReadExpected(FixturePath(name + ".expected"), expected, &error)) << error;
  return ParseMedit(ReadText(FixturePath(name + ".mesh")));
}

void ExpectAllElementsValid(const MeshDocument& document, std::int64_t expected_elements) {
  const absl::StatusOr<GridMesh> mesh = GridToMesh(document.grid);
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  ASSERT_EQ(mesh->mesh.element_count(), expected_elements);
  for (ElementId element = 0; element < mesh->mesh.element_count(); ++element) {
    DispatchElementType(mesh->mesh.type(element), [&]<ElementType kType>() {
      const auto nodes = GatherNodes<kType>(mesh->mesh, mesh->mesh.element_nodes(element).data());
      EXPECT_TRUE(IsValid<kType>(nodes)) << "element " << element;
    });
  }
}

TEST(MeditContent, HybridWrittenByMeshio) {
  ExpectedContent expected;
  const absl::StatusOr<MeshDocument> document = ReadFixture("hybrid_meshio", &expected);
  ASSERT_TRUE(document.ok()) << document.status();
  ExpectContent(expected, document->grid);
  EXPECT_EQ(document->format, FileFormat::kMedit);
  ASSERT_TRUE(document->medit.has_value());
  EXPECT_EQ(document->medit->version, 2);
  EXPECT_EQ(document->grid.points.type, VtkDataType::kDouble);
  // Two of each volume type, all placed regular: the prisms prove the mirror once more.
  ExpectAllElementsValid(*document, 8);
  const absl::StatusOr<GridMesh> mesh = GridToMesh(document->grid);
  ASSERT_TRUE(mesh.ok());
  for (const ElementType type : {ElementType::kTetrahedron, ElementType::kHexahedron,
                                 ElementType::kPrism, ElementType::kPyramid}) {
    EXPECT_EQ(mesh->mesh.element_count(type), 2);
  }
}

TEST(MeditContent, HybridWrittenByMeshioInSinglePrecision) {
  ExpectedContent expected;
  const absl::StatusOr<MeshDocument> document = ReadFixture("hybrid_meshio_float", &expected);
  ASSERT_TRUE(document.ok()) << document.status();
  ExpectContent(expected, document->grid);
  ASSERT_TRUE(document->medit.has_value());
  EXPECT_EQ(document->medit->version, 1);
  EXPECT_EQ(document->grid.points.type, VtkDataType::kFloat);
}

TEST(MeditContent, HybridWrittenByGmsh) {
  // gmsh's layout: leading blanks, "Dimension" and its value on separate lines, padded columns.
  ExpectedContent expected;
  const absl::StatusOr<MeshDocument> document = ReadFixture("hybrid_gmsh", &expected);
  ASSERT_TRUE(document.ok()) << document.status();
  ExpectContent(expected, document->grid);
}

TEST(MeditContent, SectionsInAnyOrder) {
  // GMF is random access: elements and Ridges may come before the entities they index.
  const absl::StatusOr<MeshDocument> document = ParseMedit(
      "MeshVersionFormatted 2\nDimension 3\n"
      "Ridges\n1\n1\n"
      "Tetrahedra\n1\n1 2 3 4 9\n"
      "Edges\n1\n1 2 0\n"
      "Vertices\n4\n0 0 0 1\n1 0 0 1\n0 1 0 1\n0 0 1 1\n"
      "End\n");
  ASSERT_TRUE(document.ok()) << document.status();
  EXPECT_EQ(document->grid.cells.types, (std::vector<std::uint8_t>{10, 3}));
  EXPECT_EQ(document->grid.cells.connectivity, (std::vector<std::int64_t>{0, 1, 2, 3, 0, 1}));
  EXPECT_EQ(testing::IntegerValues(document->grid.cell_data, "medit:ref"),
            (std::vector<std::int64_t>{9, 0}));
  ASSERT_EQ(document->medit->sections.size(), 1u);
  EXPECT_EQ(document->medit->sections[0], (MeditSection{"Ridges", {"1"}}));
}

TEST(MeditContent, RequiredVerticesBecomeFixed) {
  const absl::StatusOr<MeshDocument> document = ParseMedit(
      "MeshVersionFormatted 2 Dimension 3\n"
      "Vertices 4 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1 0\n"
      "RequiredVertices 2 4 2\n"
      "Tetrahedra 1 1 2 3 4 0\nEnd");
  ASSERT_TRUE(document.ok()) << document.status();
  EXPECT_EQ(testing::FixedPoints(document->grid), (std::vector<std::int64_t>{1, 3}));
  ASSERT_TRUE(document->medit->required_vertices.has_value());
  EXPECT_EQ(*document->medit->required_vertices, (std::vector<std::int64_t>{4, 2}));
  const absl::StatusOr<GridMesh> mesh = GridToMesh(document->grid);
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  EXPECT_FALSE(mesh->mesh.is_fixed(0));
  EXPECT_TRUE(mesh->mesh.is_fixed(1));
  EXPECT_TRUE(mesh->mesh.is_fixed(3));
}

}  // namespace
}  // namespace getme::formats
