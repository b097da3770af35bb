#include "remote/wire_mesh.h"

#include <array>
#include <limits>
#include <optional>

#include "absl/strings/str_cat.h"
#include "formats/vtk_cell_type.h"

namespace getme::remote {
namespace {

// VTK wedge ↔ paper prism (NOTES.md §1); the permutation is its own inverse.
constexpr std::array<int, 6> kWedgeOrder = {0, 2, 1, 3, 5, 4};

// Wire element groups in numbering order (mesh.proto).
enum WireGroup { kTetrahedra, kHexahedra, kWedges, kPyramids, kWireGroupCount };

int WireGroupOf(int vtk_cell_type) {
  switch (vtk_cell_type) {
    case formats::kVtkTetra:
      return kTetrahedra;
    case formats::kVtkHexahedron:
      return kHexahedra;
    case formats::kVtkWedge:
      return kWedges;
    case formats::kVtkPyramid:
      return kPyramids;
    default:
      return -1;
  }
}

google::protobuf::RepeatedField<std::uint32_t>* GroupField(v1::Mesh& mesh, int group) {
  switch (group) {
    case kTetrahedra:
      return mesh.mutable_tetrahedra();
    case kHexahedra:
      return mesh.mutable_hexahedra();
    case kWedges:
      return mesh.mutable_wedges();
    default:
      return mesh.mutable_pyramids();
  }
}

int WireGroupOf(ElementType type) {
  switch (type) {
    case ElementType::kTetrahedron:
      return kTetrahedra;
    case ElementType::kHexahedron:
      return kHexahedra;
    case ElementType::kPrism:
      return kWedges;
    case ElementType::kPyramid:
      break;
  }
  return kPyramids;
}

absl::Status CheckCoordinateCount(std::span<const double> coordinates, std::int64_t nodes) {
  if (static_cast<std::int64_t>(coordinates.size()) != 3 * nodes) {
    return absl::InvalidArgumentError(absl::StrCat("the result has ", coordinates.size(),
                                                   " coordinates, but ", nodes, " nodes need ",
                                                   3 * nodes));
  }
  return absl::OkStatus();
}

}  // namespace

absl::StatusOr<VtkWireMesh> ToWireMesh(const formats::VtkFile& file) {
  const formats::VtkCells& cells = file.cells;
  if (file.points.components != 3) {
    return absl::InvalidArgumentError(
        absl::StrCat("POINTS has ", file.points.components, " components; expected 3"));
  }
  VtkWireMesh result;
  v1::Mesh& mesh = result.mesh;
  const std::int64_t points = file.point_count();
  mesh.mutable_coordinates()->Reserve(static_cast<int>(3 * points));
  for (std::int64_t i = 0; i < 3 * points; ++i) mesh.add_coordinates(file.points.AsDouble(i));

  // Cells are grouped by type, so collect each group's cell indices first (file order within).
  std::array<std::vector<std::int64_t>, kWireGroupCount> group_cells;
  for (std::int64_t cell = 0; cell < cells.size(); ++cell) {
    const int code = cells.types[cell];
    const int group = WireGroupOf(code);
    if (group >= 0) {
      group_cells[group].push_back(cell);
      continue;
    }
    const std::optional<formats::VtkCellTypeInfo> info = formats::CellTypeInfo(code);
    if (!info || info->role != formats::VtkCellRole::kPassthrough) {
      return absl::InvalidArgumentError(
          absl::StrCat("cell ", cell, " has VTK type ", code, " (", info ? info->name : "unknown",
                       "), which getme can neither smooth nor pass through"));
    }
  }
  for (int group = 0; group < kWireGroupCount; ++group) {
    google::protobuf::RepeatedField<std::uint32_t>& field = *GroupField(mesh, group);
    for (const std::int64_t cell : group_cells[group]) {
      result.element_cells.push_back(cell);
      const std::int64_t* nodes = cells.nodes(cell);
      for (std::int64_t k = 0; k < cells.node_count(cell); ++k) {
        if (nodes[k] < 0 || nodes[k] > std::numeric_limits<std::uint32_t>::max()) {
          return absl::InvalidArgumentError(
              absl::StrCat("cell ", cell, " refers to point ", nodes[k],
                           ", which is not a node index the wire can carry (0 to 2^32-1)"));
        }
        field.Add(static_cast<std::uint32_t>(nodes[k]));
      }
    }
  }

  if (const formats::VtkDataArray* fixed = formats::FindArray(file.point_data, "fixed")) {
    if (fixed->tuple_count() != points) {
      return absl::InvalidArgumentError(absl::StrCat("point data 'fixed' has ",
                                                     fixed->tuple_count(),
                                                     " tuples, but there are ", points, " points"));
    }
    for (std::int64_t node = 0; node < points; ++node) {
      bool is_fixed = false;
      for (int c = 0; c < fixed->components; ++c) {
        is_fixed = is_fixed || fixed->AsDouble(node * fixed->components + c) != 0.0;
      }
      if (is_fixed) mesh.add_fixed_nodes(static_cast<std::uint32_t>(node));
    }
  }
  return result;
}

v1::Mesh ToWireMesh(const Mesh& mesh) {
  v1::Mesh wire;
  wire.mutable_coordinates()->Reserve(static_cast<int>(3 * mesh.node_count()));
  for (std::int64_t node = 0; node < mesh.node_count(); ++node) {
    wire.add_coordinates(mesh.x()[node]);
    wire.add_coordinates(mesh.y()[node]);
    wire.add_coordinates(mesh.z()[node]);
    if (mesh.is_fixed(static_cast<NodeId>(node))) {
      wire.add_fixed_nodes(static_cast<std::uint32_t>(node));
    }
  }
  for (const ElementType type : kAllElementTypes) {
    const std::vector<NodeId>& nodes = mesh.block(type).nodes;
    google::protobuf::RepeatedField<std::uint32_t>& field = *GroupField(wire, WireGroupOf(type));
    const int count = NodeCount(type);
    for (std::size_t start = 0; start < nodes.size(); start += count) {
      for (int k = 0; k < count; ++k) {
        const int source = type == ElementType::kPrism ? kWedgeOrder[k] : k;
        field.Add(static_cast<std::uint32_t>(nodes[start + source]));
      }
    }
  }
  return wire;
}

absl::Status ApplyCoordinates(std::span<const double> coordinates, formats::VtkFile& file) {
  if (absl::Status status = CheckCoordinateCount(coordinates, file.point_count()); !status.ok()) {
    return status;
  }
  file.points.type = formats::VtkDataType::kDouble;
  file.points.components = 3;
  file.points.integers.clear();
  file.points.reals.assign(coordinates.begin(), coordinates.end());
  return absl::OkStatus();
}

absl::Status ApplyCoordinates(std::span<const double> coordinates, Mesh& mesh) {
  if (absl::Status status = CheckCoordinateCount(coordinates, mesh.node_count()); !status.ok()) {
    return status;
  }
  for (std::int64_t node = 0; node < mesh.node_count(); ++node) {
    mesh.x()[node] = coordinates[3 * node];
    mesh.y()[node] = coordinates[3 * node + 1];
    mesh.z()[node] = coordinates[3 * node + 2];
  }
  return absl::OkStatus();
}

}  // namespace getme::remote
