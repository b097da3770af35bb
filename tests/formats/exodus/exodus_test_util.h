#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "formats/mesh_document.h"

namespace getme::formats::testing {

// Path of a file in the fixture directory (write_fixtures.py's output, EXODUS_FIXTURES).
std::string ExodusFixture(const std::string& name);

// A sidecar NAME.json: what an Exodus file must read as (written by write_fixtures.py).
struct ExodusExpected {
  std::vector<double> points;
  std::vector<std::vector<std::int64_t>> cells;  // VTK code, then nodes in VTK order
  std::vector<std::int64_t> block_ids;           // per block cell
  std::vector<std::pair<std::int64_t, std::vector<std::int64_t>>> side_faces;
  struct NodeSet {
    std::int64_t id = 0;
    std::string name;
    std::vector<std::int64_t> nodes;
  };
  std::vector<NodeSet> node_sets;
};
ExodusExpected ReadExodusExpected(const std::string& name);

// The grid's cells as {VTK code, nodes...} rows.
std::vector<std::vector<std::int64_t>> CellRows(const GridCells& cells);

// The values of the integer cell array `name` (empty if absent).
std::vector<std::int64_t> CellIntegers(const UnstructuredGrid& grid, const std::string& name);

// Asserts (gtest) that `document` holds what `expected` says: points bit for bit, block cells
// then side faces, block ids and side set ids per cell, node sets.
void ExpectExodusContent(const ExodusExpected& expected, const MeshDocument& document);

}  // namespace getme::formats::testing
