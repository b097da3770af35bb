#pragma once

// Meshes whose boundary is known exactly, built node by node for the surface tests.

#include "getme/mesh/mesh.h"

namespace getme::test {

// n × n × n unit hexahedra filling [0, n]³, nodes numbered x fastest: node (i, j, k) is
// i + (n + 1) (j + (n + 1) k).
Mesh HexCube(int n);

// A regular polygon of `sides` sides and radius 1 around the z axis, extruded from z = 0 to
// z = height in `layers` layers of prisms (each a triangle centre–rim–rim): a faceted cylinder
// whose neighbouring side faces meet at 360° / sides.
Mesh PolygonPrism(int sides, int layers, double height);

// The icosahedron inscribed in the unit sphere with each face split into four and the new
// nodes pushed out onto the sphere (80 faces), filled with tetrahedra from the centre.
Mesh FacetedSphere();

}  // namespace getme::test
