#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace getme::formats {

// An entity of a Gmsh model named by its dimension (0 point … 3 volume) and tag.
struct GmshDimTag {
  int dim = 0;
  int tag = 0;
  friend bool operator==(const GmshDimTag&, const GmshDimTag&) = default;
};

// $PhysicalNames: "dim tag "name"".
struct GmshPhysicalName {
  int dim = 0;
  int tag = 0;
  std::string name;
};

// One entity of a 4.1 $Entities section. A point entity stores its coordinates in `min` (and
// `max` = `min`); the others their bounding box as the file gives it (not recomputed after
// smoothing: Gmsh recomputes boxes itself and uses them only for display and search).
struct GmshEntity {
  int dim = 0;
  int tag = 0;
  std::array<double, 3> min{};
  std::array<double, 3> max{};
  std::vector<int> physical_tags;  // a 4.1 entity may belong to several physical groups
  std::vector<int> boundary_tags;  // signed: the sign is the orientation; empty for points
};

// A 4.1 $Nodes entity block: `count` consecutive points of the grid, classified on entity
// (dim, tag). With `parametric`, the block also carries `dim` parametric coordinates per node,
// kept in `parametric_coords` (count · dim values).
struct GmshNodeBlock {
  int dim = 0;
  int tag = 0;
  bool parametric = false;
  std::int64_t count = 0;
  std::vector<double> parametric_coords;
};

// The 2.2 per-element tag lists, flat: element i has tags values[offsets[i] .. offsets[i+1]).
// Gmsh writes [physical, elementary] (partitioned files add a partition count and partitions).
struct GmshTagLists {
  std::vector<std::int64_t> offsets{0};
  std::vector<int> values;
  std::int64_t size() const { return static_cast<std::int64_t>(offsets.size()) - 1; }
};

// How one $NodeData / $ElementData section maps to a grid array, and the tags needed to write
// it back as it was.
struct GmshDataView {
  bool on_nodes = true;    // $NodeData → point_data; $ElementData → cell_data
  std::string array_name;  // the grid array's name (the first string tag, made unique)
  std::vector<std::string> string_tags;
  std::vector<double> real_tags;
  std::vector<std::int64_t> integer_tags;  // time step, components, entry count[, partition]
  // The point / cell indices the section lists, in its order, when that is not simply every
  // point / cell in grid order. The grid array holds NaN (0 for "fixed") where nothing is listed.
  std::vector<std::int64_t> listed;
  // Read from an $ElementNodeData section that gives each element one value at all its nodes,
  // as the 2.2 writer stores cell arrays (gmsh_writer.h): the cell array is that value.
  bool element_nodes = false;
};

// A section kept byte for byte (its body between the "$Name" line and "$EndName"): $Comments,
// $Periodic, $PartitionedEntities, $ElementNodeData, $InterpolationScheme and anything unknown.
// Written back only in the same version and encoding, and only while the node and element tags
// it may refer to are kept; otherwise the writer names it in a warning. $Comments and
// $InterpolationScheme are text that refers to no tag (Gmsh writes them as text in binary files
// too) and are always written back.
struct GmshRawSection {
  std::string name;  // without '$'
  std::string body;
};

// What only a Gmsh MSH file carries beyond MeshDocument::grid (owned by the Gmsh reader/writer).
struct GmshExtras {
  int version_major = 4;  // 2 (2.2 layout) or 4 (4.1)
  bool binary = false;
  bool big_endian = false;  // a binary file written on a big-endian machine (written back little)
  int data_size = 8;        // $MeshFormat's data-size: sizeof(size_t) of a 4.1 binary file

  std::vector<GmshPhysicalName> physical_names;
  bool has_entities = false;
  std::vector<GmshEntity> entities;  // file order: points, curves, surfaces, volumes

  std::vector<std::int64_t> node_tags;       // point index → node tag
  std::vector<GmshNodeBlock> node_blocks;    // 4.1 only
  std::vector<std::int64_t> element_tags;    // cell index → element tag
  std::vector<GmshDimTag> element_entities;  // 4.1 only: cell index → its block's entity
  GmshTagLists element_tag_lists;            // 2.2 only

  std::vector<GmshDataView> data_views;  // $NodeData / $ElementData, file order
  std::vector<GmshRawSection> raw_sections;
  // Every section's name in file order ("MeshFormat", "Nodes", "NodeData", "Comments", …), so
  // the writer puts data views and raw sections back where they were.
  std::vector<std::string> section_order;
};

}  // namespace getme::formats
