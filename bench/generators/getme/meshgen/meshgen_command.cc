#include "getme/meshgen/meshgen_command.h"

#include <utility>
#include <vector>

#include "absl/strings/match.h"
#include "absl/strings/numbers.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_split.h"
#include "getme/meshgen/distorted_hex_block.h"
#include "getme/meshgen/hybrid_block.h"
#include "getme/meshgen/jittered_tet_block.h"
#include "getme/meshgen/layered_hex_block.h"
#include "getme/meshgen/plate_with_holes.h"
#include "getme/meshgen/ring_in_block.h"

namespace getme::meshgen {
namespace {

absl::StatusOr<MeshKind> ParseKind(const std::string& kind) {
  if (kind == "hex") return MeshKind::kHexBlock;
  if (kind == "hex-layers") return MeshKind::kLayeredHexBlock;
  if (kind == "tet") return MeshKind::kTetBlock;
  if (kind == "hybrid") return MeshKind::kHybridBlock;
  if (kind == "vessel") return MeshKind::kVessel;
  if (kind == "artery") return MeshKind::kArtery;
  if (kind == "plate") return MeshKind::kPlate;
  if (kind == "ring") return MeshKind::kRing;
  return absl::InvalidArgumentError(
      absl::StrCat("unknown mesh kind '", kind,
                   "'; expected plate, ring, vessel, artery, hex, hex-layers, tet or hybrid"));
}

absl::Status ParseSize(const std::string& flag, const std::string& value, MeshgenCommand& command) {
  const std::vector<std::string> parts = absl::StrSplit(value, ',');
  std::vector<int> sizes;
  for (const std::string& part : parts) {
    int size = 0;
    if (!absl::SimpleAtoi(part, &size)) {
      return absl::InvalidArgumentError(
          absl::StrCat(flag, ": '", value, "' is not N or NX,NY,NZ (integers)"));
    }
    sizes.push_back(size);
  }
  if (sizes.size() == 1) sizes.assign(3, sizes[0]);
  if (sizes.size() != 3) {
    return absl::InvalidArgumentError(
        absl::StrCat(flag, ": '", value, "' has ", parts.size(), " values; expected 1 or 3"));
  }
  command.nx = sizes[0];
  command.ny = sizes[1];
  command.nz = sizes[2];
  return absl::OkStatus();
}

template <typename T>
absl::Status ParseNumber(const std::string& flag, const std::string& value, T& out) {
  bool ok = false;
  if constexpr (std::is_same_v<T, double>) {
    ok = absl::SimpleAtod(value, &out);
  } else {
    ok = absl::SimpleAtoi(value, &out);
  }
  if (!ok) {
    return absl::InvalidArgumentError(absl::StrCat(flag, ": '", value, "' is not a number"));
  }
  return absl::OkStatus();
}

// The plate's and the ring's options with the command's size, distortion and seed; what the
// command leaves unset keeps the generator's default.
template <typename Options>
Options SizedOptions(const MeshgenCommand& command) {
  Options options;
  options.target_elements = command.elements.value_or(options.target_elements);
  options.distortion = command.distortion.value_or(options.distortion);
  options.seed = command.seed;
  return options;
}

}  // namespace

absl::StatusOr<MeshgenCommand> ParseMeshgenCommand(std::span<const std::string> args) {
  std::vector<std::string> positional;
  MeshgenCommand command;
  bool mesh_size_given = false;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    if (!arg.starts_with("--")) {
      positional.push_back(arg);
      continue;
    }
    if (arg == "--binary") {
      command.binary = true;
      continue;
    }
    if (arg == "--fix-wall") {
      command.vessel.fix_outer_wall = true;
      continue;
    }
    if (i + 1 == args.size()) {
      return absl::InvalidArgumentError(absl::StrCat(arg, " needs a value"));
    }
    const std::string& value = args[++i];
    absl::Status status;
    if (arg == "--size") {
      status = ParseSize(arg, value, command);
    } else if (arg == "--distortion") {
      status = ParseNumber(arg, value, command.distortion.emplace());
    } else if (arg == "--elements") {
      status = ParseNumber(arg, value, command.elements.emplace());
      if (status.ok() && *command.elements < 1) {
        status = absl::InvalidArgumentError(
            absl::StrCat("--elements: must be at least 1, got ", *command.elements));
      }
    } else if (arg == "--seed") {
      status = ParseNumber(arg, value, command.seed);
    } else if (arg == "--mesh-size") {
      status = ParseNumber(arg, value, command.vessel.mesh_size);
      command.artery.mesh_size = command.vessel.mesh_size;
      mesh_size_given = true;
    } else if (arg == "--radius") {
      status = ParseNumber(arg, value, command.vessel.radius);
      command.artery.radius = command.vessel.radius;
    } else if (arg == "--length") {
      status = ParseNumber(arg, value, command.vessel.length);
      command.artery.length = command.vessel.length;
    } else if (arg == "--bend-angle") {
      status = ParseNumber(arg, value, command.vessel.bend_angle);
    } else if (arg == "--layers") {
      status = ParseNumber(arg, value, command.vessel.layers);
      command.artery.inward_layers = command.vessel.layers;
    } else if (arg == "--outer-layers") {
      status = ParseNumber(arg, value, command.artery.outward_layers);
    } else if (arg == "--helix-radius") {
      status = ParseNumber(arg, value, command.artery.helix_radius);
    } else if (arg == "--turn-angle") {
      status = ParseNumber(arg, value, command.artery.turn_angle);
    } else if (arg == "--taper") {
      status = ParseNumber(arg, value, command.artery.taper);
    } else if (arg == "--stenosis") {
      status = ParseNumber(arg, value, command.artery.stenosis);
    } else if (arg == "--branches") {
      status = ParseNumber(arg, value, command.artery.branches);
    } else if (arg == "--branch-radius-ratio") {
      status = ParseNumber(arg, value, command.artery.branch_radius_ratio);
    } else if (arg == "--branch-length") {
      status = ParseNumber(arg, value, command.artery.branch_length);
    } else if (arg == "--junction-fillet") {
      status = ParseNumber(arg, value, command.artery.junction_fillet);
    } else if (arg == "--first-layer-ratio") {
      status = ParseNumber(arg, value, command.artery.first_layer_ratio);
      command.layer_first_height = command.artery.first_layer_ratio;
    } else if (arg == "--growth-ratio") {
      status = ParseNumber(arg, value, command.artery.growth_ratio);
      command.layer_growth = command.artery.growth_ratio;
    } else if (arg == "--layer-height-ratio") {
      status = ParseNumber(arg, value, command.vessel.layer_height_ratio);
    } else {
      return absl::InvalidArgumentError(absl::StrCat("unknown option ", arg));
    }
    if (!status.ok()) return status;
  }
  if (positional.size() != 2) {
    return absl::InvalidArgumentError(absl::StrCat("expected KIND and OUT.vtk, got ",
                                                   positional.size(), " positional arguments"));
  }
  absl::StatusOr<MeshKind> kind = ParseKind(positional[0]);
  if (!kind.ok()) return kind.status();
  command.kind = *kind;
  command.output_path = positional[1];
  // The generator writes legacy VTK only; a name that promises another format (OUT.vtu) would
  // hold VTK text that every reader of that format then refuses.
  if (!absl::EndsWithIgnoreCase(command.output_path, ".vtk")) {
    return absl::InvalidArgumentError(
        absl::StrCat("OUT must be a legacy VTK file ending in .vtk (got '", command.output_path,
                     "'); write other formats with 'getme convert OUT.vtk OTHER'"));
  }
  command.vessel.seed = command.seed;
  command.artery.seed = command.seed;
  const bool sized_kind = command.kind == MeshKind::kPlate || command.kind == MeshKind::kRing ||
                          command.kind == MeshKind::kVessel;
  if (command.elements.has_value() && !sized_kind) {
    return absl::InvalidArgumentError(
        "--elements applies to plate, ring and vessel; size the blocks with --size");
  }
  if (command.elements.has_value() && command.kind == MeshKind::kVessel && !mesh_size_given) {
    command.vessel.mesh_size = kPaperVesselMeshSize;
  }
  return command;
}

