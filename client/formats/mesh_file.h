#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "absl/status/status.h"
#include "absl/status/statusor.h"
#include "absl/strings/string_view.h"
#include "formats/mesh_document.h"

namespace getme::formats {

// A format as the command line names it, with the variant the name pins down, if any:
// "vtk", "vtu", "msh" (Gmsh; version: the input's, else 4.1), "msh2"/"msh22", "msh4"/"msh41",
// "mesh"/"medit", "su2", "cgns", "openfoam"/"foam", "exodus"/"exo". Case-insensitive.
// InvalidArgument listing the names otherwise.
struct FormatChoice {
  FileFormat format = FileFormat::kVtkLegacy;
  std::optional<GmshVersion> gmsh_version;
};
absl::StatusOr<FormatChoice> ParseFormatName(absl::string_view name);

// "VTK legacy", "VTK XML (.vtu)", "Gmsh MSH", "MEDIT", "SU2", "CGNS", "OpenFOAM polyMesh",
// "Exodus II".
const char* FormatDisplayName(FileFormat format);

// The format a path's extension names (.vtk .vtu .msh .mesh .su2 .cgns; .exo .e .ex2 .g for
// Exodus II), if any; a path whose
// last component is "polyMesh" names an OpenFOAM mesh.
std::optional<FileFormat> FormatFromExtension(absl::string_view path);

// The format a file's first bytes identify ("# vtk DataFile", "<?xml"/"<VTKFile",
// "$MeshFormat", "MeshVersionFormatted", "NDIME=" after any '%' comments, the HDF5 signature or
// ADF header of a CGNS file, the netCDF-3 signatures "CDF\x01"/"CDF\x02"/"CDF\x05" of an
// Exodus II file), if any. A netCDF-4 Exodus file is HDF5 and sniffed as CGNS: it needs its
// extension.
std::optional<FileFormat> SniffFormat(absl::string_view bytes);

// CGNS: through a temporary file, as the CGNS library reads paths only (cgns_reader.h), and
// Exodus II, as the Exodus library does (exodus_reader.h).
// OpenFOAM: InvalidArgument, a polyMesh is a directory of files (use ReadMeshDocument).
absl::StatusOr<MeshDocument> ParseMeshDocument(absl::string_view bytes, FileFormat format);

// Reads `path` as `format`, or as its extension says, or as its content says, in that order.
// Errors are prefixed with the path; a .meshb file and an unrecognised file are InvalidArgument
// naming the supported formats. A directory (or format kOpenFoam) is read as an OpenFOAM case or
// polyMesh directory (openfoam_reader.h).
absl::StatusOr<MeshDocument> ReadMeshDocument(const std::string& path,
                                              std::optional<FileFormat> format = std::nullopt);

// The bytes of `document` as `format` (OpenFOAM: InvalidArgument, a directory; use
// WriteMeshDocument).
absl::StatusOr<std::string> SerializeMeshDocument(const MeshDocument& document, FileFormat format,
                                                  const WriteOptions& options);

// Writes atomically. OpenFOAM: `path` is a case (path/constant/polyMesh) or a polyMesh
// directory (openfoam_writer.h). MEDIT: the cell-data arrays (e.g. the quality arrays), which a
// .mesh cannot hold, go to a .sol file beside it (OUT.mesh → OUT.sol).
absl::Status WriteMeshDocument(const std::string& path, const MeshDocument& document,
                               FileFormat format, const WriteOptions& options);

// The path of the MEDIT solution file that goes with `mesh_path`.
std::string MeditSolutionPath(const std::string& mesh_path);

// The write options for `document` in `format`: the input's own options when the format is the
// input's, the formats' defaults otherwise (ASCII stays ASCII, binary stays binary).
WriteOptions DefaultWriteOptions(const MeshDocument& document, FileFormat format);

// The cells (grid indices) of a named group: a Gmsh physical group by name, tag or "DIM:TAG";
// an SU2 marker by name; in any format, a number also matches the cell arrays "gmsh:physical",
// "medit:ref" and "su2:tag" (so a .msh converted to .vtu or .mesh still selects the same cells).
// NotFound naming what exists.
absl::StatusOr<std::vector<std::int64_t>> GroupCells(const MeshDocument& document,
                                                     absl::string_view group);

// Node flags (1 = fixed) for every point of the nodes of the given groups' cells and, if
// `surface_cells`, of every cell of dimension 0–2 (vertices, lines, triangles, quads: the
// boundaries and interfaces a mesher marked).
absl::StatusOr<std::vector<std::uint8_t>> SelectFixedNodes(const MeshDocument& document,
                                                           const std::vector<std::string>& groups,
                                                           bool surface_cells);

// A triangle or quad cell of a file with its surface group: the cell's value in the first of the
// cell arrays "gmsh:physical" (a Gmsh physical group; MSH files and what meshio writes from
// them), "medit:ref" (a MEDIT reference), "su2:tag" (an SU2 marker), "cgns:bc" (a CGNS boundary
// condition), "openfoam:patch", "exodus:sideset" that the file has. 0 is no group (an Exodus
// face in no side set, -1 in its array, too).
struct TaggedFace {
  std::array<std::int64_t, 4> nodes{-1, -1, -1, -1};
  int size = 0;
  std::int64_t tag = 0;
};

// The tagged triangles and quads of `document`, in cell order; none if it has no such array.
std::vector<TaggedFace> TaggedSurfaceFaces(const MeshDocument& document);

}  // namespace getme::formats
