#include "formats/grid_mesh.h"

#include <array>
#include <cmath>
#include <map>
#include <optional>
#include <utility>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_join.h"
#include "formats/vtk_cell_type.h"
#include "getme/elements/node_orders.h"
#include "getme/elements/vec3.h"
#include "getme/parallel/thread_pool.h"

namespace getme::formats {
namespace {

constexpr absl::string_view kSupportedVolumeCells =
    "getme smooths tetrahedra (10), hexahedra (12), wedges (13), pyramids (14)";

int CellCode(ElementType type) {
  switch (type) {
    case ElementType::kTetrahedron:
      return kVtkTetra;
    case ElementType::kHexahedron:
      return kVtkHexahedron;
    case ElementType::kPyramid:
      return kVtkPyramid;
    case ElementType::kPrism:
      break;
  }
  return kVtkWedge;
}

// "400 quad cells (VTK type 9) and 12 line cells (VTK type 3)".
std::string DescribeCellTypes(const GridCells& cells) {
  std::map<int, std::int64_t> counts;
  for (const std::uint8_t type : cells.types) ++counts[type];
  std::vector<std::string> parts;
  for (const auto& [code, count] : counts) {
    const std::optional<VtkCellTypeInfo> info = CellTypeInfo(code);
    parts.push_back(absl::StrCat(count, " ", info ? info->name : "unknown", " cell",
                                 count == 1 ? "" : "s", " (VTK type ", code, ")"));
  }
  if (parts.empty()) return "no cells";
  if (parts.size() == 1) return parts.front();
  const std::string last = parts.back();
  parts.pop_back();
  return absl::StrCat(absl::StrJoin(parts, ", "), " and ", last);
}

absl::Status CheckCellStructure(const UnstructuredGrid& file) {
  const GridCells& cells = file.cells;
  if (cells.offsets.size() != cells.types.size() + 1 || cells.offsets.front() != 0 ||
      cells.offsets.back() != static_cast<std::int64_t>(cells.connectivity.size())) {
    return absl::InvalidArgumentError(absl::StrCat("inconsistent cells: ", cells.types.size(),
                                                   " types, ", cells.offsets.size(), " offsets, ",
                                                   cells.connectivity.size(), " node ids"));
  }
  if (file.points.components != 3) {
    return absl::InvalidArgumentError(
        absl::StrCat("POINTS has ", file.points.components, " components; expected 3"));
  }
  return absl::OkStatus();
}

// Reads the `fixed` point-data array, if any, into the builder.
absl::Status ApplyFixedArray(const UnstructuredGrid& file, MeshBuilder& builder) {
  const DataArray* fixed = FindArray(file.point_data, "fixed");
  if (fixed == nullptr) return absl::OkStatus();
  if (fixed->tuple_count() != file.point_count()) {
    return absl::InvalidArgumentError(absl::StrCat("point data 'fixed' has ", fixed->tuple_count(),
                                                   " tuples, but there are ", file.point_count(),
                                                   " points"));
  }
  for (std::int64_t node = 0; node < file.point_count(); ++node) {
    bool is_fixed = false;
    for (int c = 0; c < fixed->components; ++c) {
      is_fixed = is_fixed || fixed->AsDouble(node * fixed->components + c) != 0.0;
    }
    if (is_fixed) builder.SetFixed(static_cast<NodeId>(node));
  }
  return absl::OkStatus();
}

DataArray ScalarArray(std::string name, VtkDataType type) {
  DataArray array;
  array.name = std::move(name);
  array.type = type;
  array.components = 1;
  return array;
}

// Puts `array` into `attributes`: in place of an existing array of the same name (inside a
// FIELD it stays a FIELD array; any other section is replaced by SCALARS), else appended.
void SetArray(std::vector<VtkAttribute>& attributes, DataArray array) {
  for (VtkAttribute& attribute : attributes) {
    for (DataArray& existing : attribute.arrays) {
      if (existing.name != array.name) continue;
      if (attribute.kind == VtkAttributeKind::kField) {
        existing = std::move(array);
      } else {
        attribute = VtkAttribute{VtkAttributeKind::kScalars, array.name, "default", {}};
        attribute.arrays.push_back(std::move(array));
      }
      return;
    }
  }
  VtkAttribute attribute{VtkAttributeKind::kScalars, array.name, "default", {}};
  attribute.arrays.push_back(std::move(array));
  attributes.push_back(std::move(attribute));
}

void SetQualityArrays(const ElementMeasures& measures, std::span<const ElementId> cell_elements,
                      std::vector<VtkAttribute>& cell_data) {
  DataArray mean_ratio = ScalarArray("mean_ratio", VtkDataType::kDouble);
  DataArray warpage = ScalarArray("warpage", VtkDataType::kDouble);
  DataArray valid = ScalarArray("valid", VtkDataType::kInt);
  mean_ratio.reals.reserve(cell_elements.size());
  warpage.reals.reserve(cell_elements.size());
  valid.integers.reserve(cell_elements.size());
  for (const ElementId element : cell_elements) {
    if (element < 0) {
      // Passthrough cells have no volume quality: -1 marks "not measured".
      mean_ratio.reals.push_back(-1.0);
      warpage.reals.push_back(-1.0);
      valid.integers.push_back(0);
      continue;
    }
    mean_ratio.reals.push_back(measures.quality[element]);
    warpage.reals.push_back(measures.warpage[element]);
    valid.integers.push_back(measures.valid[element]);
  }
  SetArray(cell_data, std::move(mean_ratio));
  SetArray(cell_data, std::move(warpage));
  SetArray(cell_data, std::move(valid));
}

void SetCoordinates(const Mesh& mesh, DataArray& points) {
  points.type = VtkDataType::kDouble;
  points.components = 3;
  points.integers.clear();
  points.reals.resize(3 * mesh.node_count());
  for (std::int64_t node = 0; node < mesh.node_count(); ++node) {
    points.reals[3 * node] = mesh.x()[node];
    points.reals[3 * node + 1] = mesh.y()[node];
    points.reals[3 * node + 2] = mesh.z()[node];
  }
}

}  // namespace

absl::StatusOr<GridMesh> GridToMesh(const UnstructuredGrid& file) {
  if (absl::Status status = CheckCellStructure(file); !status.ok()) return status;
  const GridCells& cells = file.cells;
  const std::int64_t point_count = file.point_count();

  // Refuse what cannot be smoothed before building anything.
  std::int64_t volume_cells = 0;
  for (std::int64_t cell = 0; cell < cells.size(); ++cell) {
    const int code = cells.types[cell];
    const std::optional<VtkCellTypeInfo> info = CellTypeInfo(code);
    if (!info || info->role == VtkCellRole::kUnsupported) {
      return absl::InvalidArgumentError(absl::StrCat(
          "cell ", cell, " has VTK type ", code, " (", info ? info->name : "unknown",
          "), which getme can neither smooth nor pass through; ", kSupportedVolumeCells,
          " and keeps vertices, lines, triangles, polygons and quads (VTK types 1-9) unchanged"));
    }
    if (info->role == VtkCellRole::kVolumeElement) ++volume_cells;
  }
  if (volume_cells == 0) {
    return absl::InvalidArgumentError(absl::StrCat("no volume elements: the file has ",
                                                   DescribeCellTypes(cells), "; ",
                                                   kSupportedVolumeCells));
  }

  MeshBuilder builder;
  builder.Reserve(point_count, volume_cells);
  for (std::int64_t node = 0; node < point_count; ++node) {
    const double x = file.points.AsDouble(3 * node);
    const double y = file.points.AsDouble(3 * node + 1);
    const double z = file.points.AsDouble(3 * node + 2);
    if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z)) {
      return absl::InvalidArgumentError(
          absl::StrCat("point ", node, " has a non-finite coordinate (", x, ", ", y, ", ", z, ")"));
    }
    builder.AddNode(x, y, z);
  }

  GridMesh result;
  result.element_cells.reserve(volume_cells);
  result.cell_elements.assign(cells.size(), -1);
  std::array<std::int64_t, kMaxElementNodes> nodes{};
  for (std::int64_t cell = 0; cell < cells.size(); ++cell) {
    const std::optional<ElementType> type = ElementTypeOfCell(cells.types[cell]);
    if (!type) continue;
    const int node_count = NodeCount(*type);
    const absl::string_view cell_name = CellTypeInfo(cells.types[cell])->name;
    if (cells.node_count(cell) != node_count) {
      return absl::InvalidArgumentError(absl::StrCat("cell ", cell, " (", cell_name, ") has ",
                                                     cells.node_count(cell), " node ids; expected ",
                                                     node_count));
    }
    const std::int64_t* vtk_nodes = cells.nodes(cell);
    for (int k = 0; k < node_count; ++k) {
      nodes[k] = vtk_nodes[VtkToPaperPosition(*type, k)];
      if (nodes[k] < 0 || nodes[k] >= point_count) {
        return absl::InvalidArgumentError(absl::StrCat("cell ", cell, " (", cell_name,
                                                       ") refers to point ", nodes[k],
                                                       ", but there are ", point_count, " points"));
      }
      for (int j = 0; j < k; ++j) {
        if (nodes[j] == nodes[k]) {
          return absl::InvalidArgumentError(
              absl::StrCat("cell ", cell, " (", cell_name, ") lists point ", nodes[k], " twice"));
        }
      }
    }
    result.cell_elements[cell] = static_cast<ElementId>(result.element_cells.size());
    result.element_cells.push_back(cell);
    builder.AddElement(*type, std::span<const std::int64_t>(nodes.data(), node_count));
  }
  if (absl::Status status = ApplyFixedArray(file, builder); !status.ok()) return status;

  absl::StatusOr<Mesh> mesh = std::move(builder).Build();
  if (!mesh.ok()) {
    return absl::Status(mesh.status().code(),
                        absl::StrCat("building the mesh (element ids number the volume cells in "
                                     "file order): ",
                                     mesh.status().message()));
  }
  result.mesh = *std::move(mesh);
  return result;
}

