#include "remote/grid_upload.h"

#include <array>
#include <limits>
#include <optional>

#include "absl/strings/str_cat.h"
#include "formats/vtk_cell_type.h"
#include "getme_wire/engine_mesh.h"
#include "getme_wire/mesh_fields.h"

namespace getme::remote {
namespace {

// The wire group (wire/getme_wire/mesh_fields.h) of a VTK cell type; -1 for other cells.
int WireGroupOfCell(int vtk_cell_type) {
  switch (vtk_cell_type) {
    case formats::kVtkTetra:
      return wire::WireGroupOf(ElementType::kTetrahedron);
    case formats::kVtkHexahedron:
      return wire::WireGroupOf(ElementType::kHexahedron);
    case formats::kVtkWedge:
      return wire::WireGroupOf(ElementType::kPrism);
    case formats::kVtkPyramid:
      return wire::WireGroupOf(ElementType::kPyramid);
    default:
      return -1;
  }
}

}  // namespace

absl::StatusOr<GridWireMesh> ToWireMesh(const formats::UnstructuredGrid& file) {
  const formats::GridCells& cells = file.cells;
  if (file.points.components != 3) {
    return absl::InvalidArgumentError(
        absl::StrCat("POINTS has ", file.points.components, " components; expected 3"));
  }
  GridWireMesh result;
  v1::Mesh& mesh = result.mesh;
  const std::int64_t points = file.point_count();
  mesh.mutable_coordinates()->Reserve(static_cast<int>(3 * points));
  for (std::int64_t i = 0; i < 3 * points; ++i) mesh.add_coordinates(file.points.AsDouble(i));

  // Cells are grouped by type, so collect each group's cell indices first (file order within).
  std::array<std::vector<std::int64_t>, wire::kWireElementGroupCount> group_cells;
  for (std::int64_t cell = 0; cell < cells.size(); ++cell) {
    const int code = cells.types[cell];
    const int group = WireGroupOfCell(code);
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
  for (int group = 0; group < wire::kWireElementGroupCount; ++group) {
    google::protobuf::RepeatedField<std::uint32_t>& field = *wire::MutableConnectivity(mesh, group);
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

  if (const formats::DataArray* fixed = formats::FindArray(file.point_data, "fixed")) {
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

absl::Status ApplyCoordinates(std::span<const double> coordinates,
                              formats::UnstructuredGrid& file) {
  if (absl::Status status = wire::CheckCoordinateCount(coordinates, file.point_count());
      !status.ok()) {
    return status;
  }
  file.points.type = formats::VtkDataType::kDouble;
  file.points.components = 3;
  file.points.integers.clear();
  file.points.reals.assign(coordinates.begin(), coordinates.end());
  return absl::OkStatus();
}

absl::Status AddSurfaceGroups(std::span<const formats::TaggedFace> faces, v1::Mesh& mesh) {
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const formats::TaggedFace& face = faces[f];
    if (face.tag == 0) continue;
    if (face.tag < 0 || face.tag > std::numeric_limits<std::uint32_t>::max()) {
      return absl::InvalidArgumentError(
          absl::StrCat("tagged face ", f, " has tag ", face.tag,
                       ": the service takes surface group tags from 1 to ",
                       std::numeric_limits<std::uint32_t>::max()));
    }
    google::protobuf::RepeatedField<std::uint32_t>* nodes =
        face.size == 3 ? mesh.mutable_group_triangles() : mesh.mutable_group_quads();
    for (int k = 0; k < face.size; ++k) {
      if (face.nodes[k] < 0 || face.nodes[k] > std::numeric_limits<std::uint32_t>::max()) {
        return absl::InvalidArgumentError(absl::StrCat("tagged face ", f, " has node ",
                                                       face.nodes[k],
                                                       ", which does not fit the wire's uint32"));
      }
      nodes->Add(static_cast<std::uint32_t>(face.nodes[k]));
    }
    (face.size == 3 ? mesh.mutable_triangle_groups() : mesh.mutable_quad_groups())
        ->Add(static_cast<std::uint32_t>(face.tag));
  }
  return absl::OkStatus();
}

}  // namespace getme::remote
