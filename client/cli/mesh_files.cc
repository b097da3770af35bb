#include "cli/mesh_files.h"

#include <algorithm>

#include "absl/strings/str_cat.h"
#include "spdlog/spdlog.h"

namespace getme::cli {

absl::StatusOr<formats::MeshDocument> ReadInputMesh(const std::string& path,
                                                    const FileOptions& files) {
  return formats::ReadMeshDocument(path, files.input_format);
}

absl::StatusOr<OutputTarget> ResolveOutput(const formats::MeshDocument& input,
                                           const std::string& path, const FileOptions& files) {
  OutputTarget target;
  target.path = path;
  if (files.output_format.has_value()) {
    target.format = files.output_format->format;
  } else if (std::optional<formats::FileFormat> format = formats::FormatFromExtension(path)) {
    target.format = *format;
  } else {
    return absl::InvalidArgumentError(
        absl::StrCat("cannot tell the output format from '", path,
                     "': use the extension .vtk, .vtu, .msh or .mesh, or give --format"));
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
