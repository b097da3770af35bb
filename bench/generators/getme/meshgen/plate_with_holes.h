#pragma once

#include <array>
#include <cstdint>

#include "absl/status/statusor.h"
#include "getme/mesh/mesh.h"
#include "getme/meshgen/cube_fill.h"

namespace getme::meshgen {

// The paper's first example (Sec. 4.1, Fig. 5): a hexahedral plate with two drill holes embedded
// in a tetrahedral box, a layer of pyramids between them. The paper's mesh has 5,748 hexahedra,
// 2,220 pyramids and 26,082 tetrahedra (17 % / 7 % / 77 %), and 1,022 boundary nodes, all on the
// box: the plate's surface, hole walls included, is inside the mesh, so the holes are filled with
// tetrahedra here too.
//
// Built from unit cubes (cube_fill.h): the plate is kPlateThickness cubes thick, surrounded by one
// layer of centred-tet cubes on every side; the size parameter is the plate's width, its length
// is kPlateAspect times that. Margin and thickness stay fixed in cubes while the plate grows
// sideways, so the type mix is the same at every size (the scaling benchmarks compare
// per-element costs across sizes). Measured hexahedra / pyramids / tetrahedra: 15 / 7 / 78 % at
// 100k, 18 / 6 / 76 % at 1M, 18 / 6 / 75 % at 10M; the side margins weigh more in small plates:
// 13 / 7 / 80 % at the paper's 34k, 8 / 7 / 85 % at 10k.
// With a one-cube margin every tetrahedron lies between the fixed box and the free plate surface,
// as the paper's thin tetrahedral shell does (its box has only 1,022 nodes).
inline constexpr int kPlateThickness = 6;
inline constexpr double kPlateAspect = 1.6;

// A hole drilled through the plate along z: centre (x, y) and radius, in cube units.
struct DrillHole {
  double x, y, radius;
};

// Where the plate and its holes lie in the box of nx × ny × nz unit cubes.
struct PlateLayout {
  int nx = 0, ny = 0, nz = 0;
  // The plate slab before drilling: cubes i in [x0, x1), j in [y0, y1), k in [z0, z1).
  int x0 = 0, x1 = 0, y0 = 0, y1 = 0, z0 = 0, z1 = 0;
  // A larger and a smaller hole (the paper's plate has two of different diameters), centred on
  // grid points on the plate's long axis.
  std::array<DrillHole, 2> holes{};

  // Whether cube (i, j, k) is plate material: in the slab and its centre outside both holes.
  bool IsPlateCube(int i, int j, int k) const;
};

// The layout for a plate `width` cubes wide (rounded; at least 6).
PlateLayout PlateLayoutForWidth(double width);
// Hexahedra for plate cubes, centred tetrahedra elsewhere.
CubeFillGrid FillPlate(const PlateLayout& layout);

struct PlateWithHolesOptions {
  // The plate width is chosen so the element count is the closest the cube grid allows (within
  // 10 %; measured within 2 % from 100k up, 5 % at 10k). 34,050 is the paper's mesh.
  std::int64_t target_elements = 34'050;
  // Per-axis node moves in cube edge lengths (cube_fill.h). The paper's plate came from a mesher
  // (initial q_min / q_mean 0.1625 / 0.7302); an undistorted cube mesh would give the smoother
  // nothing to do on the hexahedra, so interior nodes move by up to 0.2 edge lengths: at 34k,
  // q_min / q_mean 0.762 / 0.807 undistorted, 0.185 / 0.769 distorted (q_min falls with size as
  // more nodes draw extreme moves: 0.10 at 1M, 0.01 at 10M).
  double distortion = 0.2;
  std::uint64_t seed = 1;
};

// The layout whose element count is closest to `target_elements`; InvalidArgument when no layout
// comes within 10 % (targets below about 5.4k elements: the smallest plate has 5,888).
absl::StatusOr<PlateLayout> PlateLayoutFor(std::int64_t target_elements);

absl::StatusOr<Mesh> PlateWithHoles(const PlateWithHolesOptions& options = {});

}  // namespace getme::meshgen
