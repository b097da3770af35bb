// Files written by Gmsh's and meshio's own writers read as those tools read them back: nodes
// and coordinates bit for bit, element types, tags and node orders, entities, physical groups and
// views; a regular element of each type comes out valid with mean ratio 1 (the node orders,
// the prism's mirror in particular).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "formats/gmsh/gmsh_groups.h"
#include "formats/gmsh/gmsh_reader.h"
#include "formats/grid_mesh.h"
#include "getme/elements/element_quality.h"
#include "gmsh_test_util.h"

namespace getme::formats {
namespace {

using testing::AllGmshVariants;
using testing::GmshExpected;
using testing::GmshInput;
using testing::InVtkOrder;
using testing::ParseGmshFile;
using testing::ReadGmshExpected;
using testing::SameBits;
using testing::VtkCodeOfGmshType;

std::map<std::int64_t, std::int64_t> IndexOf(const std::vector<std::int64_t>& tags) {
  std::map<std::int64_t, std::int64_t> index;
  for (std::size_t i = 0; i < tags.size(); ++i) index[tags[i]] = static_cast<std::int64_t>(i);
  return index;
}

// Nodes, elements, entities and physical groups as Gmsh read them back.
void ExpectAsGmshReadsIt(const MeshDocument& document, const GmshExpected& expected) {
  ASSERT_TRUE(document.gmsh.has_value());
  const GmshExtras& extras = *document.gmsh;
  const UnstructuredGrid& grid = document.grid;
  ASSERT_EQ(grid.point_count(), static_cast<std::int64_t>(expected.nodes.size()));
  const auto node_index = IndexOf(extras.node_tags);
  for (const auto& node : expected.nodes) {
    ASSERT_TRUE(node_index.contains(node.tag)) << "node " << node.tag;
    const std::int64_t i = node_index.at(node.tag);
    for (int k = 0; k < 3; ++k) {
      EXPECT_TRUE(SameBits(grid.points.reals[3 * i + k], node.xyz[k]))
          << "node " << node.tag << " coordinate " << k;
    }
  }
  ASSERT_EQ(grid.cells.size(), static_cast<std::int64_t>(expected.elements.size()));
  const auto element_index = IndexOf(extras.element_tags);
  const DataArray* geometrical = FindArray(grid.cell_data, "gmsh:geometrical");
  const DataArray* physical = FindArray(grid.cell_data, "gmsh:physical");
  ASSERT_NE(geometrical, nullptr);
  ASSERT_NE(physical, nullptr);
  // The physical groups each entity belongs to.
  std::map<std::pair<int, int>, std::set<int>> groups_of_entity;
  for (const auto& group : expected.physicals) {
    for (int entity : group.entities) groups_of_entity[{group.dim, entity}].insert(group.tag);
  }
  for (const auto& element : expected.elements) {
    SCOPED_TRACE("element " + std::to_string(element.tag));
    ASSERT_TRUE(element_index.contains(element.tag));
    const std::int64_t c = element_index.at(element.tag);
    EXPECT_EQ(grid.cells.types[c], VtkCodeOfGmshType(element.type));
    std::vector<std::int64_t> tags;
    for (std::int64_t k = 0; k < grid.cells.node_count(c); ++k) {
      tags.push_back(extras.node_tags[grid.cells.nodes(c)[k]]);
    }
    EXPECT_EQ(tags, InVtkOrder(element.type, element.nodes));
    EXPECT_EQ(geometrical->AsDouble(c), element.entity);
    const std::set<int>& groups = groups_of_entity[{element.dim, element.entity}];
    if (groups.empty()) {
      EXPECT_EQ(physical->AsDouble(c), 0);
    } else {
      EXPECT_TRUE(groups.contains(static_cast<int>(physical->AsDouble(c))));
    }
    if (extras.version_major == 4) {
      EXPECT_EQ(extras.element_entities[c], (GmshDimTag{element.dim, element.entity}));
    }
  }
  // Physical groups: names, and the cells GmshGroupCells finds by name, tag and DIM:TAG.
  EXPECT_EQ(extras.physical_names.size(), expected.physicals.size());
  for (const auto& group : expected.physicals) {
    SCOPED_TRACE("group " + group.name);
    std::vector<std::int64_t> cells;
    for (const auto& element : expected.elements) {
      if (element.dim == group.dim && std::find(group.entities.begin(), group.entities.end(),
                                                element.entity) != group.entities.end()) {
        cells.push_back(element_index.at(element.tag));
      }
    }
    std::sort(cells.begin(), cells.end());
    ASSERT_FALSE(cells.empty());
    for (const std::string& key :
         {group.name, std::to_string(group.dim) + ":" + std::to_string(group.tag),
          std::to_string(group.tag)}) {
      const absl::StatusOr<std::vector<std::int64_t>> found = GmshGroupCells(document, key);
      ASSERT_TRUE(found.ok()) << key << ": " << found.status();
      EXPECT_EQ(*found, cells) << key;
    }
  }
}

class GmshWrittenTest : public ::testing::TestWithParam<std::string> {};

TEST_P(GmshWrittenTest, HybridReadsAsGmshReadsIt) {
  const absl::StatusOr<MeshDocument> document =
      ParseGmshFile(GmshInput("hybrid_" + GetParam() + ".msh"));
  ASSERT_TRUE(document.ok()) << document.status();
  const GmshExpected expected = ReadGmshExpected(GmshInput("hybrid_" + GetParam() + ".expected"));
  // All eight element types are there.
  std::set<int> types;
  for (const auto& element : expected.elements) types.insert(element.type);
  EXPECT_EQ(types, (std::set<int>{1, 2, 3, 4, 5, 6, 7, 15}));
  ExpectAsGmshReadsIt(*document, expected);
  EXPECT_EQ(document->format, FileFormat::kGmsh);
  const bool binary = GetParam().ends_with("binary");
  EXPECT_EQ(document->as_read.encoding, binary ? Encoding::kBinary : Encoding::kAscii);
  EXPECT_EQ(document->as_read.gmsh_version,
            GetParam().starts_with("41") ? GmshVersion::k41 : GmshVersion::k22);
}

TEST_P(GmshWrittenTest, ViewsBecomeArraysNamedByTheirStringTag) {
  const absl::StatusOr<MeshDocument> document =
      ParseGmshFile(GmshInput("views_" + GetParam() + ".msh"));
  ASSERT_TRUE(document.ok()) << document.status();
  const GmshExpected expected = ReadGmshExpected(GmshInput("views_" + GetParam() + ".expected"));
  ExpectAsGmshReadsIt(*document, expected);
  const auto node_index = IndexOf(document->gmsh->node_tags);
  const auto element_index = IndexOf(document->gmsh->element_tags);
  ASSERT_FALSE(expected.data.empty());
  std::set<std::int64_t> fixed_listed;
  for (const auto& data : expected.data) {
    // Later time steps of a name are kept as their own arrays.
    const std::string name =
        data.step == 0 ? data.name : data.name + " [step " + std::to_string(data.step) + "]";
    SCOPED_TRACE(name + " tag " + std::to_string(data.tag));
    const DataArray* array =
        FindArray(data.on_nodes ? document->grid.point_data : document->grid.cell_data, name);
    ASSERT_NE(array, nullptr);
    ASSERT_EQ(array->components, data.components);
    const std::int64_t target =
        data.on_nodes ? node_index.at(data.tag) : element_index.at(data.tag);
    for (int k = 0; k < data.components; ++k) {
      EXPECT_TRUE(SameBits(array->AsDouble(target * data.components + k), data.values[k]));
    }
    if (data.name == "fixed" && data.step == 0) fixed_listed.insert(target);
  }
  // Nodes the "fixed" view does not list are not fixed.
  const DataArray* fixed = FindArray(document->grid.point_data, "fixed");
  ASSERT_NE(fixed, nullptr);
  EXPECT_EQ(fixed_listed.size(), 3u);
  for (std::int64_t i = 0; i < document->grid.point_count(); ++i) {
    if (!fixed_listed.contains(i)) {
      EXPECT_EQ(fixed->AsDouble(i), 0.0) << i;
    }
  }
  // The time of step 1, as a real tag.
  const auto& views = document->gmsh->data_views;
  const auto step1 = std::find_if(views.begin(), views.end(), [](const GmshDataView& view) {
    return view.array_name == "fixed [step 1]";
  });
  ASSERT_NE(step1, views.end());
  ASSERT_FALSE(step1->real_tags.empty());
  EXPECT_EQ(step1->real_tags[0], 0.25);
}

TEST_P(GmshWrittenTest, RegularElementsHaveMeanRatioOne) {
  const absl::StatusOr<MeshDocument> document =
      ParseGmshFile(GmshInput("regular_" + GetParam() + ".msh"));
  ASSERT_TRUE(document.ok()) << document.status();
  ExpectAsGmshReadsIt(*document,
                      ReadGmshExpected(GmshInput("regular_" + GetParam() + ".expected")));
  absl::StatusOr<GridMesh> mesh = GridToMesh(document->grid);
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  ASSERT_EQ(mesh->mesh.element_count(), 4);
  std::set<ElementType> types;
  for (ElementId e = 0; e < mesh->mesh.element_count(); ++e) {
    types.insert(mesh->mesh.type(e));
    DispatchElementType(mesh->mesh.type(e), [&]<ElementType kType>() {
      const auto nodes = GatherNodes<kType>(mesh->mesh, mesh->mesh.element_nodes(e).data());
      EXPECT_TRUE(IsValid<kType>(nodes)) << e;
      EXPECT_NEAR(MeanRatio<kType>(nodes), 1.0, 1e-12) << e;
    });
  }
  EXPECT_EQ(types.size(), 4u);
}

INSTANTIATE_TEST_SUITE_P(AllVariants, GmshWrittenTest,
                         ::testing::Values("22_ascii", "22_binary", "41_ascii", "41_binary"));

class GmshMultiTest : public ::testing::TestWithParam<std::string> {};

TEST_P(GmshMultiTest, AnEntityInTwoPhysicalGroups) {
  const absl::StatusOr<MeshDocument> document =
      ParseGmshFile(GmshInput("multi_" + GetParam() + ".msh"));
  ASSERT_TRUE(document.ok()) << document.status();
  const GmshExpected expected = ReadGmshExpected(GmshInput("multi_" + GetParam() + ".expected"));
  ExpectAsGmshReadsIt(*document, expected);
  const auto tris = std::find_if(document->gmsh->entities.begin(), document->gmsh->entities.end(),
                                 [](const GmshEntity& e) { return e.dim == 2 && e.tag == 4; });
  ASSERT_NE(tris, document->gmsh->entities.end());
  EXPECT_EQ(tris->physical_tags, (std::vector<int>{21, 22}));
  // The triangles are in both groups; "bottom" also holds the quads.
  const auto bottom = GmshGroupCells(*document, "bottom");
  const auto bottom_tris = GmshGroupCells(*document, "bottom tris");
  ASSERT_TRUE(bottom.ok() && bottom_tris.ok());
  EXPECT_EQ(bottom_tris->size(), 4u);
  EXPECT_EQ(bottom->size(), 8u);
  for (std::int64_t c : *bottom_tris) {
    EXPECT_TRUE(std::binary_search(bottom->begin(), bottom->end(), c));
  }
}

INSTANTIATE_TEST_SUITE_P(Gmsh41, GmshMultiTest, ::testing::Values("41_ascii", "41_binary"));

TEST(GmshGroups, NotFoundListsTheGroups) {
  const absl::StatusOr<MeshDocument> document = ParseGmshFile(GmshInput("hybrid_41_ascii.msh"));
  ASSERT_TRUE(document.ok()) << document.status();
  for (const std::string missing : {"nothing", "99", "3:21", "2:x"}) {
    const auto found = GmshGroupCells(*document, missing);
    ASSERT_FALSE(found.ok()) << missing;
    EXPECT_EQ(found.status().code(), absl::StatusCode::kNotFound);
    EXPECT_EQ(found.status().message(),
              "no physical group '" + missing +
                  "' (a name, a tag or DIM:TAG); the mesh has \"corner\" dim 0 tag 1, \"edge\" dim "
                  "1 tag 11, \"bottom\" dim 2 tag 21, \"solid\" dim 3 tag 31, \"wedges\" dim 3 tag "
                  "32");
  }
}

// meshio's own reading of its files, compared through coordinates (its point order is its own).
class MeshioWrittenTest : public ::testing::TestWithParam<std::string> {};

TEST_P(MeshioWrittenTest, ReadsAsMeshioReadsIt) {
  const absl::StatusOr<MeshDocument> document =
      ParseGmshFile(GmshInput("meshio_" + GetParam() + ".msh"));
  ASSERT_TRUE(document.ok()) << document.status();
  const UnstructuredGrid& grid = document->grid;
  std::map<std::array<double, 3>, std::int64_t> by_position;
  for (std::int64_t i = 0; i < grid.point_count(); ++i) {
    by_position[{grid.points.reals[3 * i], grid.points.reals[3 * i + 1],
                 grid.points.reals[3 * i + 2]}] = i;
  }
  std::vector<std::int64_t> meshio_point;  // meshio index → our index
  std::int64_t cell = 0;
  const DataArray* physical = FindArray(grid.cell_data, "gmsh:physical");
  const DataArray* geometrical = FindArray(grid.cell_data, "gmsh:geometrical");
  const DataArray* fixed = FindArray(grid.point_data, "fixed");
  ASSERT_TRUE(physical != nullptr && geometrical != nullptr && fixed != nullptr);
  std::istringstream lines(testing::ReadBytes(GmshInput("meshio_" + GetParam() + ".expected")));
  std::string line;
  int fixed_checked = 0;
  while (std::getline(lines, line)) {
    std::istringstream words(line);
    std::string kind;
    words >> kind;
    if (kind == "point") {
      std::array<double, 3> xyz;
      for (double& value : xyz) {
        std::string word;
        words >> word;
        value = std::strtod(word.c_str(), nullptr);
      }
      ASSERT_TRUE(by_position.contains(xyz)) << line;
      meshio_point.push_back(by_position.at(xyz));
    } else if (kind == "cell") {
      SCOPED_TRACE(line);
      int type = 0, phys = 0, geo = 0;
      words >> type >> phys >> geo;
      std::vector<std::int64_t> nodes;
      std::int64_t node = 0;
      while (words >> node) nodes.push_back(meshio_point.at(node));
      ASSERT_LT(cell, grid.cells.size());
      EXPECT_EQ(grid.cells.types[cell], VtkCodeOfGmshType(type));
      EXPECT_EQ(std::vector<std::int64_t>(grid.cells.nodes(cell),
                                          grid.cells.nodes(cell) + grid.cells.node_count(cell)),
                InVtkOrder(type, nodes));
      if (phys >= 0) {
        EXPECT_EQ(physical->AsDouble(cell), phys);
      }
      if (geo >= 0) {
        EXPECT_EQ(geometrical->AsDouble(cell), geo);
      }
      ++cell;
    } else if (kind == "fixed") {
      std::array<double, 4> values;
      for (double& value : values) {
        std::string word;
        words >> word;
        value = std::strtod(word.c_str(), nullptr);
      }
      const std::array<double, 3> xyz = {values[0], values[1], values[2]};
      ASSERT_TRUE(by_position.contains(xyz)) << line;
      EXPECT_EQ(fixed->AsDouble(by_position.at(xyz)), values[3]) << line;
      ++fixed_checked;
    }
  }
  EXPECT_EQ(static_cast<std::int64_t>(meshio_point.size()), grid.point_count());
  EXPECT_EQ(cell, grid.cells.size());
  EXPECT_EQ(fixed_checked, grid.point_count());
}

INSTANTIATE_TEST_SUITE_P(AllVariants, MeshioWrittenTest,
                         ::testing::Values("22_ascii", "22_binary", "41_ascii", "41_binary"));

}  // namespace
}  // namespace getme::formats
