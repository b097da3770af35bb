#pragma once

// Independent checks of generated meshes: validity, per-element mean ratio and face conformity,
// computed from the element tables (paper Secs. 2.1–2.2, element_tables.h) without the engine's
// topology code.

#include <array>
#include <cstdint>
#include <map>
#include <vector>

#include "getme/elements/vec3.h"
#include "getme/mesh/mesh.h"

namespace getme::testing {

// A face of the mesh: its nodes in the owning element's face-table order (of the first element
// that has it) and every element that has it.
struct FaceUse {
  std::vector<NodeId> nodes;
  std::vector<ElementId> elements;
};
// Keyed by the face's node ids in ascending order; triangles and quads never share a key.
using FaceCensus = std::map<std::vector<NodeId>, FaceUse>;
FaceCensus CensusFaces(const Mesh& mesh);

std::vector<ElementId> InvalidElements(const Mesh& mesh);
std::vector<double> MeanRatios(const Mesh& mesh);
// Area of a planar triangle or (as two triangles) quad.
double FaceArea(const Mesh& mesh, const std::vector<NodeId>& nodes);

// Mean of the element's node positions.
Vec3 ElementCentroid(const Mesh& mesh, ElementId element);
// Volume enclosed by the boundary faces (faces of exactly one element), each fanned into
// triangles from its first node and turned to face away from its element's centroid: the
// divergence theorem, so it needs no volume formula for distorted elements.
double EnclosedVolume(const Mesh& mesh);

struct BlockFaceReport {
  std::int64_t shared_faces = 0;          // faces of exactly two elements
  std::int64_t boundary_faces = 0;        // faces of exactly one element
  std::int64_t overused_faces = 0;        // faces of three or more elements
  std::int64_t inner_boundary_faces = 0;  // single-element faces not lying on the box surface
  double boundary_area = 0.0;             // total area of the single-element faces
};
// Conformity of a mesh of the box [0,nx]×[0,ny]×[0,nz]: a face is on the box surface when all its
// nodes lie exactly on one of the six planes (generators never move boundary nodes).
BlockFaceReport CheckBlockFaces(const Mesh& mesh, int nx, int ny, int nz);

}  // namespace getme::testing
