// Conversion between VTK files and the engine mesh: node orders (the wedge mirror), fixed
// nodes, passthrough and unsupported cells, and the quality arrays written back.

#include "formats/grid_mesh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <sstream>

#include "formats/vtk_reader.h"
#include "formats/vtk_writer.h"
#include "getme/elements/element_quality.h"
#include "getme/elements/vec3.h"
#include "vtk_test_util.h"

namespace getme::formats {
namespace {

using testing::AllSharedMeshNames;
using testing::DeclaredCount;
using testing::ReadText;
using testing::SharedMesh;

struct Point {
  double x, y, z;
};

// A one-cell ASCII VTK file, coordinates printed exactly.
std::string OneCellFile(const std::vector<Point>& points, int cell_type) {
  std::ostringstream text;
  text << "# vtk DataFile Version 2.0\none cell\nASCII\nDATASET UNSTRUCTURED_GRID\n";
  text << "POINTS " << points.size() << " double\n";
  for (const Point& p : points) {
    char line[128];
    std::snprintf(line, sizeof(line), "%.17g %.17g %.17g\n", p.x, p.y, p.z);
    text << line;
  }
  text << "CELLS 1 " << points.size() + 1 << "\n" << points.size();
  for (std::size_t i = 0; i < points.size(); ++i) text << " " << i;
  text << "\nCELL_TYPES 1\n" << cell_type << "\n";
  return text.str();
}

// Regular elements with unit edges, in VTK's node order (vtkCellType.h, VTK file formats
// documentation): tetra, hexahedron and pyramid as the paper; the wedge's first triangle
// (0, 1, 2) has its right-hand normal pointing away from (3, 4, 5).
const double kS3 = std::sqrt(3.0);
const std::vector<Point> kVtkTetra = {
    {0, 0, 0}, {1, 0, 0}, {0.5, kS3 / 2, 0}, {0.5, kS3 / 6, std::sqrt(2.0 / 3.0)}};
const std::vector<Point> kVtkHexahedron = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                           {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
const std::vector<Point> kVtkPyramid = {
    {0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0.5, std::sqrt(2.0) / 2}};
const std::vector<Point> kVtkWedge = {{0, 0, 0}, {0.5, kS3 / 2, 0}, {1, 0, 0},
                                      {0, 0, 1}, {0.5, kS3 / 2, 1}, {1, 0, 1}};

Vec3 ToVec(const Point& p) { return Vec3(p.x, p.y, p.z); }

TEST(VtkWedgeConvention, TestWedgeFollowsVtkOrientation) {
  // Independent check of the fixture: VTK's base normal points away from the top triangle.
  const Vec3 normal =
      (ToVec(kVtkWedge[1]) - ToVec(kVtkWedge[0])).cross(ToVec(kVtkWedge[2]) - ToVec(kVtkWedge[0]));
  EXPECT_LT(normal.dot(ToVec(kVtkWedge[3]) - ToVec(kVtkWedge[0])), 0.0);
}

class RegularElementTest : public ::testing::TestWithParam<std::pair<int, std::vector<Point>>> {};

TEST_P(RegularElementTest, ReadsBackValidWithMeanRatioOne) {
  const auto& [cell_type, points] = GetParam();
  const absl::StatusOr<UnstructuredGrid> file = ParseVtk(OneCellFile(points, cell_type));
  ASSERT_TRUE(file.ok()) << file.status();
  absl::StatusOr<GridMesh> mesh = GridToMesh(*file);
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  ASSERT_EQ(mesh->mesh.element_count(), 1);
  DispatchElementType(mesh->mesh.type(0), [&]<ElementType kType>() {
    const auto nodes = GatherNodes<kType>(mesh->mesh, mesh->mesh.element_nodes(0).data());
    EXPECT_TRUE(IsValid<kType>(nodes));
    EXPECT_NEAR(MeanRatio<kType>(nodes), 1.0, 1e-12);
  });
  // The arrays written back say the same.
  UnstructuredGrid updated = *file;
  ASSERT_TRUE(UpdateGridFromMesh(mesh->mesh, mesh->cell_elements, updated).ok());
  const DataArray* mean_ratio = FindArray(updated.cell_data, "mean_ratio");
  const DataArray* valid = FindArray(updated.cell_data, "valid");
  ASSERT_NE(mean_ratio, nullptr);
  ASSERT_NE(valid, nullptr);
  EXPECT_NEAR(mean_ratio->AsDouble(0), 1.0, 1e-12);
  EXPECT_EQ(valid->AsDouble(0), 1.0);
}

INSTANTIATE_TEST_SUITE_P(AllTypes, RegularElementTest,
                         ::testing::Values(std::pair{10, kVtkTetra}, std::pair{12, kVtkHexahedron},
                                           std::pair{14, kVtkPyramid}, std::pair{13, kVtkWedge}));

TEST(VtkWedgeConvention, PaperOrderWrittenAsVtkWedgeIsInverted) {
  // The paper's prism order is VTK's mirrored: given as a VTK wedge it must come out invalid.
  const std::vector<Point> paper_order = {kVtkWedge[0], kVtkWedge[2], kVtkWedge[1],
                                          kVtkWedge[3], kVtkWedge[5], kVtkWedge[4]};
  const absl::StatusOr<UnstructuredGrid> file = ParseVtk(OneCellFile(paper_order, 13));
  ASSERT_TRUE(file.ok()) << file.status();
  absl::StatusOr<GridMesh> mesh = GridToMesh(*file);
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  const auto nodes =
      GatherNodes<ElementType::kPrism>(mesh->mesh, mesh->mesh.element_nodes(0).data());
  EXPECT_FALSE(IsValid<ElementType::kPrism>(nodes));
}

TEST(VtkWedgeConvention, MesquiteWedgesAreAllValid) {
  const absl::StatusOr<UnstructuredGrid> file = ReadVtkFile(SharedMesh("6-wedge-prism.vtk"));
  ASSERT_TRUE(file.ok()) << file.status();
  absl::StatusOr<GridMesh> mesh = GridToMesh(*file);
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  ASSERT_EQ(mesh->mesh.element_count(ElementType::kPrism), 6);
  for (ElementId e = 0; e < 6; ++e) {
    const auto nodes =
        GatherNodes<ElementType::kPrism>(mesh->mesh, mesh->mesh.element_nodes(e).data());
    EXPECT_TRUE(IsValid<ElementType::kPrism>(nodes)) << "element " << e;
  }
}

TEST(VtkFromMesh, WritesEngineElementsBackInVtkOrder) {
  const absl::StatusOr<UnstructuredGrid> file = ParseVtk(OneCellFile(kVtkWedge, 13));
  ASSERT_TRUE(file.ok()) << file.status();
  absl::StatusOr<GridMesh> mesh = GridToMesh(*file);
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  const UnstructuredGrid written = GridFromMesh(mesh->mesh, "from mesh");
  EXPECT_EQ(written.cells.connectivity, file->cells.connectivity);
  EXPECT_EQ(written.cells.types, file->cells.types);
  EXPECT_EQ(written.points.reals, file->points.reals);
}

// The number of nonzero values of the `fixed` point data, counted from the file text alone.
std::int64_t FixedCountFromText(const std::string& text) {
  const std::size_t at = text.find("SCALARS fixed");
  if (at == std::string::npos) return -1;
  std::istringstream rest(text.substr(at));
  std::string line;
  std::getline(rest, line);  // SCALARS fixed <type> [1]
  std::getline(rest, line);  // LOOKUP_TABLE default
  std::int64_t fixed = 0;
  double value = 0;
  const std::int64_t points = DeclaredCount(text, "POINTS");
  for (std::int64_t i = 0; i < points && rest >> value; ++i) {
    fixed += value != 0.0 ? 1 : 0;
  }
  return fixed;
}

TEST(VtkFixedNodes, FixedPointDataSetsFixedFlags) {
  int meshes_with_fixed = 0;
  for (const std::string& name : AllSharedMeshNames()) {
    if (name == "sph-10-zsquare.vtk") continue;
    SCOPED_TRACE(name);
    const std::string text = ReadText(SharedMesh(name));
    const absl::StatusOr<UnstructuredGrid> file = ParseVtk(text);
    ASSERT_TRUE(file.ok()) << file.status();
    absl::StatusOr<GridMesh> mesh = GridToMesh(*file);
    ASSERT_TRUE(mesh.ok()) << mesh.status();
    std::int64_t fixed = 0;
    for (NodeId node = 0; node < mesh->mesh.node_count(); ++node) {
      fixed += mesh->mesh.is_fixed(node) ? 1 : 0;
    }
    const std::int64_t expected = FixedCountFromText(text);
    if (expected < 0) {
      EXPECT_EQ(fixed, 0);
      continue;
    }
    ++meshes_with_fixed;
    EXPECT_EQ(fixed, expected);
  }
  EXPECT_GE(meshes_with_fixed, 15);
}

TEST(VtkFixedNodes, SingleHexHasSevenFixedNodesAndNodeSevenFree) {
  const absl::StatusOr<UnstructuredGrid> file = ReadVtkFile(SharedMesh("single_hex.vtk"));
  ASSERT_TRUE(file.ok()) << file.status();
  absl::StatusOr<GridMesh> mesh = GridToMesh(*file);
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  for (NodeId node = 0; node < 7; ++node) EXPECT_TRUE(mesh->mesh.is_fixed(node)) << node;
  EXPECT_FALSE(mesh->mesh.is_fixed(7));
}

// A hexahedron with a quad on its bottom face, a line, a vertex and a triangle.
constexpr char kHexWithSurfaceCells[] = R"(# vtk DataFile Version 3.0
hex plus passthrough cells
ASCII
DATASET UNSTRUCTURED_GRID
POINTS 8 float
0 0 0  1 0 0  1 1 0  0 1 0
0 0 1  1 0 1  1 1 1  0 1 1
CELLS 5 23
4 0 3 2 1
8 0 1 2 3 4 5 6 7
2 0 4
1 6
3 4 5 6
CELL_TYPES 5
9
12
3
1
5
CELL_DATA 5
SCALARS mean_ratio float
LOOKUP_TABLE default
5 5 5 5 5
FIELD extra 2
warpage 1 5 int
7 7 7 7 7
region 1 5 int
1 2 3 4 5
)";

TEST(VtkPassthrough, SurfaceCellsAreKeptAndMarkedUnmeasured) {
  const absl::StatusOr<UnstructuredGrid> file = ParseVtk(kHexWithSurfaceCells);
  ASSERT_TRUE(file.ok()) << file.status();
  absl::StatusOr<GridMesh> mesh = GridToMesh(*file);
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  EXPECT_EQ(mesh->mesh.element_count(), 1);
  EXPECT_EQ(mesh->cell_elements, (std::vector<ElementId>{-1, 0, -1, -1, -1}));
  EXPECT_EQ(mesh->element_cells, (std::vector<std::int64_t>{1}));

  // Move the free top corner (node 6) and write back.
  mesh->mesh.x()[6] = 1.25;
  UnstructuredGrid updated = *file;
  ASSERT_TRUE(UpdateGridFromMesh(mesh->mesh, mesh->cell_elements, updated).ok());
  const absl::StatusOr<std::string> text = SerializeVtk(updated, Encoding::kAscii);
  ASSERT_TRUE(text.ok()) << text.status();
  const absl::StatusOr<UnstructuredGrid> again = ParseVtk(*text);
  ASSERT_TRUE(again.ok()) << again.status();
  EXPECT_EQ(again->cells.connectivity, file->cells.connectivity);
  EXPECT_EQ(again->cells.types, file->cells.types);
  EXPECT_EQ(again->points.type, VtkDataType::kDouble);
  EXPECT_EQ(again->points.AsDouble(3 * 6), 1.25);

  // Existing arrays are replaced where they were: SCALARS mean_ratio, FIELD array warpage;
  // `valid` is appended; `region` is untouched.
  ASSERT_EQ(again->cell_data.size(), 3u);
  EXPECT_EQ(again->cell_data[0].kind, VtkAttributeKind::kScalars);
  EXPECT_EQ(again->cell_data[0].name, "mean_ratio");
  EXPECT_EQ(again->cell_data[1].kind, VtkAttributeKind::kField);
  EXPECT_EQ(again->cell_data[1].arrays[0].name, "warpage");
  EXPECT_EQ(again->cell_data[1].arrays[1].integers, (std::vector<std::int64_t>{1, 2, 3, 4, 5}));
  EXPECT_EQ(again->cell_data[2].name, "valid");

  const DataArray* mean_ratio = FindArray(again->cell_data, "mean_ratio");
  const DataArray* warpage = FindArray(again->cell_data, "warpage");
  const DataArray* valid = FindArray(again->cell_data, "valid");
  ASSERT_NE(mean_ratio, nullptr);
  ASSERT_NE(warpage, nullptr);
  ASSERT_NE(valid, nullptr);
  for (const std::int64_t cell : {0, 2, 3, 4}) {
    EXPECT_EQ(mean_ratio->AsDouble(cell), -1.0) << cell;
    EXPECT_EQ(warpage->AsDouble(cell), -1.0) << cell;
    EXPECT_EQ(valid->AsDouble(cell), 0.0) << cell;
  }
  // The hexahedron, recomputed independently from the moved coordinates.
  const auto nodes =
      GatherNodes<ElementType::kHexahedron>(mesh->mesh, mesh->mesh.element_nodes(0).data());
  EXPECT_EQ(mean_ratio->AsDouble(1), MeanRatio<ElementType::kHexahedron>(nodes));
  EXPECT_EQ(warpage->AsDouble(1), Warpage<ElementType::kHexahedron>(nodes));
  EXPECT_GT(warpage->AsDouble(1), 0.0);  // the top face is no longer planar
  EXPECT_LT(mean_ratio->AsDouble(1), 1.0);
  EXPECT_EQ(valid->AsDouble(1), 1.0);
}

TEST(VtkUnsupportedCells, QuadraticTetraIsRefusedByIndexAndType) {
  std::string text = OneCellFile({{0, 0, 0},
                                  {1, 0, 0},
                                  {0, 1, 0},
                                  {0, 0, 1},
                                  {0.5, 0, 0},
                                  {0.5, 0.5, 0},
                                  {0, 0.5, 0},
                                  {0, 0, 0.5},
                                  {0.5, 0, 0.5},
                                  {0, 0.5, 0.5}},
                                 24);
  const absl::StatusOr<UnstructuredGrid> file = ParseVtk(text);
  ASSERT_TRUE(file.ok()) << file.status();
  const absl::StatusOr<GridMesh> mesh = GridToMesh(*file);
  ASSERT_FALSE(mesh.ok());
  EXPECT_EQ(mesh.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_NE(mesh.status().message().find("cell 0 has VTK type 24 (quadratic_tetra)"),
            std::string::npos)
      << mesh.status();
}

TEST(VtkUnsupportedCells, PolyhedronIsRefused) {
  // A tetrahedron as a polyhedron face stream: 4 faces of 3 points.
  const std::string text = R"(# vtk DataFile Version 3.0
polyhedron
ASCII
DATASET UNSTRUCTURED_GRID
POINTS 4 double
0 0 0 1 0 0 0 1 0 0 0 1
CELLS 1 18
17 4 3 0 2 1 3 0 1 3 3 1 2 3 3 2 0 3
CELL_TYPES 1
42
)";
  const absl::StatusOr<UnstructuredGrid> file = ParseVtk(text);
  ASSERT_TRUE(file.ok()) << file.status();
  const absl::StatusOr<GridMesh> mesh = GridToMesh(*file);
  ASSERT_FALSE(mesh.ok());
  EXPECT_NE(mesh.status().message().find("cell 0 has VTK type 42 (polyhedron)"), std::string::npos)
      << mesh.status();
}

TEST(VtkUnsupportedCells, OnlySurfaceCellsNamesThemAll) {
  const std::string text = R"(# vtk DataFile Version 3.0
surface
ASCII
DATASET UNSTRUCTURED_GRID
POINTS 4 double
0 0 0 1 0 0 0 1 0 0 0 1
CELLS 3 11
3 0 1 2
3 0 1 3
2 0 1
CELL_TYPES 3
5
5
3
)";
  const absl::StatusOr<UnstructuredGrid> file = ParseVtk(text);
  ASSERT_TRUE(file.ok()) << file.status();
  const absl::StatusOr<GridMesh> mesh = GridToMesh(*file);
  ASSERT_FALSE(mesh.ok());
  EXPECT_EQ(mesh.status().message(),
            "no volume elements: the file has 1 line cell (VTK type 3) and 2 triangle cells "
            "(VTK type 5); getme smooths tetrahedra (10), hexahedra (12), wedges (13), "
            "pyramids (14)");
}

TEST(VtkUnsupportedCells, RepeatedNodeInAVolumeCellIsNamed) {
  std::string text = OneCellFile(kVtkTetra, 10);
  text.replace(text.find("4 0 1 2 3"), 9, "4 0 1 2 1");
  const absl::StatusOr<UnstructuredGrid> file = ParseVtk(text);
  ASSERT_TRUE(file.ok()) << file.status();
  const absl::StatusOr<GridMesh> mesh = GridToMesh(*file);
  ASSERT_FALSE(mesh.ok());
  EXPECT_EQ(mesh.status().message(), "cell 0 (tetra) lists point 1 twice");
}

// The CLI hands over the measures Smooth took of the result: they are what gets written, and a
// set of another size is refused, not read past its end.
TEST(VtkUpdateFromMesh, WritesTheMeasuresGivenAndRefusesOnesOfAnotherSize) {
  const absl::StatusOr<UnstructuredGrid> file = ParseVtk(OneCellFile(kVtkHexahedron, 12));
  ASSERT_TRUE(file.ok()) << file.status();
  absl::StatusOr<GridMesh> mesh = GridToMesh(*file);
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  ElementMeasures given;
  given.quality = {0.25};
  given.warpage = {0.5};
  given.valid = {0};
  UnstructuredGrid updated = *file;
  ASSERT_TRUE(UpdateGridFromMesh(mesh->mesh, mesh->cell_elements, updated, &given).ok());
  EXPECT_EQ(FindArray(updated.cell_data, "mean_ratio")->AsDouble(0), 0.25);
  EXPECT_EQ(FindArray(updated.cell_data, "warpage")->AsDouble(0), 0.5);
  EXPECT_EQ(FindArray(updated.cell_data, "valid")->AsDouble(0), 0.0);

  given.warpage.push_back(0.0);
  const absl::Status status = UpdateGridFromMesh(mesh->mesh, mesh->cell_elements, updated, &given);
  EXPECT_EQ(status.code(), absl::StatusCode::kInvalidArgument);
  EXPECT_EQ(status.message(),
            "the element measures given have 1 qualities, 2 warpages and 1 validity flags, but the "
            "mesh has 1 elements");
}

TEST(VtkUpdateFromMesh, RefusesAMeshOfAnotherFile) {
  const absl::StatusOr<UnstructuredGrid> hex = ParseVtk(OneCellFile(kVtkHexahedron, 12));
  const absl::StatusOr<UnstructuredGrid> tet = ParseVtk(OneCellFile(kVtkTetra, 10));
  ASSERT_TRUE(hex.ok() && tet.ok());
  absl::StatusOr<GridMesh> mesh = GridToMesh(*tet);
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  UnstructuredGrid target = *hex;
  const absl::Status status = UpdateGridFromMesh(mesh->mesh, mesh->cell_elements, target);
  EXPECT_EQ(status.code(), absl::StatusCode::kInvalidArgument);
  EXPECT_EQ(status.message(), "the mesh has 4 nodes, but the file has 8 points");
}

}  // namespace
}  // namespace getme::formats
