// SU2 files written by other tools read with the content they hold: the shared SU2 meshes (one
// with 6,304 mirrored elements, one with a verbatim tail), Gmsh's and meshio's SU2 writers.

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <string>
#include <vector>

#include "absl/strings/numbers.h"
#include "formats/mesh_file.h"
#include "formats/su2/su2_reader.h"
#include "formats/vtk_reader.h"
#include "nlohmann/json.hpp"
#include "su2_test_util.h"
#include "vtk_test_util.h"

namespace getme::formats {
namespace {

using testing::InvalidVolumeCellIndices;
using testing::InvalidVolumeCells;
using testing::ReadText;
using testing::SectionRows;
using testing::SharedSu2;
using testing::Su2FixturePath;

std::vector<std::int64_t> Integers(const std::vector<std::string>& tokens, std::size_t from,
                                   std::size_t count) {
  std::vector<std::int64_t> values;
  for (std::size_t k = from; k < from + count; ++k) {
    std::int64_t value = 0;
    EXPECT_TRUE(absl::SimpleAtoi(tokens[k], &value)) << tokens[k];
    values.push_back(value);
  }
  return values;
}

int NodeCountOfType(std::int64_t type) {
  switch (type) {
    case 10:
      return 4;
    case 12:
      return 8;
    case 13:
      return 6;
    case 14:
      return 5;
    case 5:
      return 3;
    case 9:
      return 4;
    default:
      return 2;
  }
}

// The cells of section rows "type node… [index]" exactly as the file lists them.
GridCells CellsOfRows(const std::vector<std::vector<std::string>>& rows) {
  GridCells cells;
  for (const std::vector<std::string>& row : rows) {
    const std::int64_t type = Integers(row, 0, 1)[0];
    cells.Add(static_cast<int>(type), Integers(row, 1, NodeCountOfType(type)));
  }
  return cells;
}

std::vector<std::int64_t> CellNodes(const GridCells& cells, std::int64_t cell) {
  return {cells.nodes(cell), cells.nodes(cell) + cells.node_count(cell)};
}

const DataArray& Tags(const MeshDocument& document) {
  const DataArray* tags = FindArray(document.grid.cell_data, "su2:tag");
  EXPECT_NE(tags, nullptr);
  return *tags;
}

TEST(Su2Read, KnowlesMixedBeamRenumbersItsMirroredElements) {
  const std::string text = ReadText(SharedSu2("knowles-mixed-beam.su2"));
  const absl::StatusOr<MeshDocument> document = ParseSu2(text);
  ASSERT_TRUE(document.ok()) << document.status();
  EXPECT_EQ(document->format, FileFormat::kSu2);
  ASSERT_TRUE(document->su2.has_value());
  const UnstructuredGrid& grid = document->grid;

  // In the file's own order, 6,304 elements are invalid (core's IsValid on a grid built from the
  // rows by plain text search); after reading none is, and exactly those were renumbered. A
  // cell's validity depends on its own nodes alone, so the invalid cells of the whole listed grid
  // are the cells that are invalid each on its own.
  UnstructuredGrid as_listed;
  as_listed.points = grid.points;
  as_listed.cells = CellsOfRows(SectionRows(text, "NELEM="));
  ASSERT_EQ(as_listed.cells.size(), 11744);
  const absl::StatusOr<std::vector<std::int64_t>> invalid_as_listed =
      InvalidVolumeCellIndices(as_listed);
  ASSERT_TRUE(invalid_as_listed.ok()) << invalid_as_listed.status();
  EXPECT_EQ(invalid_as_listed->size(), 6304u);
  EXPECT_EQ(*invalid_as_listed, document->su2->mirrored_cells);
  EXPECT_EQ(InvalidVolumeCells(grid), 0);
  for (std::int64_t cell = 0; cell < as_listed.cells.size(); ++cell) {
    const bool mirrored = std::binary_search(document->su2->mirrored_cells.begin(),
                                             document->su2->mirrored_cells.end(), cell);
    std::vector<std::int64_t> read = CellNodes(grid.cells, cell);
    std::vector<std::int64_t> listed = CellNodes(as_listed.cells, cell);
    EXPECT_EQ(read == listed, !mirrored) << "cell " << cell;
    std::sort(read.begin(), read.end());
    std::sort(listed.begin(), listed.end());
    EXPECT_EQ(read, listed) << "cell " << cell;
  }

  EXPECT_EQ(grid.point_count(), 9161);
  EXPECT_EQ(grid.cells.size(), 11744 + 160);
  ASSERT_EQ(document->su2->markers.size(), 2u);
  EXPECT_EQ(document->su2->markers[0], (Su2Marker{"clamped", 1}));
  EXPECT_EQ(document->su2->markers[1], (Su2Marker{"load", 2}));
  const GridCells load = CellsOfRows(SectionRows(text, "MARKER_TAG= load"));
  ASSERT_EQ(load.size(), 80);
  for (std::int64_t k = 0; k < load.size(); ++k) {
    const std::int64_t cell = 11744 + 80 + k;
    EXPECT_EQ(CellNodes(grid.cells, cell), CellNodes(load, k));
    EXPECT_EQ(grid.cells.types[cell], 9);
    EXPECT_EQ(Tags(*document).AsDouble(cell), 2.0);
  }
  EXPECT_EQ(Tags(*document).AsDouble(0), 0.0);
  EXPECT_TRUE(document->su2->element_indices);
  EXPECT_TRUE(document->su2->point_indices);
  EXPECT_TRUE(document->su2->tail.empty());
}

TEST(Su2Read, KnowlesMixedBeamHoldsTheMeshOfItsVtkTwin) {
  const absl::StatusOr<MeshDocument> su2 = ReadMeshDocument(SharedSu2("knowles-mixed-beam.su2"));
  const absl::StatusOr<MeshDocument> vtk = ReadMeshDocument(SharedSu2("knowles-mixed-beam.vtk"));
  ASSERT_TRUE(su2.ok()) << su2.status();
  ASSERT_TRUE(vtk.ok()) << vtk.status();
  EXPECT_EQ(su2->format, FileFormat::kSu2);
  EXPECT_EQ(su2->grid.points.reals, vtk->grid.points.reals);
  // The same elements (node sets, types), every one valid in both.
  const auto signature = [](const GridCells& cells) {
    std::vector<std::vector<std::int64_t>> elements;
    for (std::int64_t cell = 0; cell < cells.size(); ++cell) {
      if (cells.types[cell] < 10) continue;
      std::vector<std::int64_t> nodes = CellNodes(cells, cell);
      std::sort(nodes.begin(), nodes.end());
      nodes.push_back(cells.types[cell]);
      elements.push_back(nodes);
    }
    std::sort(elements.begin(), elements.end());
    return elements;
  };
  EXPECT_EQ(signature(su2->grid.cells), signature(vtk->grid.cells));
  EXPECT_EQ(InvalidVolumeCells(su2->grid), 0);
  EXPECT_EQ(InvalidVolumeCells(vtk->grid), 0);
}

TEST(Su2Read, BrickPrismKeepsItsMarkersAndTail) {
  const std::string text = ReadText(SharedSu2("brick-prism.su2"));
  const absl::StatusOr<MeshDocument> document = ParseSu2(text);
  ASSERT_TRUE(document.ok()) << document.status();
  std::vector<std::string> names;
  for (const Su2Marker& marker : document->su2->markers) names.push_back(marker.name);
  EXPECT_EQ(names, (std::vector<std::string>{"x_m", "x_p", "y_m", "y_p", "z_m", "z_p"}));
  EXPECT_EQ(document->grid.point_count(), 16800);
  EXPECT_EQ(document->grid.cells.size(), 29640 + 380 * 2 + 780 * 2 + 1482 * 2);
  EXPECT_EQ(InvalidVolumeCells(document->grid), 0);
  const std::size_t tail = text.find("NPERIODIC=");
  ASSERT_NE(tail, std::string::npos);
  EXPECT_EQ(document->su2->tail, text.substr(tail));
}

struct Expected {
  std::vector<double> points;
  GridCells cells;
  std::vector<std::pair<std::string, GridCells>> markers;
};

Expected ReadExpectedJson(const std::string& name) {
  std::ifstream in(Su2FixturePath(name + ".expected.json"));
  const nlohmann::json json = nlohmann::json::parse(in);
  Expected expected;
  for (const auto& point : json["points"]) {
    for (const double value : point) expected.points.push_back(value);
  }
  const auto add = [](GridCells& cells, const nlohmann::json& row) {
    std::vector<std::int64_t> nodes(row.begin() + 1, row.end());
    cells.Add(row[0].get<int>(), nodes);
  };
  for (const auto& row : json["cells"]) add(expected.cells, row);
  for (const auto& [name, rows] : json["markers"].items()) {
    GridCells cells;
    for (const auto& row : rows) add(cells, row);
    expected.markers.emplace_back(name, cells);
  }
  return expected;
}

void ExpectHolds(const MeshDocument& document, const Expected& expected) {
  const UnstructuredGrid& grid = document.grid;
  ASSERT_EQ(grid.points.reals.size(), expected.points.size());
  for (std::size_t k = 0; k < expected.points.size(); ++k) {
    EXPECT_DOUBLE_EQ(grid.points.reals[k], expected.points[k]) << "coordinate " << k;
  }
  std::int64_t cell = 0;
  for (; cell < expected.cells.size(); ++cell) {
    ASSERT_LT(cell, grid.cells.size());
    EXPECT_EQ(grid.cells.types[cell], expected.cells.types[cell]) << "cell " << cell;
    EXPECT_EQ(CellNodes(grid.cells, cell), CellNodes(expected.cells, cell)) << "cell " << cell;
  }
  ASSERT_EQ(document.su2->markers.size(), expected.markers.size());
  // JSON objects come back sorted by name; the file's marker order is Gmsh's group order.
  for (const auto& [name, cells] : expected.markers) {
    // clang 14 cannot capture a structured binding in a lambda (C++20's P1091, clang 16).
    const std::string& wanted = name;
    const auto marker = std::find_if(document.su2->markers.begin(), document.su2->markers.end(),
                                     [&](const Su2Marker& m) { return m.name == wanted; });
    ASSERT_NE(marker, document.su2->markers.end()) << name;
    const absl::StatusOr<std::vector<std::int64_t>> group = GroupCells(document, name);
    ASSERT_TRUE(group.ok()) << group.status();
    ASSERT_EQ(static_cast<std::int64_t>(group->size()), cells.size()) << name;
    for (std::int64_t k = 0; k < cells.size(); ++k) {
      EXPECT_EQ(CellNodes(grid.cells, (*group)[k]), CellNodes(cells, k)) << name << " " << k;
      EXPECT_EQ(grid.cells.types[(*group)[k]], cells.types[k]);
    }
  }
}

TEST(Su2Read, BoxWrittenByGmsh) {
  const absl::StatusOr<MeshDocument> document = ParseSu2(ReadText(Su2FixturePath("box_gmsh.su2")));
  ASSERT_TRUE(document.ok()) << document.status();
  ExpectHolds(*document, ReadExpectedJson("box_gmsh"));
  EXPECT_EQ(InvalidVolumeCells(document->grid), 0);
}

TEST(Su2Read, HybridWrittenByMeshio) {
  const absl::StatusOr<MeshDocument> document =
      ParseSu2(ReadText(Su2FixturePath("hybrid_meshio.su2")));
  ASSERT_TRUE(document.ok()) << document.status();
  ExpectHolds(*document, ReadExpectedJson("hybrid_meshio"));
  EXPECT_EQ(InvalidVolumeCells(document->grid), 0);
  EXPECT_TRUE(document->su2->mirrored_cells.empty());
  // meshio writes neither row indices nor markers (NMARK= 0), and the points first.
  EXPECT_FALSE(document->su2->element_indices);
  EXPECT_FALSE(document->su2->point_indices);
  EXPECT_TRUE(document->su2->markers.empty());
}

TEST(Su2Files, DispatchByExtensionContentAndName) {
  EXPECT_EQ(FormatFromExtension("a/b.SU2"), FileFormat::kSu2);
  EXPECT_EQ(SniffFormat("% written by hand\n%\n  NDIME = 3\nNELEM= 0\n"), FileFormat::kSu2);
  EXPECT_EQ(SniffFormat("NZONE= 2\n"), FileFormat::kSu2);
  EXPECT_EQ(SniffFormat("NDIMENSION 3\n"), std::nullopt);
  const absl::StatusOr<FormatChoice> choice = ParseFormatName("SU2");
  ASSERT_TRUE(choice.ok());
  EXPECT_EQ(choice->format, FileFormat::kSu2);
  EXPECT_STREQ(FormatDisplayName(FileFormat::kSu2), "SU2");
}

TEST(Su2Files, MarkersAreGroupsByName) {
  const std::string text = ReadText(SharedSu2("knowles-mixed-beam.su2"));
  const absl::StatusOr<MeshDocument> document = ParseSu2(text);
  ASSERT_TRUE(document.ok()) << document.status();
  const absl::StatusOr<std::vector<std::int64_t>> clamped = GroupCells(*document, "clamped");
  ASSERT_TRUE(clamped.ok()) << clamped.status();
  std::vector<std::int64_t> expected_cells(80);
  for (int k = 0; k < 80; ++k) expected_cells[k] = 11744 + k;
  EXPECT_EQ(*clamped, expected_cells);
  // By number, the tag meshio would give the marker.
  EXPECT_EQ(GroupCells(*document, "1").value(), expected_cells);

  const absl::StatusOr<std::vector<std::uint8_t>> fixed =
      SelectFixedNodes(*document, {"clamped"}, false);
  ASSERT_TRUE(fixed.ok()) << fixed.status();
  std::vector<std::uint8_t> expected(9161, 0);
  for (const auto& row : SectionRows(text, "MARKER_TAG= clamped")) {
    for (const std::int64_t node : Integers(row, 1, 4)) expected[node] = 1;
  }
  EXPECT_EQ(*fixed, expected);

  const absl::StatusOr<std::vector<std::int64_t>> missing = GroupCells(*document, "inlet");
  EXPECT_EQ(missing.status(),
            absl::NotFoundError("no SU2 marker 'inlet'; the file's markers: 'clamped', 'load'"));
}

}  // namespace
}  // namespace getme::formats
