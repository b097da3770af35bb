#include "formats/su2/su2_writer.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "absl/container/flat_hash_map.h"
#include "absl/strings/ascii.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_join.h"
#include "formats/su2/su2_mirrored_elements.h"
#include "formats/vtk_cell_type.h"
#include "formats/vtk_values.h"
#include "spdlog/spdlog.h"

namespace getme::formats {
namespace {

constexpr int kVtkVertex = 1;
constexpr int kVtkLine = 3;

bool IsBoundaryType(int type) {
  return type == kVtkTriangle || type == kVtkQuad || type == kVtkLine;
}

// The cell array the markers come from (header), or null.
const DataArray* MarkerTags(const UnstructuredGrid& grid) {
  for (const char* name : {"su2:tag", "gmsh:physical", "medit:ref"}) {
    const DataArray* tags = FindArray(grid.cell_data, name);
    if (tags != nullptr && tags->components == 1 && tags->tuple_count() == grid.cells.size()) {
      return tags;
    }
  }
  return nullptr;
}

struct Marker {
  std::string name;
  std::vector<std::int64_t> cells;
};

// The markers of `document` in the order they are written.
std::vector<Marker> CollectMarkers(const MeshDocument& document, const DataArray* tags) {
  const UnstructuredGrid& grid = document.grid;
  std::vector<Marker> markers;
  absl::flat_hash_map<std::int64_t, std::size_t> by_tag;
  const bool su2_tags = tags != nullptr && tags->name == "su2:tag";
  if (su2_tags && document.su2.has_value()) {
    for (const Su2Marker& marker : document.su2->markers) {
      if (by_tag.emplace(marker.tag, markers.size()).second) {
        markers.push_back(Marker{marker.name, {}});
      }
    }
  }
  for (std::int64_t cell = 0; cell < grid.cells.size(); ++cell) {
    if (!IsBoundaryType(grid.cells.types[cell])) continue;
    const std::int64_t tag =
        tags != nullptr ? static_cast<std::int64_t>(tags->AsDouble(cell)) : std::int64_t{0};
    auto [it, inserted] = by_tag.emplace(tag, markers.size());
    if (inserted) {
      std::string name = absl::StrCat(tag);
      if (tags != nullptr && tags->name == "gmsh:physical" && document.gmsh.has_value()) {
        const int dim = grid.cells.types[cell] == kVtkLine ? 1 : 2;
        for (const GmshPhysicalName& physical : document.gmsh->physical_names) {
          if (physical.dim == dim && physical.tag == tag && !physical.name.empty()) {
            name = physical.name;
          }
        }
      }
      markers.push_back(Marker{std::move(name), {}});
    }
    markers[it->second].cells.push_back(cell);
  }
  return markers;
}

// A marker name is the rest of its MARKER_TAG= line, without surrounding whitespace; '%' would
// start a comment.
absl::Status CheckMarkerName(absl::string_view name) {
  if (name.empty() || name.find_first_of("%\n\r") != absl::string_view::npos ||
      absl::ascii_isspace(static_cast<unsigned char>(name.front())) ||
      absl::ascii_isspace(static_cast<unsigned char>(name.back()))) {
    return absl::InvalidArgumentError(
        absl::StrCat("marker name '", name,
                     "' cannot be written to SU2: it is empty, holds '%' or a line break, or "
                     "starts or ends with a space"));
  }
  return absl::OkStatus();
}

// Names what a .su2 cannot hold and is left out.
void WarnDropped(const UnstructuredGrid& grid, const DataArray* tags, std::int64_t vertices) {
  std::vector<std::string> dropped;
  for (const VtkAttribute& attribute : grid.point_data) {
    for (const DataArray& array : attribute.arrays) {
      dropped.push_back(absl::StrCat("point data '", array.name, "'"));
    }
  }
  for (const VtkAttribute& attribute : grid.cell_data) {
    for (const DataArray& array : attribute.arrays) {
      if (&array != tags) dropped.push_back(absl::StrCat("cell data '", array.name, "'"));
    }
  }
  for (const VtkAttribute& attribute : grid.field_data) {
    for (const DataArray& array : attribute.arrays) {
      dropped.push_back(absl::StrCat("field data '", array.name, "'"));
    }
  }
  if (vertices > 0) dropped.push_back(absl::StrCat(vertices, " vertex cells"));
  if (!dropped.empty()) {
    spdlog::warn("SU2 .su2 meshes hold no data arrays or vertex cells; not written: {}",
                 absl::StrJoin(dropped, ", "));
  }
}

void AppendRow(std::string& out, const GridCells& cells, std::int64_t cell,
               const std::int64_t* nodes) {
  absl::StrAppend(&out, static_cast<int>(cells.types[cell]));
  for (std::int64_t k = 0; k < cells.node_count(cell); ++k) absl::StrAppend(&out, " ", nodes[k]);
}

}  // namespace

absl::StatusOr<std::string> SerializeSu2(const MeshDocument& document,
                                         const WriteOptions& options) {
  if (options.encoding == Encoding::kBinary) {
    return absl::InvalidArgumentError(
        "SU2 native meshes are ASCII only (SU2 reads binary meshes as CGNS)");
  }
  const UnstructuredGrid& grid = document.grid;
  const GridCells& cells = grid.cells;
  if (grid.points.components != 3 || grid.points.value_count() != 3 * grid.point_count()) {
    return absl::InvalidArgumentError(absl::StrCat("SU2 needs 3D points; the points have ",
                                                   grid.points.components, " components"));
  }
  const std::int64_t point_count = grid.point_count();
  for (std::int64_t value = 0; value < 3 * point_count; ++value) {
    if (!std::isfinite(grid.points.AsDouble(value))) {
      return absl::InvalidArgumentError(
          absl::StrCat("point ", value / 3, ": coordinate ", value % 3,
                       " is not a finite number, which an SU2 mesh cannot hold"));
    }
  }
  std::int64_t volume_count = 0;
  std::int64_t vertices = 0;
  for (std::int64_t cell = 0; cell < cells.size(); ++cell) {
    const int type = cells.types[cell];
    const std::optional<VtkCellTypeInfo> info = CellTypeInfo(type);
    const bool volume = info.has_value() && info->role == VtkCellRole::kVolumeElement;
    if (!volume && !IsBoundaryType(type) && type != kVtkVertex) {
      return absl::InvalidArgumentError(absl::StrCat(
          "cell ", cell, ": VTK type ", type, " (", info.has_value() ? info->name : "unknown",
          ") cannot be written to SU2, which holds tetrahedra, hexahedra, prisms, "
          "pyramids and boundary triangles, quads and lines"));
    }
    if (info.has_value() && info->node_count >= 0 && cells.node_count(cell) != info->node_count) {
      return absl::InvalidArgumentError(absl::StrCat("cell ", cell, ": a ", info->name, " with ",
                                                     cells.node_count(cell), " nodes"));
    }
    const std::int64_t* nodes = cells.nodes(cell);
    for (std::int64_t k = 0; k < cells.node_count(cell); ++k) {
      if (nodes[k] < 0 || nodes[k] >= point_count) {
        return absl::InvalidArgumentError(
            absl::StrCat("cell ", cell, ": node ", nodes[k], " out of range 0..", point_count - 1));
      }
    }
    if (volume) ++volume_count;
    if (type == kVtkVertex) ++vertices;
  }

  const DataArray* tags = MarkerTags(grid);
  const std::vector<Marker> markers = CollectMarkers(document, tags);
  for (const Marker& marker : markers) {
    if (absl::Status status = CheckMarkerName(marker.name); !status.ok()) return status;
  }
  WarnDropped(grid, tags, vertices);

  const Su2Extras* extras = document.su2.has_value() ? &*document.su2 : nullptr;
  const bool element_indices = extras == nullptr || extras->element_indices;
  const bool point_indices = extras == nullptr || extras->point_indices;
  std::vector<bool> mirrored;
  if (extras != nullptr && !extras->mirrored_cells.empty()) {
    mirrored.assign(static_cast<std::size_t>(cells.size()), false);
    for (const std::int64_t cell : extras->mirrored_cells) {
      if (cell < 0 || cell >= cells.size() || !ElementTypeOfCell(cells.types[cell]).has_value()) {
        return absl::InvalidArgumentError(
            absl::StrCat("inconsistent SU2 extras: mirrored cell ", cell, " is not a volume cell"));
      }
      mirrored[cell] = true;
    }
  }

  std::string out;
  // Enough for 7-digit node ids and full 17-digit coordinates, so the text is never copied to a
  // larger buffer halfway.
  out.reserve(static_cast<std::size_t>(cells.connectivity.size() * 9 + cells.size() * 12 +
                                       point_count * 75 + 4096) +
              (extras != nullptr ? extras->tail.size() : 0));
  absl::StrAppend(&out, "NDIME= 3\nNELEM= ", volume_count, "\n");
  std::int64_t element = 0;
  GridCells scratch;
  for (std::int64_t cell = 0; cell < cells.size(); ++cell) {
    if (!ElementTypeOfCell(cells.types[cell]).has_value()) continue;
    const std::int64_t* nodes = cells.nodes(cell);
    if (!mirrored.empty() && mirrored[cell]) {
      // The file's own order: the reader's renumbering is its own inverse.
      scratch.offsets = {0, cells.node_count(cell)};
      scratch.connectivity.assign(nodes, nodes + cells.node_count(cell));
      scratch.types = {cells.types[cell]};
      MirrorCellNodeOrder(scratch, 0);
      nodes = scratch.connectivity.data();
    }
    AppendRow(out, cells, cell, nodes);
    if (element_indices) absl::StrAppend(&out, " ", element);
    out.push_back('\n');
    ++element;
  }
  absl::StrAppend(&out, "NPOIN= ", point_count, "\n");
  for (std::int64_t point = 0; point < point_count; ++point) {
    for (int k = 0; k < 3; ++k) {
      if (k > 0) out.push_back(' ');
      AppendReal(out, grid.points.AsDouble(3 * point + k));
    }
    if (point_indices) absl::StrAppend(&out, " ", point);
    out.push_back('\n');
  }
  absl::StrAppend(&out, "NMARK= ", markers.size(), "\n");
  for (const Marker& marker : markers) {
    absl::StrAppend(&out, "MARKER_TAG= ", marker.name, "\nMARKER_ELEMS= ", marker.cells.size(),
                    "\n");
    for (const std::int64_t cell : marker.cells) {
      AppendRow(out, cells, cell, cells.nodes(cell));
      out.push_back('\n');
    }
  }
  if (extras != nullptr) out += extras->tail;
  return out;
}

}  // namespace getme::formats