absl::StatusOr<Mesh> GenerateMesh(const MeshgenCommand& command, std::string* note) {
  const double block_distortion = command.distortion.value_or(kBlockDistortion);
  switch (command.kind) {
    case MeshKind::kHexBlock:
      return DistortedHexBlock(command.nx, command.ny, command.nz, block_distortion, command.seed);
    case MeshKind::kLayeredHexBlock:
      return LayeredHexBlock(command.nx, command.ny, command.nz,
                             command.layer_first_height.value_or(kLayeredHexFirstHeight),
                             command.layer_growth.value_or(kLayeredHexGrowth), block_distortion,
                             command.seed);
    case MeshKind::kTetBlock:
      return JitteredTetBlock(command.nx, command.ny, command.nz, block_distortion, command.seed);
    case MeshKind::kHybridBlock:
      return HybridBlock(command.nx, command.ny, command.nz, block_distortion, command.seed);
    case MeshKind::kVessel:
      return ThinPrismVessel(command.elements.has_value()
                                 ? VesselOptionsForElements(*command.elements, command.vessel)
                                 : command.vessel);
    case MeshKind::kArtery: {
      absl::StatusOr<ArteryMesh> artery = GenerateArtery(command.artery);
      if (!artery.ok()) return artery.status();
      if (note != nullptr) {
        const BoundaryLayerReport& layers = artery->layers;
        *note = absl::StrCat(
            "first layer height ", artery->first_layer_height, " (",
            command.artery.first_layer_ratio, " x mean wall edge ", artery->mean_wall_edge, "), ",
            artery->caps.size(), " openings; stacks thinned: ", layers.thinned_inward, " inward, ",
            layers.thinned_outward, " outward of ", layers.wall_vertices, " wall nodes");
      }
      return std::move(artery->mesh);
    }
    case MeshKind::kPlate:
      return PlateWithHoles(SizedOptions<PlateWithHolesOptions>(command));
    case MeshKind::kRing:
      return RingInBlock(SizedOptions<RingInBlockOptions>(command));
  }
  return absl::InternalError("GenerateMesh: unhandled mesh kind");
}

}  // namespace getme::meshgen
