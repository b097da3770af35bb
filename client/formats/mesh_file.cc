#include "formats/mesh_file.h"

#include <algorithm>
#include <array>
#include <filesystem>
#include <utility>

#include "absl/strings/ascii.h"
#include "absl/strings/match.h"
#include "absl/strings/numbers.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_join.h"
#include "absl/strings/strip.h"
#include "formats/cgns/cgns_groups.h"
#include "formats/cgns/cgns_reader.h"
#include "formats/cgns/cgns_writer.h"
#include "formats/exodus/exodus_groups.h"
#include "formats/exodus/exodus_reader.h"
#include "formats/exodus/exodus_writer.h"
#include "formats/file_io.h"
#include "formats/gmsh/gmsh_groups.h"
#include "formats/gmsh/gmsh_reader.h"
#include "formats/gmsh/gmsh_writer.h"
#include "formats/medit/medit_reader.h"
#include "formats/medit/medit_writer.h"
#include "formats/openfoam/openfoam_reader.h"
#include "formats/openfoam/openfoam_writer.h"
#include "formats/su2/su2_reader.h"
#include "formats/su2/su2_writer.h"
#include "formats/vtk_cell_type.h"
#include "formats/vtk_reader.h"
#include "formats/vtk_writer.h"
#include "formats/vtu/vtu_reader.h"
#include "formats/vtu/vtu_writer.h"

