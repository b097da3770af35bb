#pragma once

#include <cstdint>
#include <span>
#include <string>

#include "absl/status/statusor.h"
#include "getme/mesh.h"
#include "getme/meshgen/thin_prism_vessel.h"

namespace getme::meshgen {

enum class MeshKind { kHexBlock, kTetBlock, kHybridBlock, kVessel };

// One invocation of getme-meshgen: which mesh, with which parameters, written where.
struct MeshgenCommand {
  MeshKind kind = MeshKind::kHybridBlock;
  std::string output_path;
  int nx = 8, ny = 8, nz = 8;  // cubes per axis for the blocks
  double distortion = 0.3;     // blocks: per-axis move of interior nodes, in edge lengths
  std::uint64_t seed = 1;
  ThinPrismVesselOptions vessel;
  bool binary = false;
};

inline constexpr char kMeshgenUsage[] =
    "usage: getme-meshgen KIND OUT.vtk [options]\n"
    "  KIND: hex (distorted hexahedra), tet (jittered Kuhn tetrahedra),\n"
    "        hybrid (hexahedra, prisms, pyramids and tetrahedra), vessel (tetrahedra + thin "
    "prisms)\n"
    "  --size N | NX,NY,NZ     cubes per axis for hex/tet/hybrid (default 8)\n"
    "  --distortion D          hex/tet/hybrid: interior node moves up to D edge lengths per axis "
    "(default 0.3)\n"
    "  --seed N                random seed (default 1; gmsh's seed for vessel)\n"
    "  --mesh-size H           vessel: tetrahedron edge length (default 0.25)\n"
    "  --radius R  --length L  --bend-angle A  --layers N  --layer-height-ratio F\n"
    "                          vessel geometry and prism layers (defaults 1, 6, 0, 6, 0.01);\n"
    "                          --length 42 --bend-angle 1.5 gives ~100k elements, 60 % prisms\n"
    "  --fix-wall              vessel: mark the outer wall (outer prism surface) fixed in the\n"
    "                          `fixed` point data; smooth with --free-boundary so the inflow\n"
    "                          and outflow caps may move (docs/thin-layers.md)\n"
    "  --binary                write BINARY VTK instead of ASCII\n";

// Parses the arguments after the program name. InvalidArgument names the offending argument.
absl::StatusOr<MeshgenCommand> ParseMeshgenCommand(std::span<const std::string> args);

// Runs the generator the command asks for.
absl::StatusOr<Mesh> GenerateMesh(const MeshgenCommand& command);

}  // namespace getme::meshgen
