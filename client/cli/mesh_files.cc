#include "cli/mesh_files.h"

#include <algorithm>
#include <filesystem>

#include "absl/strings/str_cat.h"
#include "spdlog/spdlog.h"

namespace getme::cli {

absl::StatusOr<formats::MeshDocument> ReadInputMesh(const std::string& path,
                                                    const FileOptions& files) {
  absl::StatusOr<formats::MeshDocument> document =
      formats::ReadMeshDocument(path, files.input_format);
  if (document.ok() && document->su2.has_value() && !document->su2->mirrored_cells.empty()) {
    spdlog::info(
        "{}: {} mirrored elements renumbered (every corner Jacobian negative in VTK's convention); "
        "SU2 output writes them back in the file's order",
        path, document->su2->mirrored_cells.size());
  }
  return document;
}

absl::StatusOr<OutputTarget> ResolveOutput(const formats::MeshDocument& input,
                                           const std::string& path, const FileOptions& files) {
  OutputTarget target;
  target.path = path;
  if (files.output_format.has_value()) {
    target.format = files.output_format->format;
  } else if (std::optional<formats::FileFormat> format = formats::FormatFromExtension(path)) {
    target.format = *format;
  } else if (std::filesystem::is_directory(path) ||
             input.format == formats::FileFormat::kOpenFoam) {
    // An existing directory can only take an OpenFOAM case (OUT/constant/polyMesh); an OpenFOAM
    // input written to a path without extension stays an OpenFOAM case.
    target.format = formats::FileFormat::kOpenFoam;
  } else {
    return absl::InvalidArgumentError(absl::StrCat(
        "cannot tell the output format from '", path,
        "': use the extension .vtk, .vtu, .msh, .mesh, .su2, .cgns or .exo, a directory named "
        "polyMesh or an existing directory (OpenFOAM), or give --format"));
  }
  target.options = formats::DefaultWriteOptions(input, target.format);
  if (files.output_format.has_value() && files.output_format->gmsh_version.has_value()) {
    target.options.gmsh_version = *files.output_format->gmsh_version;
  }
  if (files.encoding.has_value()) target.options.encoding = *files.encoding;
  if (files.compress) {
    if (target.format != formats::FileFormat::kVtkXml) {
      return absl::InvalidArgumentError(absl::StrCat("--compress applies to .vtu output only; '",
                                                     path, "' is written as ",
                                                     formats::FormatDisplayName(target.format)));
    }
    target.options.vtu_compress = true;
  }
  if (target.format == formats::FileFormat::kSu2 &&
      target.options.encoding == formats::Encoding::kBinary) {
    if (files.encoding.has_value()) {
      return absl::InvalidArgumentError(
          "SU2 output is ASCII only: SU2 has no binary native mesh (it reads binary meshes as "
          "CGNS)");
    }
    target.options.encoding = formats::Encoding::kAscii;
  }
  if (target.format == formats::FileFormat::kCgns) {
    if (files.encoding == formats::Encoding::kAscii) {
      return absl::InvalidArgumentError(
          "CGNS output is binary only (HDF5, written by the CGNS library)");
    }
    target.options.encoding = formats::Encoding::kBinary;
  }
  if (target.format == formats::FileFormat::kExodus) {
    if (files.encoding == formats::Encoding::kAscii) {
      return absl::InvalidArgumentError(
          "Exodus II output is binary only (netCDF, written by the Exodus library)");
    }
    target.options.encoding = formats::Encoding::kBinary;
  }
  if (target.format == formats::FileFormat::kMedit &&
      target.options.encoding == formats::Encoding::kBinary) {
    if (files.encoding.has_value()) {
      return absl::InvalidArgumentError(
          "MEDIT output is ASCII only: the binary .meshb needs libMeshb, which Debian does not "
          "package");
    }
    target.options.encoding = formats::Encoding::kAscii;
  }
  return target;
}

absl::Status WriteOutputMesh(const formats::MeshDocument& document, const OutputTarget& target) {
  // The polyhedra of an OpenFOAM mesh are not in the grid (openfoam_reader.h): only the
  // polyMesh written back keeps them.
  if (document.openfoam.has_value() && document.openfoam->polyhedron_count > 0 &&
      target.format != formats::FileFormat::kOpenFoam) {
    spdlog::warn(
        "{} polyhedral cells of the OpenFOAM mesh are not written to {}: only the tetrahedra, "
        "pyramids, prisms, hexahedra and boundary faces are (an OpenFOAM output keeps them)",
        document.openfoam->polyhedron_count, formats::FormatDisplayName(target.format));
  }
  if (absl::Status status =
          formats::WriteMeshDocument(target.path, document, target.format, target.options);
      !status.ok()) {
    return status;
  }
  const bool binary = target.options.encoding == formats::Encoding::kBinary;
  std::string variant = binary ? "binary" : "ascii";
  if (target.format == formats::FileFormat::kGmsh) {
    variant = absl::StrCat(
        target.options.gmsh_version == formats::GmshVersion::k22 ? "2.2 " : "4.1 ", variant);
  } else if (target.format == formats::FileFormat::kCgns) {
    variant = "HDF5";
  } else if (target.format == formats::FileFormat::kVtkXml && binary) {
    variant = absl::StrCat(
        target.options.vtu_layout == formats::VtuLayout::kAppended ? "appended" : "inline",
        target.options.vtu_compress ? ", zlib" : "");
  }
  spdlog::info("wrote {} ({} {})", target.path, formats::FormatDisplayName(target.format), variant);
  return absl::OkStatus();
}

absl::StatusOr<std::vector<std::uint8_t>> FixedNodesFromOptions(
    const formats::MeshDocument& document, const SmoothCommandOptions& options) {
  if (options.fix_groups.empty() && !options.fix_surfaces) return std::vector<std::uint8_t>{};
  return formats::SelectFixedNodes(document, options.fix_groups, options.fix_surfaces);
}

std::vector<surface::GroupedFace> SurfaceGroupsOf(const formats::MeshDocument& document) {
  const std::vector<formats::TaggedFace> tagged = formats::TaggedSurfaceFaces(document);
  std::vector<std::int64_t> tags;
  for (const formats::TaggedFace& face : tagged) {
    if (face.tag != 0) tags.push_back(face.tag);
  }
  std::sort(tags.begin(), tags.end());
  tags.erase(std::unique(tags.begin(), tags.end()), tags.end());
  std::vector<surface::GroupedFace> groups;
  groups.reserve(tagged.size());
  for (const formats::TaggedFace& face : tagged) {
    surface::GroupedFace grouped{{-1, -1, -1, -1}, face.size, 0};
    for (int k = 0; k < face.size; ++k) grouped.nodes[k] = static_cast<NodeId>(face.nodes[k]);
    if (face.tag != 0) {
      grouped.group =
          static_cast<int>(std::lower_bound(tags.begin(), tags.end(), face.tag) - tags.begin()) + 1;
    }
    groups.push_back(grouped);
  }
  return groups;
}

}  // namespace getme::cli
