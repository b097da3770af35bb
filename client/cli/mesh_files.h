#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "absl/status/status.h"
#include "absl/status/statusor.h"
#include "cli/cli_options.h"
#include "formats/mesh_file.h"
#include "getme_surface/boundary_surface.h"

namespace getme::cli {

// Where and how a command writes its output mesh.
struct OutputTarget {
  std::string path;
  formats::FileFormat format = formats::FileFormat::kVtkLegacy;
  formats::WriteOptions options;
};

// Reads IN as --input-format says, else by extension, else by content. Errors name the path.
absl::StatusOr<formats::MeshDocument> ReadInputMesh(const std::string& path,
                                                    const FileOptions& files);

// The output's format (--format, else OUT's extension) and write options (the input's where the
// format is the same, then --binary/--ascii/--compress). Resolved before any smoothing, so a
// bad output name fails at once. InvalidArgument naming the problem.
absl::StatusOr<OutputTarget> ResolveOutput(const formats::MeshDocument& input,
                                           const std::string& path, const FileOptions& files);

absl::Status WriteOutputMesh(const formats::MeshDocument& document, const OutputTarget& target);

// The nodes `--fix-physical` and `--fix-surfaces` hold (1 = fixed), or an empty vector when
// neither was given.
absl::StatusOr<std::vector<std::uint8_t>> FixedNodesFromOptions(
    const formats::MeshDocument& document, const SmoothCommandOptions& options);

// The surface groups of the file's tagged triangles and quads (formats::TaggedSurfaceFaces) for a
// sliding boundary: each distinct nonzero tag becomes a group 1, 2, … in ascending tag order, and
// tag 0 (Gmsh's and MEDIT's "none") is group 0, as is every boundary face without a cell.
std::vector<surface::GroupedFace> SurfaceGroupsOf(const formats::MeshDocument& document);

}  // namespace getme::cli
