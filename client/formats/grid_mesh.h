#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "absl/status/status.h"
#include "absl/status/statusor.h"
#include "formats/unstructured_grid.h"
#include "getme/mesh/mesh.h"
#include "getme/mesh/mesh_quality.h"

namespace getme::formats {

// The engine mesh of a grid (of any format) and how its elements map back to the grid's cells.
struct GridMesh {
  Mesh mesh;
  std::vector<std::int64_t> element_cells;  // element id → cell index
  std::vector<ElementId> cell_elements;     // cell index → element id; -1 for passthrough cells
};

// Builds the engine mesh: every point becomes a node (same ids), volume cells — tetra (10),
// hexahedron (12), wedge (13), pyramid (14) — become elements in file order. VTK's wedge is
// mirrored against the paper's prism (getme/elements/node_orders.h): paper (p0..p5) = VTK (v0, v2,
// v1, v3, v5, v4); the other three keep their order. Linear cells of dimension 0–2 (vertex … quad)
// are passthrough: not smoothed, they follow their nodes. A point-data array named `fixed` (any
// numeric type, any component nonzero = fixed) marks caller-fixed nodes.
//
// InvalidArgument for: a file without volume cells (naming the cell types it has), a cell type
// that is neither (naming the cell and its type), a non-finite coordinate, a volume cell
// listing a point twice, a `fixed` array of the wrong length.
absl::StatusOr<GridMesh> GridToMesh(const UnstructuredGrid& file);

// Writes the smoothed coordinates of `mesh` into `file` (as double, so nothing is rounded) and
// sets the per-cell arrays `mean_ratio` (Def. 3, 0 for an invalid element), `warpage`
// (Sec. 4.4) and `valid` (Def. 2, 1/0) computed with the core kernels. Passthrough cells get
// mean_ratio = -1, warpage = -1, valid = 0: they have no volume quality. Existing arrays of those
// names are replaced where they are; new ones are appended as SCALARS. `cell_elements` is
// GridMesh::cell_elements of the conversion the mesh came from. `measures`, if given, are
// MeasureElements of `mesh` as it is now (SmoothingResult::after_elements), written instead of
// measuring the mesh again; InvalidArgument if their sizes are not the mesh's.
absl::Status UpdateGridFromMesh(const Mesh& mesh, std::span<const ElementId> cell_elements,
                                UnstructuredGrid& file, const ElementMeasures* measures = nullptr);

// A new grid holding `mesh` (elements as cells in element-id order, the same three quality
// arrays, and a `fixed` point-data array when any node is fixed); for meshes that did not come
// from a file.
UnstructuredGrid GridFromMesh(const Mesh& mesh, std::string title);

}  // namespace getme::formats
