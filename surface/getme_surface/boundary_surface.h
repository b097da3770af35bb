#pragma once

// The boundary surface of a volume mesh as a sliding boundary needs it (issue 15, item 1): the
// faces used by exactly one element, each in a surface group, and the features that split it:
// feature edges (a dihedral angle above the feature angle, or two groups meeting), the feature
// curves they chain into, and corners. Built once from the input mesh, before any node moves:
// "the input's own surface" is this one.
//
// What a boundary node may do follows from its kind:
//   - kSurface: slide on the faces of its group;
//   - kFeature: slide along its feature curve;
//   - kCorner (on other than two feature edges, e.g. where three feature curves meet, or at the
//     end of an open curve): stay where it is.
// docs/boundary.md explains the choices (the default feature angle among them).

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "absl/status/statusor.h"
#include "getme/mesh/mesh.h"

namespace getme::surface {

// 45°: a smooth surface faceted with at least 8 faces around a full turn (a coarse cylinder or
// sphere) has its neighbouring faces meet at 45° or less, so it stays one surface; the edges a
// CAD model calls sharp (60° and more, the cube's 90°) are features.
inline constexpr double kDefaultFeatureAngleDegrees = 45.0;

struct BoundaryFace {
  std::array<NodeId, 4> nodes;  // turned so that the normal points out of the mesh
  int size;                     // 3 or 4
  int group;                    // surface group: 0 unless the caller's groups say otherwise
};

// A face the input tags with a group (a physical tag, SU2 marker or MEDIT reference): its nodes
// in any order.
struct GroupedFace {
  std::array<NodeId, 4> nodes;
  int size;  // 3 or 4
  int group;
};

enum class BoundaryNodeKind : std::uint8_t { kInterior, kSurface, kFeature, kCorner };

struct BoundarySurface {
  std::vector<BoundaryFace> faces;
  // Per mesh node.
  std::vector<BoundaryNodeKind> kind;
  // Per mesh node: for kSurface its group (all its faces have it), for kFeature its curve, else -1.
  std::vector<int> support;
  // Feature edges as node pairs (smaller id first), ascending, and the curve of each.
  std::vector<std::array<NodeId, 2>> feature_edges;
  std::vector<int> edge_curve;
  int curve_count = 0;
  int group_count = 0;
  std::int64_t corner_count = 0;
  // Grouped faces left out as not on the boundary (skip_interior_groups).
  std::int64_t interior_grouped_faces = 0;
};

// Extracts the boundary of `mesh` and classifies its nodes. `groups` tags boundary faces; a face
// it does not list is in group 0, and an entry that is not a boundary face of the mesh is an
// InvalidArgument naming it. A node whose faces lie in two groups is on a feature edge between
// them, so it never leaves its group. feature_angle_degrees must be in [0, 180]. With
// skip_interior_groups, grouped faces that are not on the boundary are counted instead
// (interior_grouped_faces): a file's tagged surface cells include the interfaces between its
// volumes, which bound no surface to slide on.
absl::StatusOr<BoundarySurface> ExtractBoundarySurface(
    const Mesh& mesh, std::span<const GroupedFace> groups = {},
    double feature_angle_degrees = kDefaultFeatureAngleDegrees, bool skip_interior_groups = false);

}  // namespace getme::surface
