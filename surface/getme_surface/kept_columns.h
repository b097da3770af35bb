#pragma once

// The boundary-layer columns (layer_columns.h) described as the engine keeps them
// (core/getme/smoothing/kept_layers.h).

#include "getme/smoothing/kept_layers.h"
#include "getme_surface/layer_columns.h"
#include "getme_surface/wall_distance.h"

namespace getme::surface {

// Per wall node: its chain of layer nodes, lowest first; the wall's normal there (area-weighted
// over its wall faces, turned into the layers); each node's distance along it, chosen so that
// the node's distance from the input's wall is its input distance; and its neighbours on the
// wall. A node at or above one where columns collide belongs to no column.
KeptLayers DescribeKeptLayers(const Mesh& mesh, const LayerColumns& layers,
                              const WallDistance& walls);

// The point of the ray from `from` along unit `direction` at distance `distance` from the walls,
// starting from `along` on the ray: each round scales the distance along the ray by how far the
// point it gives falls short of (or beyond) the wall distance wanted.
Vec3 AlongToWallDistance(const WallDistance& walls, const Vec3& from, const Vec3& direction,
                         double along, double distance);

}  // namespace getme::surface
