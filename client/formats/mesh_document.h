#pragma once

#include <optional>

#include "formats/cgns/cgns_extras.h"
#include "formats/exodus/exodus_extras.h"
#include "formats/gmsh/gmsh_extras.h"
#include "formats/medit/medit_extras.h"
#include "formats/openfoam/openfoam_extras.h"
#include "formats/su2/su2_extras.h"
#include "formats/unstructured_grid.h"

namespace getme::formats {

// The mesh file formats the client reads and writes.
enum class FileFormat {
  kVtkLegacy,  // .vtk, VTK legacy UNSTRUCTURED_GRID, ASCII or BINARY
  kVtkXml,     // .vtu, VTK XML UnstructuredGrid
  kGmsh,       // .msh, Gmsh MSH 2.2 or 4.1, ASCII or binary
  kMedit,      // .mesh, INRIA Gamma MEDIT (ASCII)
  kOpenFoam,   // an OpenFOAM polyMesh directory (constant/polyMesh), ASCII or binary
  kCgns,       // .cgns, CGNS (HDF5 or ADF) through the CGNS library
  kSu2,        // .su2, SU2 native mesh (ASCII)
  kExodus,     // .exo .e .ex2 .g, Exodus II (netCDF) through the Exodus II library
};

enum class GmshVersion { k22, k41 };

// Where a .vtu file's binary arrays live: base64 inside each DataArray, or raw bytes in one
// AppendedData block after the grid.
enum class VtuLayout { kInline, kAppended };

// How to write a document. Each format uses the fields that apply to it; a format without a
// binary variant (MEDIT .mesh) rejects kBinary with InvalidArgument.
struct WriteOptions {
  Encoding encoding = Encoding::kAscii;
  GmshVersion gmsh_version = GmshVersion::k41;
  VtuLayout vtu_layout = VtuLayout::kAppended;
  bool vtu_compress = false;  // zlib-compressed blocks (vtkZLibDataCompressor)
  // Threads that may format a legacy VTK file's ASCII numbers (formats/parallel_text.h). The
  // file's bytes do not depend on it.
  int threads = 1;
};

// A mesh file of any format, read into memory with everything needed to write it back.
//
// `grid` is the neutral content every reader produces and every writer consumes, so any format
// converts to any other:
// - points: 3 components, in the file's node order (node i of the file = point i);
// - cells: every element of the file of any dimension (volumes, surfaces, lines, vertices), in
//   file order, as VTK cell type codes with VTK's node order. In particular the linear wedge is
//   in VTK's order, mirrored against Gmsh's and MEDIT's prism (docs/node-orders.md);
// - point_data / cell_data / field_data: named numeric arrays. Readers store format tags under
//   meshio's names so the conventions meet: "gmsh:physical" and "gmsh:geometrical" (cell data,
//   Int32), "medit:ref" (point and cell data, Int32). A point array named "fixed" (nonzero =
//   fixed) marks caller-fixed nodes in every format (MEDIT: RequiredVertices).
//
// The extras hold what only one format has (Gmsh physical names, entities, node and element
// tags; MEDIT's keyword sections that carry no mesh elements). A writer uses its own format's
// extras when they are present (same-format round trip, nothing lost) and derives what it needs
// from `grid` otherwise; what it cannot store it names in a warning, never drops silently.
struct MeshDocument {
  FileFormat format = FileFormat::kVtkLegacy;
  WriteOptions as_read;  // the input's encoding / version / layout: the default when writing back
  UnstructuredGrid grid;
  std::optional<GmshExtras> gmsh;
  std::optional<MeditExtras> medit;
  std::optional<OpenFoamExtras> openfoam;
  std::optional<CgnsExtras> cgns;
  std::optional<Su2Extras> su2;
  std::optional<ExodusExtras> exodus;
};

}  // namespace getme::formats
