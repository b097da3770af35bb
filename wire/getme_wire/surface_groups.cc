#include "getme_wire/surface_groups.h"

#include <algorithm>

#include "absl/strings/str_cat.h"

namespace getme::wire {
namespace {

struct FaceField {
  const char* faces;  // the field's name in mesh.proto
  const char* tags;
  const char* shape;
  int size;
  const std::vector<std::uint32_t>& nodes;
  const std::vector<std::uint32_t>& groups;
};

absl::Status CheckField(const FaceField& field, std::int64_t node_count) {
  const auto values = static_cast<std::int64_t>(field.nodes.size());
  if (values % field.size != 0) {
    return absl::InvalidArgumentError(absl::StrCat("mesh.", field.faces, " has ", values,
                                                   " node indices, not a multiple of ", field.size,
                                                   " (nodes per ", field.shape, ")"));
  }
  const std::int64_t faces = values / field.size;
  if (static_cast<std::int64_t>(field.groups.size()) != faces) {
    return absl::InvalidArgumentError(absl::StrCat(
        "mesh.", field.tags, " has ", field.groups.size(), " tags but mesh.", field.faces, " has ",
        faces, " ", field.shape, "s: give one tag per ", field.shape));
  }
  for (std::int64_t i = 0; i < values; ++i) {
    if (field.nodes[i] >= node_count) {
      return absl::InvalidArgumentError(absl::StrCat("mesh.", field.faces, "[", i,
                                                     "] = ", field.nodes[i], " (", field.shape, " ",
                                                     i / field.size,
                                                     ") is out of range: the mesh "
                                                     "has ",
                                                     node_count, " nodes"));
    }
  }
  return absl::OkStatus();
}

}  // namespace

void WireSurfaceGroups::Append(const v1::Mesh& part) {
  triangles.insert(triangles.end(), part.group_triangles().begin(), part.group_triangles().end());
  quads.insert(quads.end(), part.group_quads().begin(), part.group_quads().end());
  triangle_groups.insert(triangle_groups.end(), part.triangle_groups().begin(),
                         part.triangle_groups().end());
  quad_groups.insert(quad_groups.end(), part.quad_groups().begin(), part.quad_groups().end());
}

absl::StatusOr<std::vector<surface::GroupedFace>> ToSurfaceGroups(const WireSurfaceGroups& wire,
                                                                  std::int64_t node_count) {
  const FaceField fields[] = {
      {"group_triangles", "triangle_groups", "triangle", 3, wire.triangles, wire.triangle_groups},
      {"group_quads", "quad_groups", "quad", 4, wire.quads, wire.quad_groups},
  };
  std::vector<std::uint32_t> tags;
  for (const FaceField& field : fields) {
    if (auto status = CheckField(field, node_count); !status.ok()) return status;
    tags.insert(tags.end(), field.groups.begin(), field.groups.end());
  }
  std::sort(tags.begin(), tags.end());
  tags.erase(std::unique(tags.begin(), tags.end()), tags.end());
  std::vector<surface::GroupedFace> faces;
  faces.reserve(wire.triangle_groups.size() + wire.quad_groups.size());
  for (const FaceField& field : fields) {
    for (std::size_t f = 0; f < field.groups.size(); ++f) {
      surface::GroupedFace face{{-1, -1, -1, -1}, field.size, 0};
      for (int k = 0; k < field.size; ++k) {
        face.nodes[k] = static_cast<NodeId>(field.nodes[f * field.size + k]);
      }
      face.group = static_cast<int>(std::lower_bound(tags.begin(), tags.end(), field.groups[f]) -
                                    tags.begin()) +
                   1;
      faces.push_back(face);
    }
  }
  return faces;
}

}  // namespace getme::wire
