// Exodus's node order and side numbering, established with files written by other tools: a
// regular element of each type written by meshio's Exodus writer must read back valid with mean
// ratio 1, and the sides the Exodus library itself lists for each side number
// (ex_get_side_set_node_list) must be the Exodus II manual's table, facing outwards.

#include <gtest/gtest.h>

#include <array>
#include <ostream>
#include <string>

#include "exodus_test_util.h"
#include "formats/exodus/exodus_element_types.h"
#include "formats/exodus/exodus_reader.h"
#include "formats/grid_mesh.h"
#include "getme/elements/element_quality.h"

namespace getme::formats {
namespace {

using testing::ExodusFixture;
using testing::ExpectExodusContent;
using testing::ReadExodusExpected;

struct RegularCase {
  const char* type;  // meshio's name, as in the fixture names
  int vtk_type;
  ElementType element_type;
};

void PrintTo(const RegularCase& param, std::ostream* out) { *out << param.type; }

class ExodusRegularElementTest : public ::testing::TestWithParam<RegularCase> {};

TEST_P(ExodusRegularElementTest, MeshioElementReadsBackValidWithMeanRatioOne) {
  const RegularCase& param = GetParam();
  const std::string name = std::string("regular_meshio_") + param.type;
  const absl::StatusOr<MeshDocument> document = ReadExodus(ExodusFixture(name + ".exo"));
  ASSERT_TRUE(document.ok()) << document.status();
  ExpectExodusContent(ReadExodusExpected(name), *document);
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

std::array<double, 3> Point(const UnstructuredGrid& grid, std::int64_t node) {
  return {grid.points.reals[3 * node], grid.points.reals[3 * node + 1],
          grid.points.reals[3 * node + 2]};
}

TEST_P(ExodusRegularElementTest, LibrarySidesAreTheManualsAndFaceOutwards) {
  const RegularCase& param = GetParam();
  const std::string name = std::string("regular_sides_") + param.type;
  const absl::StatusOr<MeshDocument> document = ReadExodus(ExodusFixture(name + ".exo"));
  ASSERT_TRUE(document.ok()) << document.status();
  // The sidecar lists the manual's side table, applied by write_fixtures.py.
  ExpectExodusContent(ReadExodusExpected(name), *document);
  const UnstructuredGrid& grid = document->grid;
  const GridCells& cells = grid.cells;
  ASSERT_EQ(cells.size(), 1 + SideCount(param.vtk_type));

  std::array<double, 3> element_centre{};
  for (std::int64_t k = 0; k < cells.node_count(0); ++k) {
    for (int c = 0; c < 3; ++c) element_centre[c] += Point(grid, cells.nodes(0)[k])[c];
  }
  for (double& c : element_centre) c /= static_cast<double>(cells.node_count(0));
  std::vector<std::int64_t> exodus_nodes(cells.nodes(0), cells.nodes(0) + cells.node_count(0));
  ConvertExodusVtkOrder(param.vtk_type, exodus_nodes);

  for (int side = 1; side <= SideCount(param.vtk_type); ++side) {
    SCOPED_TRACE(side);
    const std::int64_t face = side;  // side faces follow the element, in set order
    // The writer's table (exodus_element_types.cc) agrees with the library's.
    const ExodusSide table = SideNodes(param.vtk_type, side);
    ASSERT_EQ(cells.node_count(face), table.size);
    for (int i = 0; i < table.size; ++i) {
      EXPECT_EQ(cells.nodes(face)[i], exodus_nodes[table.nodes[i]]);
    }
    // Newell's normal of the face points away from the element's centre.
    std::array<double, 3> normal{}, centre{};
    const int n = table.size;
    for (int i = 0; i < n; ++i) {
      const auto p = Point(grid, cells.nodes(face)[i]);
      const auto q = Point(grid, cells.nodes(face)[(i + 1) % n]);
      normal[0] += (p[1] - q[1]) * (p[2] + q[2]);
      normal[1] += (p[2] - q[2]) * (p[0] + q[0]);
      normal[2] += (p[0] - q[0]) * (p[1] + q[1]);
      for (int c = 0; c < 3; ++c) centre[c] += p[c] / n;
    }
    double outward = 0;
    for (int c = 0; c < 3; ++c) outward += normal[c] * (centre[c] - element_centre[c]);
    EXPECT_GT(outward, 0.1);
  }
}

INSTANTIATE_TEST_SUITE_P(WrittenByMeshioAndNetcdf, ExodusRegularElementTest,
                         ::testing::Values(RegularCase{"tetra", 10, ElementType::kTetrahedron},
                                           RegularCase{"hexahedron", 12, ElementType::kHexahedron},
                                           RegularCase{"pyramid", 14, ElementType::kPyramid},
                                           RegularCase{"wedge", 13, ElementType::kPrism}),
                         [](const ::testing::TestParamInfo<RegularCase>& info) {
                           return std::string(info.param.type);
                         });

// The type names Exodus writers use, matched as exodus_element_types.h says.
TEST(ExodusElementTypes, AcceptsTheSpellingsWritersUse) {
  for (const auto& [name, nodes, vtk] :
       std::vector<std::tuple<const char*, int, int>>{{"TETRA", 4, 10},
                                                      {"tet4", 4, 10},
                                                      {"TETRA4", 4, 10},
                                                      {"HEX", 8, 12},
                                                      {"hex8", 8, 12},
                                                      {"HEXAHEDRON", 8, 12},
                                                      {"WEDGE", 6, 13},
                                                      {"wedge6", 6, 13},
                                                      {"PYRAMID", 5, 14},
                                                      {"PYRAMID5", 5, 14},
                                                      {"SHELL4", 4, 9},
                                                      {"SHELL", 3, 5},
                                                      {"TRI3", 3, 5},
                                                      {"BAR2", 2, 3},
                                                      {"SPHERE", 1, 1},
                                                      {"TETRA   ", 4, 10}}) {
    SCOPED_TRACE(name);
    const absl::StatusOr<ExodusTopology> topology = TopologyOfBlock(name, nodes);
    ASSERT_TRUE(topology.ok()) << topology.status();
    EXPECT_EQ(topology->vtk_type, vtk);
  }
}

TEST(ExodusElementTypes, RefusesHigherOrderWrongCountsAndUnknownTypes) {
  EXPECT_EQ(TopologyOfBlock("TETRA10", 10).status().message(),
            "element type 'TETRA10' with 10 nodes per element is not supported: getme smooths "
            "linear elements (TETRA has 4 nodes)");
  EXPECT_EQ(TopologyOfBlock("HEX", 7).status().message(),
            "element type 'HEX' needs 8 nodes per element, the block has 7");
  EXPECT_EQ(TopologyOfBlock("WEDGE6", 15).status().message(),
            "element type 'WEDGE6' names 6 nodes but the block has 15 per element");
  EXPECT_EQ(TopologyOfBlock("NSIDED", 4).status().message(),
            "element type 'NSIDED' is not supported: getme reads linear TETRA, PYRAMID, WEDGE and "
            "HEX blocks and passes SHELL/QUAD, TRI, BAR/BEAM/TRUSS and SPHERE blocks through");
}

}  // namespace
}  // namespace getme::formats
