#include "medit_test_util.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "vtk_test_util.h"

namespace getme::formats::testing {
namespace {

bool ParseDouble(const std::string& token, double* value) {
  const char* end = token.data() + token.size();
  const auto [ptr, ec] = std::from_chars(token.data(), end, *value);
  return ec == std::errc() && ptr == end;
}

// Reads "keyword count" and then `count * per_item` numbers of type T.
template <typename T>
bool ReadBlock(std::istream& in, const std::string& keyword, int per_item, std::vector<T>* values,
               std::string* error) {
  std::string word;
  std::int64_t count = -1;
  if (!(in >> word >> count) || word != keyword || count < 0) {
    *error = "expected '" + keyword + " <count>', found '" + word + "'";
    return false;
  }
  for (std::int64_t i = 0; i < count * per_item; ++i) {
    std::string token;
    if (!(in >> token)) {
      *error = keyword + ": ends early";
      return false;
    }
    if constexpr (std::is_same_v<T, double>) {
      double value = 0;
      if (!ParseDouble(token, &value)) {
        *error = keyword + ": bad number " + token;
        return false;
      }
      values->push_back(value);
    } else {
      values->push_back(std::stoll(token));
    }
  }
  return true;
}

}  // namespace

std::string FixturePath(const std::string& name) {
  return std::string(MEDIT_FIXTURES) + "/" + name;
}

bool ReadExpected(const std::string& path, ExpectedContent* expected, std::string* error) {
  std::ifstream in(path);
  if (!in) {
    *error = "cannot open " + path + " (did the fixture formats_medit_write_fixtures run?)";
    return false;
  }
  std::string word, tolerance;
  if (!(in >> word >> tolerance) || word != "tolerance" ||
      !ParseDouble(tolerance, &expected->tolerance)) {
    *error = path + ": expected 'tolerance <value>'";
    return false;
  }
  if (!ReadBlock(in, "points", 3, &expected->points, error) ||
      !ReadBlock(in, "point_refs", 1, &expected->point_refs, error)) {
    return false;
  }
  std::int64_t count = -1;
  if (!(in >> word >> count) || word != "cells" || count < 0) {
    *error = path + ": expected 'cells <count>'";
    return false;
  }
  for (std::int64_t cell = 0; cell < count; ++cell) {
    int type = 0, nodes = 0;
    if (!(in >> type >> nodes)) {
      *error = path + ": bad cell line";
      return false;
    }
    std::vector<std::int64_t> ids(nodes);
    for (std::int64_t& id : ids) in >> id;
    expected->cells.Add(type, ids);
  }
  return ReadBlock(in, "cell_refs", 1, &expected->cell_refs, error);
}

void WriteExpected(const std::string& path, const ExpectedContent& expected) {
  std::ostringstream out;
  out << "tolerance " << expected.tolerance << "\npoints " << expected.points.size() / 3 << "\n";
  char number[40];
  for (std::size_t i = 0; i < expected.points.size(); ++i) {
    std::snprintf(number, sizeof(number), "%.17g", expected.points[i]);
    out << number << (i % 3 == 2 ? "\n" : " ");
  }
  out << "point_refs " << expected.point_refs.size() << "\n";
  for (const std::int64_t ref : expected.point_refs) out << ref << " ";
  out << "\ncells " << expected.cells.size() << "\n";
  for (std::int64_t cell = 0; cell < expected.cells.size(); ++cell) {
    out << static_cast<int>(expected.cells.types[cell]) << " " << expected.cells.node_count(cell);
    for (std::int64_t k = 0; k < expected.cells.node_count(cell); ++k) {
      out << " " << expected.cells.nodes(cell)[k];
    }
    out << "\n";
  }
  out << "cell_refs " << expected.cell_refs.size() << "\n";
  for (const std::int64_t ref : expected.cell_refs) out << ref << " ";
  out << "\n";
  WriteText(path, out.str());
}

void ExpectContent(const ExpectedContent& expected, const UnstructuredGrid& grid) {
  ASSERT_EQ(grid.points.components, 3);
  ASSERT_EQ(grid.points.reals.size(), expected.points.size());
  for (std::size_t i = 0; i < expected.points.size(); ++i) {
    if (expected.tolerance == 0.0) {
      ASSERT_EQ(std::bit_cast<std::uint64_t>(grid.points.reals[i]),
                std::bit_cast<std::uint64_t>(expected.points[i]))
          << "coordinate " << i << ": " << grid.points.reals[i] << " vs " << expected.points[i];
    } else {
      ASSERT_NEAR(grid.points.reals[i], expected.points[i], expected.tolerance)
          << "coordinate " << i;
    }
  }
  EXPECT_EQ(grid.cells.types, expected.cells.types);
  EXPECT_EQ(grid.cells.offsets, expected.cells.offsets);
  EXPECT_EQ(grid.cells.connectivity, expected.cells.connectivity);
  EXPECT_EQ(IntegerValues(grid.point_data, "medit:ref"), expected.point_refs);
  EXPECT_EQ(IntegerValues(grid.cell_data, "medit:ref"), expected.cell_refs);
}

std::vector<std::int64_t> IntegerValues(const std::vector<VtkAttribute>& attributes,
                                        const std::string& name) {
  const DataArray* array = FindArray(attributes, name);
  if (array == nullptr) return {};
  std::vector<std::int64_t> values;
  for (std::int64_t i = 0; i < array->value_count(); ++i) {
    values.push_back(static_cast<std::int64_t>(array->AsDouble(i)));
  }
  return values;
}

std::vector<std::int64_t> FixedPoints(const UnstructuredGrid& grid) {
  std::vector<std::int64_t> fixed;
  const DataArray* array = FindArray(grid.point_data, "fixed");
  if (array == nullptr) return fixed;
  for (std::int64_t point = 0; point < array->tuple_count(); ++point) {
    for (int c = 0; c < array->components; ++c) {
      if (array->AsDouble(point * array->components + c) != 0.0) {
        fixed.push_back(point);
        break;
      }
    }
  }
  return fixed;
}

std::vector<std::int64_t> GroupedCellOrder(const GridCells& cells) {
  std::vector<int> kinds;
  for (std::int64_t cell = 0; cell < cells.size(); ++cell) {
    const int type = cells.types[cell];
    if (type != 1 && std::find(kinds.begin(), kinds.end(), type) == kinds.end()) {
      kinds.push_back(type);
    }
  }
  std::vector<std::int64_t> order;
  for (const int kind : kinds) {
    for (std::int64_t cell = 0; cell < cells.size(); ++cell) {
      if (cells.types[cell] == kind) order.push_back(cell);
    }
  }
  return order;
}

GridCells Reordered(const GridCells& cells, const std::vector<std::int64_t>& order) {
  GridCells result;
  for (const std::int64_t cell : order) {
    result.Add(
        cells.types[cell],
        std::vector<std::int64_t>(cells.nodes(cell), cells.nodes(cell) + cells.node_count(cell)));
  }
  return result;
}

void WriteText(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  ASSERT_TRUE(out.good()) << "cannot write " << path;
}

}  // namespace getme::formats::testing
