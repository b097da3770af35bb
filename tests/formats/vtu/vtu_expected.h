#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "formats/mesh_document.h"

namespace getme::formats::testing {

// The content of a .vtu file as write_vtu_fixtures.py found it, independently of ParseVtu (see
// the sidecar format there).
struct ExpectedArray {
  std::string where;  // point, cell, field
  std::string name;
  std::string xml_type;  // Int8 … Float64
  int components = 1;
  std::int64_t tuples = 0;
  std::string keyword;  // the legacy section the reader must file it under: SCALARS, FIELD, …
  std::vector<std::string> values;
};

struct ExpectedContent {
  std::vector<double> points;  // x y z per point
  std::vector<std::uint8_t> types;
  std::vector<std::vector<std::int64_t>> cells;
  std::vector<ExpectedArray> arrays;
};

// Reads <path>.expected; fails the test (and returns what it has) if it cannot.
ExpectedContent ReadExpected(const std::string& vtu_path);

// Asserts (gtest) that `grid` holds exactly the expected points (bit for bit), cells and arrays
// (type, components, values bit for bit, and legacy section keyword).
void ExpectContent(const ExpectedContent& expected, const UnstructuredGrid& grid);

// Where the fixtures are: GETME_VTU_FIXTURES/<name>.
std::string FixturePath(const std::string& name);

}  // namespace getme::formats::testing
