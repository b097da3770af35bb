#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products
#include <array>

#include "getme/element_tables.h"
#include "getme/mesh.h"

namespace getme {

using Vec3 = Eigen::Vector3d;

// The nodes of one element as small fixed-size arrays: what every per-element kernel works on.
template <ElementType kType>
using ElementNodes = std::array<Vec3, ElementTable<kType>::kNodes>;

// Gathers an element's node coordinates from the mesh's structure-of-arrays storage.
template <ElementType kType>
inline ElementNodes<kType> GatherNodes(std::span<const double> x, std::span<const double> y,
                                       std::span<const double> z, const NodeId* ids) {
  ElementNodes<kType> nodes;
  for (int k = 0; k < ElementTable<kType>::kNodes; ++k) {
    nodes[k] = Vec3(x[ids[k]], y[ids[k]], z[ids[k]]);
  }
  return nodes;
}

template <ElementType kType>
inline ElementNodes<kType> GatherNodes(const Mesh& mesh, const NodeId* ids) {
  return GatherNodes<kType>(mesh.x(), mesh.y(), mesh.z(), ids);
}

}  // namespace getme
