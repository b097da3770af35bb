#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace getme::formats {

// One element block of an Exodus file as read. Its cells are consecutive in the grid, blocks in
// file order; the grid's cell array "exodus:block" holds the block id of each of them.
struct ExodusBlock {
  std::int64_t id = 0;
  std::string name;      // "" if the file names none
  std::string topology;  // the file's element type, as spelled there ("TETRA", "hex8", …)
  std::int64_t cell_count = 0;
  // Per-element attributes (num_attr per element, element-major) and their names; Exodus keeps
  // e.g. shell thicknesses here. Written back when the block keeps its cells.
  std::vector<std::string> attribute_names;
  std::vector<double> attributes;

  bool operator==(const ExodusBlock&) const = default;
};

// A side set: faces of volume elements, each the pair (element, local side) with Exodus's side
// numbering (exodus_element_types.h). Each entry is also a triangle or quad cell of the grid,
// after the block cells, whose "exodus:sideset" cell value is this set's id.
struct ExodusSideSet {
  std::int64_t id = 0;
  std::string name;
  std::vector<std::int64_t> elements;  // 1-based element numbers, block order (as in the file)
  std::vector<std::int64_t> sides;     // 1-based local side numbers
  std::vector<double> distribution_factors;  // empty if the file has none

  bool operator==(const ExodusSideSet&) const = default;
};

// A node set: nodes only, no cells. `getme smooth --fix-physical NAME` holds its nodes.
struct ExodusNodeSet {
  std::int64_t id = 0;
  std::string name;
  std::vector<std::int64_t> nodes;  // 0-based point indices
  std::vector<double> distribution_factors;

  bool operator==(const ExodusNodeSet&) const = default;
};

// What only an Exodus II file carries beyond MeshDocument::grid (owned by the Exodus
// reader/writer), so that Exodus → Exodus keeps block, set and number-map identities.
struct ExodusExtras {
  std::string title;
  std::vector<ExodusBlock> blocks;
  std::vector<ExodusSideSet> side_sets;
  std::vector<ExodusNodeSet> node_sets;
  // The files' node_num_map / elem_num_map (global ids of nodes and elements, 1-based in the
  // file order); empty when the file has none or they are the identity.
  std::vector<std::int64_t> node_number_map;
  std::vector<std::int64_t> element_number_map;

  bool operator==(const ExodusExtras&) const = default;
};

}  // namespace getme::formats