namespace getme::formats {
namespace {

constexpr char kSupportedFormats[] =
    "supported: .vtk (VTK legacy), .vtu (VTK XML), .msh (Gmsh 2.2 / 4.1), .mesh (MEDIT), .su2 "
    "(SU2), "
    ".cgns (CGNS), .exo/.e/.ex2/.g (Exodus II), an OpenFOAM case or polyMesh "
    "directory; --format / --input-format names: vtk, vtu, msh, "
    "msh2, msh4, mesh, su2, cgns, exodus, openfoam";

struct NamedFormat {
  const char* name;
  FormatChoice choice;
};

constexpr std::array<NamedFormat, 15> kFormatNames = {{
    {"vtk", {FileFormat::kVtkLegacy, std::nullopt}},
    {"vtu", {FileFormat::kVtkXml, std::nullopt}},
    {"msh", {FileFormat::kGmsh, std::nullopt}},
    {"msh2", {FileFormat::kGmsh, GmshVersion::k22}},
    {"msh22", {FileFormat::kGmsh, GmshVersion::k22}},
    {"msh4", {FileFormat::kGmsh, GmshVersion::k41}},
    {"msh41", {FileFormat::kGmsh, GmshVersion::k41}},
    {"mesh", {FileFormat::kMedit, std::nullopt}},
    {"medit", {FileFormat::kMedit, std::nullopt}},
    {"openfoam", {FileFormat::kOpenFoam, std::nullopt}},
    {"foam", {FileFormat::kOpenFoam, std::nullopt}},
    {"cgns", {FileFormat::kCgns, std::nullopt}},
    {"su2", {FileFormat::kSu2, std::nullopt}},
    {"exodus", {FileFormat::kExodus, std::nullopt}},
    {"exo", {FileFormat::kExodus, std::nullopt}},
}};

std::string Lowercase(absl::string_view text) { return absl::AsciiStrToLower(text); }

absl::string_view Extension(absl::string_view path) {
  const std::size_t slash = path.find_last_of('/');
  const absl::string_view name = slash == absl::string_view::npos ? path : path.substr(slash + 1);
  const std::size_t dot = name.find_last_of('.');
  if (dot == absl::string_view::npos || dot == 0) return {};
  return name.substr(dot + 1);
}

// A number for a group ("5") or nothing.
std::optional<std::int64_t> GroupNumber(absl::string_view group) {
  std::int64_t number = 0;
  if (!absl::SimpleAtoi(group, &number)) return std::nullopt;
  return number;
}

// Cells whose integer cell array `name` equals `value`.
std::vector<std::int64_t> CellsWithTag(const UnstructuredGrid& grid, absl::string_view name,
                                       std::int64_t value) {
  std::vector<std::int64_t> cells;
  const DataArray* tags = FindArray(grid.cell_data, name);
  if (tags == nullptr || tags->components != 1 || tags->tuple_count() != grid.cells.size()) {
    return cells;
  }
  for (std::int64_t cell = 0; cell < tags->tuple_count(); ++cell) {
    if (tags->AsDouble(cell) == static_cast<double>(value)) cells.push_back(cell);
  }
  return cells;
}

// The cell arrays that carry a file's surface groups, in the order a file's own array is looked
// for: Gmsh physical groups, MEDIT refs, SU2 markers, CGNS boundary conditions, OpenFOAM patches,
// Exodus side sets. A grid converted from one format to another keeps its array, so the same
// numbers select the same cells everywhere. client/python/getme/_wire.py (SURFACE_TAG_ARRAYS)
// lists the same names for the Python client's sliding boundary.
constexpr std::array<const char*, 6> kGroupTagArrays = {
    "gmsh:physical", "medit:ref", "su2:tag", "cgns:bc", "openfoam:patch", "exodus:sideset"};

}  // namespace

absl::StatusOr<FormatChoice> ParseFormatName(absl::string_view name) {
  const std::string lower = Lowercase(name);
  for (const NamedFormat& entry : kFormatNames) {
    if (lower == entry.name) return entry.choice;
  }
  if (lower == "meshb") {
    return absl::InvalidArgumentError(
        "format 'meshb' (binary MEDIT) is not supported: it needs libMeshb, which Debian does not "
        "package; use 'mesh'");
  }
  return absl::InvalidArgumentError(
      absl::StrCat("unknown format '", name, "'; ", kSupportedFormats));
}

const char* FormatDisplayName(FileFormat format) {
  switch (format) {
    case FileFormat::kVtkLegacy:
      return "VTK legacy";
    case FileFormat::kVtkXml:
      return "VTK XML";
    case FileFormat::kGmsh:
      return "Gmsh MSH";
    case FileFormat::kOpenFoam:
      return "OpenFOAM polyMesh";
    case FileFormat::kCgns:
      return "CGNS";
    case FileFormat::kSu2:
      return "SU2";
    case FileFormat::kExodus:
      return "Exodus II";
    case FileFormat::kMedit:
      break;
  }
  return "MEDIT";
}

std::optional<FileFormat> FormatFromExtension(absl::string_view path) {
  const std::string extension = Lowercase(Extension(path));
  if (extension == "vtk") return FileFormat::kVtkLegacy;
  if (extension == "vtu") return FileFormat::kVtkXml;
  if (extension == "msh") return FileFormat::kGmsh;
  if (extension == "mesh") return FileFormat::kMedit;
  if (extension == "cgns") return FileFormat::kCgns;
  if (extension == "su2") return FileFormat::kSu2;
  // Exodus II: .exo and .e (Sierra, MOOSE, meshio), .ex2 (meshio), .g (Cubit's "genesis" meshes).
  if (extension == "exo" || extension == "e" || extension == "ex2" || extension == "g") {
    return FileFormat::kExodus;
  }
  // An OpenFOAM mesh is a directory, named by its last component (openfoam_writer.h).
  const absl::string_view directory = absl::StripSuffix(path, "/");
  if (directory == "polyMesh" || absl::EndsWith(directory, "/polyMesh")) {
    return FileFormat::kOpenFoam;
  }
  return std::nullopt;
}

std::optional<FileFormat> SniffFormat(absl::string_view bytes) {
  // CGNS files are HDF5 (its 8-byte signature, HDF5 File Format Specification §II.A) or ADF
  // (whose header names itself after a 4-byte tag). The other HDF5-based files read here
  // (netCDF-4 Exodus) are recognised by their extension only, so an HDF5 file without one is
  // taken for CGNS and the CGNS library says if it is not one.
  if (absl::StartsWith(bytes, absl::string_view("\x89HDF\r\n\x1a\n", 8)) ||
      (bytes.size() >= 24 && bytes.substr(4, 20) == "ADF Database Version")) {
    return FileFormat::kCgns;
  }
  // Exodus II files written by the Exodus library are netCDF-3: classic "CDF\x01", 64-bit offset
  // "CDF\x02" or 64-bit data "CDF\x05" (netCDF File Format Specification, "magic"). netCDF-4
  // Exodus files (meshio's) are HDF5 and only recognised by their extension, so the HDF5
  // signature stays with CGNS above. No other format read here is netCDF.
  if (bytes.size() >= 4 && absl::StartsWith(bytes, "CDF") &&
      (bytes[3] == '\x01' || bytes[3] == '\x02' || bytes[3] == '\x05')) {
    return FileFormat::kExodus;
  }
  absl::string_view head = absl::StripLeadingAsciiWhitespace(bytes.substr(0, 256));
  if (absl::StartsWith(head, "# vtk DataFile")) return FileFormat::kVtkLegacy;
  if (absl::StartsWith(head, "<?xml") || absl::StartsWith(head, "<VTKFile")) {
    return FileFormat::kVtkXml;
  }
  if (absl::StartsWith(head, "$MeshFormat")) return FileFormat::kGmsh;
  // SU2 files may open with '%' comment lines, then the dimension (or, multi-zone, the zones).
  absl::string_view su2 = head;
  while (absl::StartsWith(su2, "%")) {
    const std::size_t end = su2.find('\n');
    if (end == absl::string_view::npos) return std::nullopt;
    su2 = absl::StripLeadingAsciiWhitespace(su2.substr(end + 1));
  }
  for (const absl::string_view keyword : {"NDIME", "NZONE"}) {
    if (absl::StartsWith(su2, keyword) &&
        absl::StartsWith(absl::StripLeadingAsciiWhitespace(su2.substr(keyword.size())), "=")) {
      return FileFormat::kSu2;
    }
  }
  // MEDIT files may open with comment lines.
  while (absl::StartsWith(head, "#")) {
    const std::size_t end = head.find('\n');
    if (end == absl::string_view::npos) return std::nullopt;
    head = absl::StripLeadingAsciiWhitespace(head.substr(end + 1));
  }
  if (absl::StartsWithIgnoreCase(head, "MeshVersionFormatted")) return FileFormat::kMedit;
  return std::nullopt;
}

absl::StatusOr<MeshDocument> ParseMeshDocument(absl::string_view bytes, FileFormat format) {
  switch (format) {
    case FileFormat::kVtkLegacy: {
      absl::StatusOr<UnstructuredGrid> file = ParseVtk(bytes);
      if (!file.ok()) return file.status();
      MeshDocument document;
      document.format = FileFormat::kVtkLegacy;
      document.as_read.encoding = file->encoding;
      document.grid = *std::move(file);
      return document;
    }
    case FileFormat::kVtkXml:
      return ParseVtu(bytes);
    case FileFormat::kGmsh:
      return ParseGmsh(bytes);
    case FileFormat::kCgns:
      return ParseCgns(bytes);
    case FileFormat::kSu2:
      return ParseSu2(bytes);
    case FileFormat::kExodus:
      return ParseExodus(bytes);
    case FileFormat::kOpenFoam:
      return absl::InvalidArgumentError(
          "an OpenFOAM polyMesh is a directory of files, not one file: read it with "
          "ReadMeshDocument (a case or polyMesh directory)");
    case FileFormat::kMedit:
      break;
  }
  return ParseMedit(bytes);
}

absl::StatusOr<MeshDocument> ReadMeshDocument(const std::string& path,
                                              std::optional<FileFormat> format) {
  if (!format.has_value() && Lowercase(Extension(path)) == "meshb") {
    return absl::InvalidArgumentError(absl::StrCat(
        path,
        ": binary MEDIT (.meshb) is not supported: it needs libMeshb, which Debian does not "
        "package; convert it to .mesh"));
  }
  // An OpenFOAM polyMesh is a directory of files (openfoam_reader.h); any directory is read as one.
  if (format == FileFormat::kOpenFoam ||
      (!format.has_value() && (FormatFromExtension(path) == FileFormat::kOpenFoam ||
                               std::filesystem::is_directory(path)))) {
    return ReadOpenFoam(path);
  }
  // The CGNS library reads the file by its path (cgns_reader.h); its bytes are read into memory
  // only when the content must tell the format.
  const std::optional<FileFormat> named = format.has_value() ? format : FormatFromExtension(path);
  if (named.has_value() && *named == FileFormat::kCgns) {
    absl::StatusOr<MeshDocument> document = ReadCgnsFile(path);
    if (!document.ok() && document.status().code() != absl::StatusCode::kNotFound) {
      return absl::Status(document.status().code(),
                          absl::StrCat(path, ": ", document.status().message()));
    }
    return document;
  }
  // So does the Exodus library (exodus_reader.h).
  if ((format.has_value() ? format : FormatFromExtension(path)) == FileFormat::kExodus) {
    absl::StatusOr<MeshDocument> document = ReadExodus(path);
    if (!document.ok() && document.status().code() != absl::StatusCode::kNotFound) {
      return absl::Status(document.status().code(),
                          absl::StrCat(path, ": ", document.status().message()));
    }
    return document;
  }
  absl::StatusOr<std::string> bytes = ReadFileBytes(path);
  if (!bytes.ok()) return bytes.status();
  if (!format.has_value()) format = FormatFromExtension(path);
  if (!format.has_value()) format = SniffFormat(*bytes);
  if (!format.has_value()) {
    return absl::InvalidArgumentError(absl::StrCat(
        path, ": cannot tell the format from the extension or the content; ", kSupportedFormats));
  }
  absl::StatusOr<MeshDocument> document = ParseMeshDocument(*bytes, *format);
  if (!document.ok()) {
    return absl::Status(document.status().code(),
                        absl::StrCat(path, ": ", document.status().message()));
  }
  return document;
}

absl::StatusOr<std::string> SerializeMeshDocument(const MeshDocument& document, FileFormat format,
                                                  const WriteOptions& options) {
  switch (format) {
    case FileFormat::kVtkLegacy:
      return SerializeVtk(document.grid, options.encoding, options.threads);
    case FileFormat::kVtkXml:
      return SerializeVtu(document, options);
    case FileFormat::kGmsh:
      return SerializeGmsh(document, options);
    case FileFormat::kCgns:
      return SerializeCgns(document);
    case FileFormat::kSu2:
      return SerializeSu2(document, options);
    case FileFormat::kExodus:
      return SerializeExodus(document, options);
    case FileFormat::kOpenFoam:
      return absl::InvalidArgumentError(
          "an OpenFOAM polyMesh is a directory of files, not one file: write it with "
          "WriteMeshDocument");
    case FileFormat::kMedit:
      break;
  }
  return SerializeMedit(document, options);
}

std::string MeditSolutionPath(const std::string& mesh_path) {
  const absl::string_view extension = Extension(mesh_path);
  if (extension.empty()) return absl::StrCat(mesh_path, ".sol");
  return absl::StrCat(mesh_path.substr(0, mesh_path.size() - extension.size()), "sol");
}

absl::Status WriteMeshDocument(const std::string& path, const MeshDocument& document,
                               FileFormat format, const WriteOptions& options) {
  WarnExodusNodeSetsNotWritten(document, format);
  const auto with_path = [&](const absl::Status& status) {
    return absl::Status(status.code(),
                        absl::StrCat("cannot write '", path, "': ", status.message()));
  };
  if (format == FileFormat::kOpenFoam) {
    absl::Status status = WriteOpenFoam(path, document, options);
    return status.ok() ? status : with_path(status);
  }
  // The CGNS library writes to a path itself (and atomically, cgns_writer.h).
  if (format == FileFormat::kCgns) {
    absl::Status status = WriteCgnsFile(path, document);
    return status.ok() ? status : with_path(status);
  }
  absl::StatusOr<std::string> bytes = SerializeMeshDocument(document, format, options);
  if (!bytes.ok()) return with_path(bytes.status());
  if (format == FileFormat::kMedit) {
    absl::StatusOr<std::string> solution = SerializeMeditSolution(document);
    if (!solution.ok()) return with_path(solution.status());
    if (!solution->empty()) {
      if (absl::Status status = WriteFileAtomically(MeditSolutionPath(path), *solution);
          !status.ok()) {
        return status;
      }
    }
  }
  return WriteFileAtomically(path, *bytes);
}

WriteOptions DefaultWriteOptions(const MeshDocument& document, FileFormat format) {
  if (format == document.format) return document.as_read;
  WriteOptions options;
  options.encoding = document.as_read.encoding;
  if (format == FileFormat::kMedit || format == FileFormat::kSu2)
    options.encoding = Encoding::kAscii;
  return options;
}

absl::StatusOr<std::vector<std::int64_t>> GroupCells(const MeshDocument& document,
                                                     absl::string_view group) {
  if (document.format == FileFormat::kGmsh && document.gmsh.has_value()) {
    return GmshGroupCells(document, group);
  }
  if (document.cgns.has_value()) return CgnsGroupCells(document, group);
  const std::optional<std::int64_t> number = GroupNumber(group);
  if (document.su2.has_value()) {
    std::vector<std::string> names;
    for (const Su2Marker& marker : document.su2->markers) {
      if (marker.name == group) return CellsWithTag(document.grid, "su2:tag", marker.tag);
      names.push_back(absl::StrCat("'", marker.name, "'"));
    }
    if (!number.has_value()) {
      return absl::NotFoundError(
          absl::StrCat("no SU2 marker '", group, "'; the file's markers: ",
                       names.empty() ? std::string("none") : absl::StrJoin(names, ", ")));
    }
  }
  // OpenFOAM patches by name; a number is the patch's 1-based position (the cell array
  // "openfoam:patch").
  if (document.openfoam.has_value()) {
    std::vector<std::string> names;
    for (std::size_t patch = 0; patch < document.openfoam->patches.size(); ++patch) {
      const std::string& name = document.openfoam->patches[patch].name;
      if (name == group) {
        return CellsWithTag(document.grid, "openfoam:patch", static_cast<std::int64_t>(patch) + 1);
      }
      names.push_back(absl::StrCat("'", name, "'"));
    }
    if (!number.has_value()) {
      return absl::NotFoundError(
          absl::StrCat("no OpenFOAM patch '", group, "'; the mesh's patches: ",
                       names.empty() ? std::string("none") : absl::StrJoin(names, ", ")));
    }
  }
  std::vector<std::string> available;
  for (const char* name : kGroupTagArrays) {
    if (FindArray(document.grid.cell_data, name) != nullptr) available.push_back(name);
  }
  if (number.has_value()) {
    for (const std::string& name : available) {
      std::vector<std::int64_t> cells = CellsWithTag(document.grid, name, *number);
      if (!cells.empty()) return cells;
    }
  }
  if (available.empty()) {
    return absl::NotFoundError(absl::StrCat("no group '", group, "': this ",
                                            FormatDisplayName(document.format),
                                            " file has no groups (Gmsh physical groups, SU2 "
                                            "markers, CGNS boundary conditions, OpenFOAM "
                                            "patches, Exodus sets, or the cell arrays ",
                                            absl::StrJoin(kGroupTagArrays, " / "), ")"));
  }
  return absl::NotFoundError(absl::StrCat("no group '", group, "': no cell has ",
                                          absl::StrJoin(available, " or "), " = ", group,
                                          number.has_value() ? "" : " (give the group's number)"));
}

std::vector<TaggedFace> TaggedSurfaceFaces(const MeshDocument& document) {
  const UnstructuredGrid& grid = document.grid;
  std::vector<TaggedFace> faces;
  for (const char* name : kGroupTagArrays) {
    const DataArray* tags = FindArray(grid.cell_data, name);
    if (tags == nullptr || tags->components != 1 || tags->tuple_count() != grid.cells.size()) {
      continue;
    }
    for (std::int64_t cell = 0; cell < grid.cells.size(); ++cell) {
      const int type = grid.cells.types[cell];
      if (type != kVtkTriangle && type != kVtkQuad) continue;
      TaggedFace face;
      face.size = type == kVtkTriangle ? 3 : 4;
      if (grid.cells.node_count(cell) != face.size) continue;
      std::copy_n(grid.cells.nodes(cell), face.size, face.nodes.begin());
      face.tag = static_cast<std::int64_t>(tags->AsDouble(cell));
      // The Exodus reader marks a face of no side set -1 (exodus_reader.h); here, as in every
      // other format, "no group" is 0, which local and remote runs both leave ungrouped.
      if (absl::string_view(name) == "exodus:sideset" && face.tag < 0) face.tag = 0;
      faces.push_back(face);
    }
    break;
  }
  return faces;
}

absl::StatusOr<std::vector<std::uint8_t>> SelectFixedNodes(const MeshDocument& document,
                                                           const std::vector<std::string>& groups,
                                                           bool surface_cells) {
  const GridCells& cells = document.grid.cells;
  std::vector<std::uint8_t> fixed(static_cast<std::size_t>(document.grid.point_count()), 0);
  const auto fix_cell = [&](std::int64_t cell) {
    const std::int64_t* nodes = cells.nodes(cell);
    for (std::int64_t k = 0; k < cells.node_count(cell); ++k) {
      if (nodes[k] >= 0 && nodes[k] < static_cast<std::int64_t>(fixed.size())) fixed[nodes[k]] = 1;
    }
  };
  for (const std::string& group : groups) {
    // A CGNS boundary condition may list vertices rather than elements.
    if (document.cgns.has_value()) {
      absl::StatusOr<std::vector<std::int64_t>> nodes = CgnsGroupNodes(document, group);
      if (!nodes.ok()) return nodes.status();
      for (const std::int64_t node : *nodes) {
        if (node >= 0 && node < static_cast<std::int64_t>(fixed.size())) fixed[node] = 1;
      }
      continue;
    }
    // An Exodus node set has no cells: the group is a node set, side set or block.
    if (document.exodus.has_value()) {
      absl::StatusOr<std::vector<std::int64_t>> nodes = ExodusGroupNodes(document, group);
      if (!nodes.ok()) return nodes.status();
      for (const std::int64_t node : *nodes) {
        if (node >= 0 && node < static_cast<std::int64_t>(fixed.size())) fixed[node] = 1;
      }
      continue;
    }
    absl::StatusOr<std::vector<std::int64_t>> selected = GroupCells(document, group);
    if (!selected.ok()) return selected.status();
    for (const std::int64_t cell : *selected) fix_cell(cell);
  }
  if (surface_cells) {
    for (std::int64_t cell = 0; cell < cells.size(); ++cell) {
      const std::optional<VtkCellTypeInfo> info = CellTypeInfo(cells.types[cell]);
      if (info.has_value() && info->role == VtkCellRole::kPassthrough) fix_cell(cell);
    }
  }
  return fixed;
}

}  // namespace getme::formats