absl::Status UpdateGridFromMesh(const Mesh& mesh, std::span<const ElementId> cell_elements,
                                UnstructuredGrid& file, const ElementMeasures* measures) {
  if (mesh.node_count() != file.point_count()) {
    return absl::InvalidArgumentError(absl::StrCat("the mesh has ", mesh.node_count(),
                                                   " nodes, but the file has ", file.point_count(),
                                                   " points"));
  }
  if (static_cast<std::int64_t>(cell_elements.size()) != file.cells.size()) {
    return absl::InvalidArgumentError(absl::StrCat("the cell map has ", cell_elements.size(),
                                                   " entries, but the file has ", file.cells.size(),
                                                   " cells"));
  }
  for (std::size_t cell = 0; cell < cell_elements.size(); ++cell) {
    if (cell_elements[cell] >= mesh.element_count()) {
      return absl::InvalidArgumentError(absl::StrCat("cell ", cell, " maps to element ",
                                                     cell_elements[cell], ", but the mesh has ",
                                                     mesh.element_count(), " elements"));
    }
  }
  const auto elements = static_cast<std::size_t>(mesh.element_count());
  if (measures != nullptr &&
      (measures->quality.size() != elements || measures->warpage.size() != elements ||
       measures->valid.size() != elements)) {
    return absl::InvalidArgumentError(
        absl::StrCat("the element measures given have ", measures->quality.size(), " qualities, ",
                     measures->warpage.size(), " warpages and ", measures->valid.size(),
                     " validity flags, but the mesh has ", elements, " elements"));
  }
  SetCoordinates(mesh, file.points);
  if (measures != nullptr) {
    SetQualityArrays(*measures, cell_elements, file.cell_data);
  } else {
    ThreadPool pool(1);
    SetQualityArrays(MeasureElements(mesh, pool), cell_elements, file.cell_data);
  }
  return absl::OkStatus();
}

