#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products
#include <algorithm>
#include <array>
#include <utility>

#include "getme/elements/element_tables.h"
#include "getme/elements/lanes.h"
#include "getme/mesh/mesh.h"

namespace getme {

using Vec3 = Eigen::Vector3d;

// One node's coordinates gathered from the structure-of-arrays mesh (for setup code, not for the
// per-element kernels, which gather through ElementNodes).
inline Vec3 NodePosition(const Mesh& mesh, NodeId node) {
  return Vec3(mesh.x()[node], mesh.y()[node], mesh.z()[node]);
}

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

namespace internal {

// Node k's coordinate `axis` of every lane's element, built as one vector value from its lanes
// rather than lane by lane into memory: lane stores followed by a vector load cannot be forwarded
// and stalled the passes (11 % of a mean-ratio pass at 8 lanes).
template <typename S, std::size_t... kLane>
GETME_LANE_INLINE S GatherCoordinate(const double* axis, const NodeId* const* lane_nodes, int k,
                                     std::index_sequence<kLane...>) {
  return S{axis[lane_nodes[kLane][k]]...};
}

}  // namespace internal

// Gathers the nodes of kWidth elements, one per lane: lane l's node ids start at lane_nodes[l].
template <ElementType kType, int kWidth>
GETME_LANE_INLINE LaneNodes<kType, LanesOf<kWidth>> GatherLanes(std::span<const double> x,
                                                                std::span<const double> y,
                                                                std::span<const double> z,
                                                                const NodeId* const* lane_nodes) {
  using S = LanesOf<kWidth>;
  constexpr auto kLaneIndices = std::make_index_sequence<kWidth>();
  LaneNodes<kType, S> nodes;
  for (int k = 0; k < ElementTable<kType>::kNodes; ++k) {
    nodes[k] = {internal::GatherCoordinate<S>(x.data(), lane_nodes, k, kLaneIndices),
                internal::GatherCoordinate<S>(y.data(), lane_nodes, k, kLaneIndices),
                internal::GatherCoordinate<S>(z.data(), lane_nodes, k, kLaneIndices)};
  }
  return nodes;
}

// Gathers the nodes of `count` (1..kWidth) consecutive block entries whose node ids start at
// `ids`, one element per lane; lanes past `count` repeat the last element.
template <ElementType kType, int kWidth = kLanes>
GETME_LANE_INLINE LaneNodes<kType, LanesOf<kWidth>> GatherLanes(std::span<const double> x,
                                                                std::span<const double> y,
                                                                std::span<const double> z,
                                                                const NodeId* ids, int count) {
  constexpr int kNodes = ElementTable<kType>::kNodes;
  const NodeId* lane_nodes[kWidth];
  for (int l = 0; l < kWidth; ++l) lane_nodes[l] = ids + std::min(l, count - 1) * kNodes;
  return GatherLanes<kType, kWidth>(x, y, z, lane_nodes);
}

}  // namespace getme
