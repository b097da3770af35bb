#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace getme::formats {

// The cell array in which a CGNS document marks each cell's boundary condition: the 1-based
// index into CgnsExtras::boundary_conditions, 0 for cells in none (Int32, meshio-style name).
inline constexpr char kCgnsBcArray[] = "cgns:bc";

// One BC_t of the zone (SIDS §9.3): a named set of boundary elements (GridLocation FaceCenter,
// EdgeCenter, … or the pre-3.1 ElementRange/ElementList: the cells whose "cgns:bc" value is this
// condition's index) or of nodes (GridLocation Vertex: `nodes`).
struct CgnsBoundaryCondition {
  std::string name;
  int bc_type = 0;     // BCType_t value (BCWall, BCFarfield, …; cg_BCTypeName names it)
  std::string family;  // its FamilyName_t, empty without one
  bool on_nodes = false;
  std::vector<std::int64_t> nodes;  // 0-based grid points, for on_nodes only

  bool operator==(const CgnsBoundaryCondition&) const = default;
};

// A Family_t of the base (SIDS §12.6) with its FamilyBC_t type, if it has one.
struct CgnsFamily {
  std::string name;
  bool has_bc = false;
  int bc_type = 0;

  bool operator==(const CgnsFamily&) const = default;
};

// What only a CGNS file carries beyond MeshDocument::grid (owned by the CGNS reader/writer).
struct CgnsExtras {
  std::string file_type = "HDF5";  // the storage the file was read from: "HDF5" or "ADF"
  std::string base_name = "Base";
  std::string zone_name = "Zone";
  std::vector<CgnsFamily> families;
  std::vector<CgnsBoundaryCondition> boundary_conditions;

  bool operator==(const CgnsExtras&) const = default;
};

}  // namespace getme::formats
