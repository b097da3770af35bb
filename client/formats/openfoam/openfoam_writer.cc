#include "formats/openfoam/openfoam_writer.h"

#include <charconv>
#include <cstring>
#include <filesystem>
#include <optional>
#include <system_error>

#include "absl/strings/match.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/strip.h"
#include "formats/file_io.h"
#include "formats/openfoam/foam_file.h"
#include "formats/openfoam/polymesh_builder.h"

namespace getme::formats {
namespace {

// The point list in the layout OpenFOAM writes (Field<vector>::writeEntry): the size, then
// "(" and either one "(x y z)" line per point or the raw values, then ")".
std::string PointList(const DataArray& points, const OpenFoamExtras& extras) {
  const std::int64_t count = points.tuple_count();
  std::string out = absl::StrCat(count, "\n(");
  if (extras.points_binary) {
    const std::size_t first = out.size();
    out.resize(first + static_cast<std::size_t>(3 * count) * extras.scalar_bytes);
    char* data = out.data() + first;
    for (std::int64_t i = 0; i < 3 * count; ++i) {
      const double value = points.AsDouble(i);
      if (extras.scalar_bytes == 8) {
        std::memcpy(data, &value, 8);
      } else {
        const float narrow = static_cast<float>(value);
        std::memcpy(data, &narrow, 4);
      }
      data += extras.scalar_bytes;
    }
    out += ')';
    return out;
  }
  out += '\n';
  out.reserve(out.size() + static_cast<std::size_t>(count) * 64);
  char buffer[32];
  for (std::int64_t i = 0; i < count; ++i) {
    out += '(';
    for (int k = 0; k < 3; ++k) {
      // Shortest round-trip form: what is read back is bit-identical.
      const std::to_chars_result result =
          std::to_chars(buffer, buffer + sizeof(buffer), points.AsDouble(3 * i + k));
      out.append(buffer, result.ptr);
      out += k < 2 ? ' ' : ')';
    }
    out += '\n';
  }
  out += ')';
  return out;
}

absl::string_view BaseName(absl::string_view name) { return absl::StripSuffix(name, ".gz"); }

}  // namespace

absl::StatusOr<std::vector<PolyMeshFile>> SerializeOpenFoam(const MeshDocument& document,
                                                            const WriteOptions& options) {
  // A mesh from another format gets its faces, owners and patches built from its cells.
  std::optional<OpenFoamExtras> built;
  if (!document.openfoam.has_value()) {
    absl::StatusOr<OpenFoamExtras> polymesh = BuildPolyMesh(document, options.encoding);
    if (!polymesh.ok()) return polymesh.status();
    built = *std::move(polymesh);
  }
  const OpenFoamExtras& extras = built.has_value() ? *built : *document.openfoam;
  const DataArray& points = document.grid.points;
  if (points.components != 3 || points.tuple_count() != extras.point_count) {
    return absl::InvalidArgumentError(
        absl::StrCat("the grid has ", points.tuple_count(), " points (", points.components,
                     " components), but the polyMesh it was read from has ", extras.point_count));
  }
  const Encoding points_encoding = extras.points_binary ? Encoding::kBinary : Encoding::kAscii;
  if (options.encoding != points_encoding) {
    return absl::InvalidArgumentError(
        absl::StrCat("an OpenFOAM polyMesh is written back in the encoding it was read in (",
                     extras.points_binary ? "binary" : "ascii",
                     "): only its points change, and its other files are copied as they are"));
  }
  std::string text =
      absl::StrCat(extras.points_before, PointList(points, extras), extras.points_after);
  if (extras.points_gzipped) {
    absl::StatusOr<std::string> compressed = Gzip(text);
    if (!compressed.ok()) return compressed.status();
    text = *std::move(compressed);
  }
  std::vector<PolyMeshFile> files;
  files.push_back({extras.points_name, std::move(text)});
  files.insert(files.end(), extras.files.begin(), extras.files.end());
  return files;
}

std::string PolyMeshDirectoryFor(const std::string& path) {
  namespace fs = std::filesystem;
  fs::path directory(path);
  if (!directory.has_filename()) directory = directory.parent_path();  // "out/" → "out"
  if (directory.filename() == "polyMesh") return directory.string();
  return (directory / "constant" / "polyMesh").string();
}

absl::Status WriteOpenFoam(const std::string& path, const MeshDocument& document,
                           const WriteOptions& options) {
  namespace fs = std::filesystem;
  absl::StatusOr<std::vector<PolyMeshFile>> files = SerializeOpenFoam(document, options);
  if (!files.ok()) return files.status();
  const fs::path directory = PolyMeshDirectoryFor(path);
  std::error_code error;
  fs::create_directories(directory, error);
  if (error) {
    return absl::PermissionDeniedError(
        absl::StrCat("cannot create ", directory.string(), ": ", error.message()));
  }
  for (const PolyMeshFile& file : *files) {
    const std::string base(BaseName(file.name));
    const std::string other = file.name == base ? absl::StrCat(base, ".gz") : base;
    if (fs::exists(directory / other, error)) {
      return absl::InvalidArgumentError(
          absl::StrCat((directory / other).string(), " exists, and ", file.name,
                       " is to be written beside it: OpenFOAM would read either; remove it first"));
    }
  }
  for (const PolyMeshFile& file : *files) {
    if (absl::Status status = WriteFileAtomically((directory / file.name).string(), file.bytes);
        !status.ok()) {
      return status;
    }
  }
  return absl::OkStatus();
}

}  // namespace getme::formats
