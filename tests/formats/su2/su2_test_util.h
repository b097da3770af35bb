#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "formats/mesh_document.h"

namespace getme::formats::testing {

// The shared SU2 meshes (read only) and the files make_su2_inputs.py writes (SU2_FIXTURES).
std::string SharedSu2(const std::string& name);
std::string Su2FixturePath(const std::string& name);

// The rows of an SU2 file's section as token lists, found by plain text search independently of
// the reader: the `count` rows after the line starting with `keyword` (e.g. "NELEM=",
// "MARKER_TAG= load" then its MARKER_ELEMS rows).
std::vector<std::vector<std::string>> SectionRows(const std::string& text,
                                                  const std::string& keyword);

// The indices (in `grid.cells`, ascending) of the volume cells that are invalid (some corner
// determinant ≤ 0, core's IsValid); the error of GridToMesh where the grid makes no mesh.
absl::StatusOr<std::vector<std::int64_t>> InvalidVolumeCellIndices(const UnstructuredGrid& grid);

// How many volume cells of `grid` are invalid, as above; -1 where the grid makes no mesh.
std::int64_t InvalidVolumeCells(const UnstructuredGrid& grid);

}  // namespace getme::formats::testing
