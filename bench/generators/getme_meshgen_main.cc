// getme-meshgen: writes a generated test or benchmark mesh as a VTK legacy file and reports its
// element counts and quality.

#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include "absl/strings/str_format.h"
#include "formats/grid_mesh.h"
#include "formats/vtk_writer.h"
#include "getme/mesh/mesh_quality.h"
#include "getme/meshgen/meshgen_command.h"
#include "getme/parallel/thread_pool.h"

namespace {

const char* KindName(getme::meshgen::MeshKind kind) {
  switch (kind) {
    case getme::meshgen::MeshKind::kHexBlock:
      return "hex";
    case getme::meshgen::MeshKind::kLayeredHexBlock:
      return "hex-layers";
    case getme::meshgen::MeshKind::kTetBlock:
      return "tet";
    case getme::meshgen::MeshKind::kHybridBlock:
      return "hybrid";
    case getme::meshgen::MeshKind::kPlate:
      return "plate";
    case getme::meshgen::MeshKind::kRing:
      return "ring";
    case getme::meshgen::MeshKind::kArtery:
      return "artery";
    case getme::meshgen::MeshKind::kVessel:
      break;
  }
  return "vessel";
}

int Run(std::span<const std::string> args) {
  using namespace getme;
  if (args.size() == 1 && (args[0] == "--help" || args[0] == "-h")) {
    std::fputs(meshgen::kMeshgenUsage, stdout);
    return 0;
  }
  absl::StatusOr<meshgen::MeshgenCommand> command = meshgen::ParseMeshgenCommand(args);
  if (!command.ok()) {
    absl::FPrintF(stderr, "getme-meshgen: %s\n%s", command.status().message(),
                  meshgen::kMeshgenUsage);
    return 2;
  }
  const auto start = std::chrono::steady_clock::now();
  std::string note;
  absl::StatusOr<Mesh> mesh = meshgen::GenerateMesh(*command, &note);
  const double generate_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!mesh.ok()) {
    absl::FPrintF(stderr, "getme-meshgen: %s\n", mesh.status().ToString());
    return 1;
  }
  // Peak resident memory of generation alone, before the writer's copy (Linux reports KiB).
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  const double generate_peak_mib = static_cast<double>(usage.ru_maxrss) / 1024.0;
  const std::string title =
      absl::StrFormat("getme-meshgen %s seed %d", KindName(command->kind), command->seed);
  const formats::UnstructuredGrid file = formats::GridFromMesh(*mesh, title);
  if (absl::Status status = formats::WriteVtkFile(
          command->output_path, file,
          command->binary ? formats::Encoding::kBinary : formats::Encoding::kAscii);
      !status.ok()) {
    absl::FPrintF(stderr, "getme-meshgen: %s\n", status.ToString());
    return 1;
  }
  ThreadPool pool(1);
  const MeshQuality quality = EvaluateMeshQuality(*mesh, pool);
  absl::PrintF("%s: %d nodes, %d elements; generated in %.2f s, peak RSS %.0f MiB\n",
               command->output_path, mesh->node_count(), mesh->element_count(), generate_seconds,
               generate_peak_mib);
  for (const ElementType type : kAllElementTypes) {
    const TypeQuality& by_type = quality.by_type[TypeIndex(type)];
    if (by_type.count == 0) continue;
    absl::PrintF("  %-12s %8d  q_min %.4f  q_mean %.4f\n", std::string(TypeName(type)),
                 by_type.count, by_type.q_min, by_type.q_mean);
  }
  absl::PrintF("  %-12s %8d  q_min %.4f  q_mean %.4f  invalid %d\n", "all", quality.elements,
               quality.q_min, quality.q_mean, quality.invalid);
  if (!note.empty()) absl::PrintF("  %s\n", note);
  return quality.invalid == 0 ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  return Run(args);
}
