#pragma once

// Distances from the walls of boundary-layer columns (layer_columns.h), as the input had them: a
// CFD user's layer height is a distance from the wall, so this is what --keep-layers holds and what
// the layer report measures (layer_heights.h). Nearest points come from a CGAL AABB tree over the
// wall faces (quads split along 0–2), built once; queries only read, so threads may share it.

#include <memory>

#include "getme/elements/vec3.h"
#include "getme/mesh/mesh.h"
#include "getme_surface/layer_columns.h"

namespace getme::surface {

class WallDistance {
 public:
  // The walls of `columns` at the current coordinates of `mesh`.
  WallDistance(const Mesh& mesh, const LayerColumns& columns);
  WallDistance(WallDistance&&) noexcept;
  WallDistance& operator=(WallDistance&&) noexcept;
  ~WallDistance();

  // The nearest wall point to `point` (`point` itself without walls).
  Vec3 Nearest(const Vec3& point) const;
  double Distance(const Vec3& point) const { return (Nearest(point) - point).norm(); }

 private:
  struct Tree;
  std::unique_ptr<Tree> tree_;
};

}  // namespace getme::surface
