#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "formats/unstructured_grid.h"

namespace getme::formats::testing {

// Path of a file in the fixture directory (write_fixtures.py's output, MEDIT_FIXTURES).
std::string FixturePath(const std::string& name);

// A sidecar NAME.expected: what a MEDIT file must read as (write_fixtures.py writes them for
// other tools' files; WriteExpected for getme's own, which check_with_meshio.py reads).
struct ExpectedContent {
  double tolerance = 0.0;  // on coordinates; 0 = bit for bit
  std::vector<double> points;
  std::vector<std::int64_t> point_refs;
  GridCells cells;  // VTK codes and node order, file order
  std::vector<std::int64_t> cell_refs;
};

// Parses a sidecar; false (with `error` set) if it is missing or malformed.
bool ReadExpected(const std::string& path, ExpectedContent* expected, std::string* error);
void WriteExpected(const std::string& path, const ExpectedContent& expected);

// Asserts (gtest) that `grid` holds the expected points, cells and "medit:ref" arrays.
void ExpectContent(const ExpectedContent& expected, const UnstructuredGrid& grid);

// The values of an integer array (any section) called `name`; empty if there is none.
std::vector<std::int64_t> IntegerValues(const std::vector<VtkAttribute>& attributes,
                                        const std::string& name);
// 0-based indices of the points a "fixed" point array marks (any component nonzero).
std::vector<std::int64_t> FixedPoints(const UnstructuredGrid& grid);

// The order MEDIT must hold `cells` in, computed here independently of the writer: vertex
// cells dropped, the other kinds grouped in the order each first appears, grid order within.
std::vector<std::int64_t> GroupedCellOrder(const GridCells& cells);
GridCells Reordered(const GridCells& cells, const std::vector<std::int64_t>& order);

void WriteText(const std::string& path, const std::string& text);

}  // namespace getme::formats::testing
