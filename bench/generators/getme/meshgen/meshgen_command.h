#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>

#include "absl/status/statusor.h"
#include "getme/mesh/mesh.h"
#include "getme/meshgen/artery.h"
#include "getme/meshgen/thin_prism_vessel.h"

namespace getme::meshgen {

enum class MeshKind {
  kHexBlock,
  kLayeredHexBlock,
  kTetBlock,
  kHybridBlock,
  kVessel,
  kArtery,
  kPlate,
  kRing
};

inline constexpr double kBlockDistortion = 0.3;
inline constexpr double kLayeredHexFirstHeight = 0.01;
inline constexpr double kLayeredHexGrowth = 1.3;

// One invocation of getme-meshgen: which mesh, with which parameters, written where.
struct MeshgenCommand {
  MeshKind kind = MeshKind::kHybridBlock;
  std::string output_path;
  int nx = 8, ny = 8, nz = 8;  // cubes per axis for the blocks
  // Per-axis move of interior nodes, in edge lengths; unset: each generator's default (blocks
  // kBlockDistortion, plate and ring their options' defaults).
  std::optional<double> distortion;
  std::uint64_t seed = 1;
  // plate, ring, vessel: the element count to aim for; unset: the paper's size for plate and ring,
  // the vessel options as given for vessel.
  std::optional<std::int64_t> elements;
  ThinPrismVesselOptions vessel;
  ArteryOptions artery;  // --radius, --length, --mesh-size, --layers and --seed set it too
  // hex-layers: --first-layer-ratio and --growth-ratio; unset: the defaults below.
  std::optional<double> layer_first_height;
  std::optional<double> layer_growth;
  bool binary = false;
};

inline constexpr char kMeshgenUsage[] =
    "usage: getme-meshgen KIND OUT.vtk [options]\n"
    "  KIND: the paper's examples at any size (--elements):\n"
    "          plate  hexahedral plate with two drill holes in a tetrahedral box, pyramids\n"
    "                 between (Sec. 4.1; default 34,050 elements)\n"
    "          ring   tetrahedra around a ring (a hole) in a hexahedral block, pyramids between,\n"
    "                 randomly distorted (Sec. 4.2; default 83,210 elements)\n"
    "          vessel tetrahedral vessel in 6 thin prism layers (Sec. 4.3)\n"
    "          artery vascular CFD-like mesh: helical centre line, tapering radius with a\n"
    "                 stenosis, side branches, prism layers grown inward and outward from the\n"
    "                 wall with geometric growth (default 2 branches, 6 + 2 layers, 21k\n"
    "                 elements; --mesh-size 0.5: 8k, 0.2: 50k; docs/thin-layers.md)\n"
    "        blocks: hex (distorted hexahedra), tet (jittered Kuhn tetrahedra),\n"
    "          hybrid (hexahedra, prisms, pyramids and tetrahedra),\n"
    "          hex-layers (hexahedra clustered geometrically toward the wall z = 0, a\n"
    "          boundary-layer block: layer k is --first-layer-ratio x --growth-ratio^k\n"
    "          thick, x and y edges 1; defaults 0.01 and 1.3; --distortion 0.3 leans the\n"
    "          columns)\n"
    "  --elements N            plate/ring/vessel: aim for N elements (plate and ring within 10 %,\n"
    "                          vessel within 20 %; vessel: a straight vessel whose length grows\n"
    "                          with N, built from segments of at most 100k elements)\n"
    "  --size N | NX,NY,NZ     cubes per axis for hex/tet/hybrid (default 8)\n"
    "  --distortion D          interior node moves up to D edge lengths per axis (default 0.3\n"
    "                          for hex/tet/hybrid, 0.2 plate, 0.6 ring)\n"
    "  --seed N                random seed (default 1; gmsh's seed for vessel)\n"
    "  --mesh-size H           vessel: tetrahedron edge length (default 0.25; with --elements\n"
    "                          0.38, which gives the paper's 68 % prisms and q_mean 0.30)\n"
    "  --radius R  --length L  --bend-angle A  --layers N  --layer-height-ratio F\n"
    "                          vessel geometry and prism layers (defaults 1, 6, 0, 6, 0.01);\n"
    "                          --length 42 --bend-angle 1.5 gives ~100k elements, 60 % prisms;\n"
    "                          with --elements, --length and --bend-angle do not apply\n"
    "  artery (--radius, --length, --mesh-size, --seed as above; defaults 1, 8, 0.3, 1):\n"
    "  --helix-radius A  --turn-angle PHI\n"
    "                          centre line: a helix of radius A turning PHI radians about z\n"
    "                          while rising by --length (defaults 2, 3.8); A 0: straight\n"
    "  --taper T  --stenosis S radius 1-T times the inlet's at the outlet, narrowed by S in a\n"
    "                          stenosis half way (defaults 0.3, 0.3)\n"
    "  --branches N            side branches, 0 to 3 (default 2)\n"
    "  --branch-radius-ratio F  --branch-length L\n"
    "                          branch start radius over the main radius there, and length\n"
    "                          (defaults 0.55, 3)\n"
    "  --junction-fillet F     round the branch junctions with a fillet of radius F x --radius\n"
    "                          (default 0.25); 0: a sharp crease, the harder case\n"
    "  --layers N  --outer-layers M\n"
    "                          prism layers inside the lumen and outside the wall (defaults\n"
    "                          6, 2; for vessel --layers is its outward layer count)\n"
    "  --first-layer-ratio F   height of the layers touching the wall, as a fraction of the\n"
    "                          mean wall edge length (default 0.005)\n"
    "  --growth-ratio G        each layer G times thicker than the next one towards the wall\n"
    "                          (default 1.2)\n"
    "                          no node is marked fixed; the engine's default fix_boundary pins\n"
    "                          the whole boundary (outer wall and caps)\n"
    "  --fix-wall              vessel: mark the outer wall (outer prism surface) fixed in the\n"
    "                          `fixed` point data; smooth with --free-boundary so the inflow\n"
    "                          and outflow caps may move (docs/thin-layers.md)\n"
    "  --binary                write BINARY VTK instead of ASCII\n";

// Parses the arguments after the program name. InvalidArgument names the offending argument.
absl::StatusOr<MeshgenCommand> ParseMeshgenCommand(std::span<const std::string> args);

// Runs the generator the command asks for. When `note` is given, generators with something to
// report beyond the mesh (artery: first layer height, thinned stacks) write one line into it.
absl::StatusOr<Mesh> GenerateMesh(const MeshgenCommand& command, std::string* note = nullptr);

}  // namespace getme::meshgen
