#pragma once

#include <string>

#include "absl/status/statusor.h"
#include "absl/strings/string_view.h"
#include "formats/mesh_document.h"

namespace getme::formats {

// Reads a CGNS file (HDF5 or ADF storage, whichever the library build opens: this Debian build
// opens both) through the CGNS mid-level library into a MeshDocument:
// - The one base of cell dimension 3 (physical dimension 3) and its one zone, which must be
//   Unstructured. Several 3D bases or several zones are refused, naming them: merging zones
//   would need their ZoneGridConnectivity to glue the shared nodes, which getme does not do.
// - GridCoordinates CoordinateX/Y/Z → grid points (typed float when all three are RealSingle).
// - Element sections in the file's order, elements in section order → grid cells with VTK codes
//   and VTK node order (cgns_element_type.h): TETRA_4, PYRA_5, PENTA_6, HEXA_8, TRI_3, QUAD_4,
//   BAR_2, NODE, and MIXED sections of these. Any other type (TETRA_10, NGON_n, …) is refused,
//   and so is a zone without volume elements.
// - BC_t nodes → CgnsExtras::boundary_conditions with their BCType and FamilyName. A condition
//   on elements (GridLocation other than Vertex, or ElementRange/ElementList) marks its cells
//   in the cell array "cgns:bc" (its 1-based index; 0 = none); one on vertices keeps its nodes.
//   An element in two conditions is refused (the array holds one), and so is an empty point set
//   (which the library's own writer refuses too). Family_t nodes of the base
//   (with their FamilyBC type) → CgnsExtras::families.
// - FlowSolution_t with GridLocation Vertex → point arrays (Float64 / Int32 / …; "fixed" marks
//   fixed nodes as in every format). Cell-centred solutions are skipped with a warning that
//   names them (getme recomputes its quality arrays; other cell data has no per-cell home for
//   the boundary elements).
//
// Every cg_* return code is checked; a failure is an InvalidArgument naming the base, zone,
// section, condition or field and carrying the library's own message (cg_get_error). A missing
// file is NotFound. Before the library sees a file, it must open with the HDF5 signature or a
// complete ADF header (the library's ADF core aborts the process on some others,
// cgns_library.cc), and every count is checked against what the file's size can hold before
// anything is allocated for it.
//
// The library is not thread-safe; calls are serialised (cgns_library.h).
absl::StatusOr<MeshDocument> ReadCgnsFile(const std::string& path);

// The same from bytes in memory: written to a temporary file first, since the CGNS library (and
// HDF5 below it) reads only from paths. Used where a file's bytes are already in memory: the
// content sniffer's path in ReadMeshDocument, the fuzzer, the remote path.
absl::StatusOr<MeshDocument> ParseCgns(absl::string_view bytes);

}  // namespace getme::formats
