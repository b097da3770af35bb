#include "formats/mesh_file.h"

#include <algorithm>
#include <array>
#include <utility>

#include "absl/strings/ascii.h"
#include "absl/strings/match.h"
#include "absl/strings/numbers.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_join.h"
#include "absl/strings/strip.h"
#include "formats/file_io.h"
#include "formats/gmsh/gmsh_groups.h"
#include "formats/gmsh/gmsh_reader.h"
#include "formats/gmsh/gmsh_writer.h"
#include "formats/medit/medit_reader.h"
#include "formats/medit/medit_writer.h"
#include "formats/vtk_cell_type.h"
#include "formats/vtk_reader.h"
#include "formats/vtk_writer.h"
#include "formats/vtu/vtu_reader.h"
#include "formats/vtu/vtu_writer.h"

namespace getme::formats {
namespace {

constexpr char kSupportedFormats[] =
    "supported: .vtk (VTK legacy), .vtu (VTK XML), .msh (Gmsh 2.2 / 4.1), .mesh (MEDIT); "
    "--format / --input-format names: vtk, vtu, msh, msh2, msh4, mesh";

struct NamedFormat {
  const char* name;
  FormatChoice choice;
};

constexpr std::array<NamedFormat, 9> kFormatNames = {{
    {"vtk", {FileFormat::kVtkLegacy, std::nullopt}},
    {"vtu", {FileFormat::kVtkXml, std::nullopt}},
    {"msh", {FileFormat::kGmsh, std::nullopt}},
    {"msh2", {FileFormat::kGmsh, GmshVersion::k22}},
    {"msh22", {FileFormat::kGmsh, GmshVersion::k22}},
    {"msh4", {FileFormat::kGmsh, GmshVersion::k41}},
    {"msh41", {FileFormat::kGmsh, GmshVersion::k41}},
    {"mesh", {FileFormat::kMedit, std::nullopt}},
    {"medit", {FileFormat::kMedit, std::nullopt}},
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
  return std::nullopt;
}

std::optional<FileFormat> SniffFormat(absl::string_view bytes) {
  absl::string_view head = absl::StripLeadingAsciiWhitespace(bytes.substr(0, 256));
  if (absl::StartsWith(head, "# vtk DataFile")) return FileFormat::kVtkLegacy;
  if (absl::StartsWith(head, "<?xml") || absl::StartsWith(head, "<VTKFile")) {
    return FileFormat::kVtkXml;
  }
  if (absl::StartsWith(head, "$MeshFormat")) return FileFormat::kGmsh;
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
      return SerializeVtk(document.grid, options.encoding);
    case FileFormat::kVtkXml:
      return SerializeVtu(document, options);
    case FileFormat::kGmsh:
      return SerializeGmsh(document, options);
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
  const auto with_path = [&](const absl::Status& status) {
    return absl::Status(status.code(),
                        absl::StrCat("cannot write '", path, "': ", status.message()));
  };
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
  if (format == FileFormat::kMedit) options.encoding = Encoding::kAscii;
  return options;
}

absl::StatusOr<std::vector<std::int64_t>> GroupCells(const MeshDocument& document,
                                                     absl::string_view group) {
  if (document.format == FileFormat::kGmsh && document.gmsh.has_value()) {
    return GmshGroupCells(document, group);
  }
  const std::optional<std::int64_t> number = GroupNumber(group);
  std::vector<std::string> available;
  for (const char* name : {"gmsh:physical", "medit:ref"}) {
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
                                            " file has no groups (Gmsh physical groups, or the "
                                            "cell arrays gmsh:physical / medit:ref)"));
  }
  return absl::NotFoundError(absl::StrCat("no group '", group, "': no cell has ",
                                          absl::StrJoin(available, " or "), " = ", group,
                                          number.has_value() ? "" : " (give the group's number)"));
}

std::vector<TaggedFace> TaggedSurfaceFaces(const MeshDocument& document) {
  const UnstructuredGrid& grid = document.grid;
  std::vector<TaggedFace> faces;
  for (const char* name : {"gmsh:physical", "medit:ref"}) {
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
