#pragma once

#include <cstdint>
#include <vector>

#include "absl/status/statusor.h"
#include "absl/strings/string_view.h"
#include "formats/mesh_document.h"

namespace getme::formats {

// The grid cell indices (ascending) of a Gmsh physical group, named by its $PhysicalNames name
// (every dimension with that name), its physical tag (a number: that tag in any dimension) or
// "DIM:TAG". Membership comes from the 4.1 entities of document.gmsh (an entity may belong to
// several groups), else from the "gmsh:physical" cell data (2.2, meshio-converted files), with
// the group's dimension that of the cell. A named group without cells gives an empty vector;
// NotFound, listing the groups there are (name, dim, tag), when nothing matches.
absl::StatusOr<std::vector<std::int64_t>> GmshGroupCells(const MeshDocument& document,
                                                         absl::string_view group);

}  // namespace getme::formats
