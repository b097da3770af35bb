#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products
#include <algorithm>
#include <array>

#include "getme/elements/element_tables.h"
#include "getme/elements/lanes.h"
#include "getme/mesh/mesh.h"

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

// An element's nodes with lane-typed coordinates (lanes.h): S = double for one element, Lanes for
// kLanes elements at once. The generic kernels work on these.
template <ElementType kType, typename S>
using LaneNodes = std::array<Point3<S>, ElementTable<kType>::kNodes>;

template <ElementType kType>
inline LaneNodes<kType, double> ToLaneNodes(const ElementNodes<kType>& p) {
  LaneNodes<kType, double> nodes;
  for (int k = 0; k < ElementTable<kType>::kNodes; ++k) nodes[k] = {p[k].x(), p[k].y(), p[k].z()};
  return nodes;
}

template <ElementType kType>
inline ElementNodes<kType> ToElementNodes(const LaneNodes<kType, double>& p) {
  ElementNodes<kType> nodes;
  for (int k = 0; k < ElementTable<kType>::kNodes; ++k) nodes[k] = Vec3(p[k].x, p[k].y, p[k].z);
  return nodes;
}

// Gathers the nodes of `count` (1..kLanes) consecutive block entries whose node ids start at
// `ids`, one element per lane; lanes past `count` repeat the last element.
template <ElementType kType>
inline LaneNodes<kType, Lanes> GatherLanes(std::span<const double> x, std::span<const double> y,
                                           std::span<const double> z, const NodeId* ids,
                                           int count) {
  constexpr int kNodes = ElementTable<kType>::kNodes;
  LaneNodes<kType, Lanes> nodes;
  for (int l = 0; l < kLanes; ++l) {
    const NodeId* element = ids + std::min(l, count - 1) * kNodes;
    for (int k = 0; k < kNodes; ++k) {
      nodes[k].x[l] = x[element[k]];
      nodes[k].y[l] = y[element[k]];
      nodes[k].z[l] = z[element[k]];
    }
  }
  return nodes;
}

}  // namespace getme
