#include "getme_surface/wall_distance.h"

#include "getme_surface/aabb_trees.h"

namespace getme::surface {

struct WallDistance::Tree {
  aabb::TriangleSet walls;
};

WallDistance::WallDistance(const Mesh& mesh, const LayerColumns& columns)
    : tree_(std::make_unique<Tree>()) {
  for (std::size_t f = 0; f < columns.wall_faces.size(); ++f) {
    aabb::AppendFaceTriangles(mesh, columns.wall_faces[f], columns.wall_face_sizes[f],
                              tree_->walls.items);
  }
  tree_->walls.Build();
}

WallDistance::WallDistance(WallDistance&&) noexcept = default;
WallDistance& WallDistance::operator=(WallDistance&&) noexcept = default;
WallDistance::~WallDistance() = default;

Vec3 WallDistance::Nearest(const Vec3& point) const { return tree_->walls.Nearest(point); }

}  // namespace getme::surface
