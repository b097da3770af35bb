#include "benchmark_mesh.h"

#include <malloc.h>

#include <algorithm>
#include <chrono>
#include <span>
#include <string>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_split.h"
#include "formats/grid_mesh.h"
#include "formats/mesh_file.h"
#include "getme/meshgen/meshgen_command.h"
#include "peak_memory.h"

namespace getme::bench {
namespace {

absl::StatusOr<Mesh> ReadMesh(const std::string& path) {
  absl::StatusOr<formats::MeshDocument> document = formats::ReadMeshDocument(path);
  if (!document.ok()) return document.status();
  absl::StatusOr<formats::GridMesh> converted = formats::GridToMesh(document->grid);
  if (!converted.ok()) {
    return absl::Status(converted.status().code(),
                        absl::StrCat(path, ": ", converted.status().message()));
  }
  return std::move(converted->mesh);
}

absl::StatusOr<Mesh> GenerateWithMeshgen(const std::string& arguments) {
  // meshgen's own parser, with a placeholder for the output path it requires: a new generator
  // kind is benchmarkable as soon as getme-meshgen knows it.
  std::vector<std::string> args = absl::StrSplit(arguments, ' ', absl::SkipWhitespace());
  if (args.empty()) return absl::InvalidArgumentError("--generate: empty generator arguments");
  args.insert(args.begin() + 1, "unused.vtk");
  absl::StatusOr<meshgen::MeshgenCommand> command = meshgen::ParseMeshgenCommand(args);
  if (!command.ok()) {
    return absl::InvalidArgumentError(
        absl::StrCat("--generate \"", arguments, "\": ", command.status().message()));
  }
  absl::StatusOr<Mesh> mesh = meshgen::GenerateMesh(*command);
  if (!mesh.ok()) {
    return absl::Status(mesh.status().code(),
                        absl::StrCat("--generate \"", arguments, "\": ", mesh.status().message()));
  }
  return mesh;
}

std::vector<double> Copy(std::span<const double> values) {
  return std::vector<double>(values.begin(), values.end());
}

}  // namespace

void BenchmarkMesh::RestoreInitialCoordinates() {
  std::ranges::copy(initial_x, mesh.x().begin());
  std::ranges::copy(initial_y, mesh.y().begin());
  std::ranges::copy(initial_z, mesh.z().begin());
}

absl::StatusOr<BenchmarkMesh> LoadBenchmarkMesh(const MeshSpec& spec) {
  const std::int64_t rss_before = CurrentRssBytes();
  const auto start = std::chrono::steady_clock::now();
  absl::StatusOr<Mesh> mesh = spec.source == MeshSpec::Source::kFile
                                  ? ReadMesh(spec.path_or_arguments)
                                  : GenerateWithMeshgen(spec.path_or_arguments);
  if (!mesh.ok()) return mesh.status();
  BenchmarkMesh loaded;
  loaded.spec = spec;
  loaded.mesh = *std::move(mesh);
  loaded.load_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  loaded.initial_x = Copy(loaded.mesh.x());
  loaded.initial_y = Copy(loaded.mesh.y());
  loaded.initial_z = Copy(loaded.mesh.z());
  // The file document or generator draft is gone; without this glibc would keep its pages and
  // every later RSS figure would include them.
  malloc_trim(0);
  loaded.rss_before_load_bytes = rss_before;
  loaded.rss_after_load_bytes = CurrentRssBytes();
  return loaded;
}

}  // namespace getme::bench