UnstructuredGrid GridFromMesh(const Mesh& mesh, std::string title) {
  UnstructuredGrid file;
  file.title = std::move(title);
  SetCoordinates(mesh, file.points);
  std::vector<ElementId> cell_elements;
  std::vector<std::int64_t> nodes;
  for (ElementId element = 0; element < mesh.element_count(); ++element) {
    const std::span<const NodeId> engine_nodes = mesh.element_nodes(element);
    const ElementType type = mesh.type(element);
    nodes.clear();
    for (std::size_t k = 0; k < engine_nodes.size(); ++k) {
      nodes.push_back(engine_nodes[VtkToPaperPosition(type, static_cast<int>(k))]);
    }
    file.cells.Add(CellCode(type), nodes);
    cell_elements.push_back(element);
  }
  ThreadPool pool(1);
  SetQualityArrays(MeasureElements(mesh, pool), cell_elements, file.cell_data);
  bool any_fixed = false;
  DataArray fixed = ScalarArray("fixed", VtkDataType::kInt);
  for (std::int64_t node = 0; node < mesh.node_count(); ++node) {
    const bool is_fixed = mesh.is_fixed(static_cast<NodeId>(node));
    any_fixed = any_fixed || is_fixed;
    fixed.integers.push_back(is_fixed ? 1 : 0);
  }
  if (any_fixed) SetArray(file.point_data, std::move(fixed));
  return file;
}

}  // namespace getme::formats
