#include "exodus_test_util.h"

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

namespace getme::formats::testing {

std::string ExodusFixture(const std::string& name) {
  return std::string(EXODUS_FIXTURES) + "/" + name;
}

ExodusExpected ReadExodusExpected(const std::string& name) {
  std::ifstream in(ExodusFixture(name + ".json"));
  EXPECT_TRUE(in.good()) << "missing sidecar " << name << ".json";
  ExodusExpected expected;
  if (!in.good()) return expected;
  const nlohmann::json json = nlohmann::json::parse(in);
  expected.points = json["points"].get<std::vector<double>>();
  expected.cells = json["cells"].get<std::vector<std::vector<std::int64_t>>>();
  expected.block_ids = json["block_ids"].get<std::vector<std::int64_t>>();
  for (const auto& face : json["side_faces"]) {
    expected.side_faces.emplace_back(face[0].get<std::int64_t>(),
                                     face[1].get<std::vector<std::int64_t>>());
  }
  for (const auto& set : json["node_sets"]) {
    expected.node_sets.push_back({set[0].get<std::int64_t>(), set[1].get<std::string>(),
                                  set[2].get<std::vector<std::int64_t>>()});
  }
  return expected;
}

std::vector<std::vector<std::int64_t>> CellRows(const GridCells& cells) {
  std::vector<std::vector<std::int64_t>> rows;
  for (std::int64_t cell = 0; cell < cells.size(); ++cell) {
    std::vector<std::int64_t> row = {cells.types[cell]};
    row.insert(row.end(), cells.nodes(cell), cells.nodes(cell) + cells.node_count(cell));
    rows.push_back(std::move(row));
  }
  return rows;
}

std::vector<std::int64_t> CellIntegers(const UnstructuredGrid& grid, const std::string& name) {
  const DataArray* array = FindArray(grid.cell_data, name);
  if (array == nullptr) return {};
  std::vector<std::int64_t> values;
  for (std::int64_t k = 0; k < array->value_count(); ++k) {
    values.push_back(static_cast<std::int64_t>(array->AsDouble(k)));
  }
  return values;
}

void ExpectExodusContent(const ExodusExpected& expected, const MeshDocument& document) {
  const UnstructuredGrid& grid = document.grid;
  EXPECT_EQ(grid.points.reals, expected.points);
  std::vector<std::vector<std::int64_t>> rows = expected.cells;
  std::vector<std::int64_t> blocks = expected.block_ids;
  std::vector<std::int64_t> side_sets(expected.cells.size(), -1);
  for (const auto& [set, nodes] : expected.side_faces) {
    std::vector<std::int64_t> row = {nodes.size() == 3 ? 5 : 9};
    row.insert(row.end(), nodes.begin(), nodes.end());
    rows.push_back(row);
    blocks.push_back(-1);
    side_sets.push_back(set);
  }
  EXPECT_EQ(CellRows(grid.cells), rows);
  EXPECT_EQ(CellIntegers(grid, "exodus:block"), blocks);
  EXPECT_EQ(CellIntegers(grid, "exodus:sideset"), side_sets);
  ASSERT_TRUE(document.exodus.has_value());
  ASSERT_EQ(document.exodus->node_sets.size(), expected.node_sets.size());
  for (std::size_t k = 0; k < expected.node_sets.size(); ++k) {
    EXPECT_EQ(document.exodus->node_sets[k].id, expected.node_sets[k].id);
    EXPECT_EQ(document.exodus->node_sets[k].name, expected.node_sets[k].name);
    EXPECT_EQ(document.exodus->node_sets[k].nodes, expected.node_sets[k].nodes);
  }
}

}  // namespace getme::formats::testing
