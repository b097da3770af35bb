#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "absl/status/statusor.h"
#include "getme/v1/mesh.pb.h"
#include "getme_surface/boundary_surface.h"

namespace getme::wire {

// The tagged boundary faces of an upload (mesh.proto: group_triangles, group_quads,
// triangle_groups, quad_groups), gathered over its chunks.
struct WireSurfaceGroups {
  std::vector<std::uint32_t> triangles;
  std::vector<std::uint32_t> quads;
  std::vector<std::uint32_t> triangle_groups;
  std::vector<std::uint32_t> quad_groups;

  bool empty() const {
    return triangles.empty() && quads.empty() && triangle_groups.empty() && quad_groups.empty();
  }
  void Append(const v1::Mesh& part);
};

// As the surface's groups (surface/getme_surface/boundary_surface.h): triangles first, then
// quads; the distinct tags in ascending order become groups 1, 2, ..., and group 0 is left to the
// boundary faces the caller did not list. INVALID_ARGUMENT naming the field and entry for a count
// that is not whole, a tag count that differs from the face count, or a node out of range.
absl::StatusOr<std::vector<surface::GroupedFace>> ToSurfaceGroups(const WireSurfaceGroups& wire,
                                                                  std::int64_t node_count);

}  // namespace getme::wire
