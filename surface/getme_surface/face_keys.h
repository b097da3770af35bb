#pragma once

// A face's nodes sorted ascending: the key under which the elements that share a face meet,
// whatever order each element lists its nodes in.

#include <algorithm>
#include <array>

#include "getme/mesh/mesh.h"

namespace getme::surface {

using SortedFace = std::array<NodeId, 4>;  // ascending ids, -1 after a triangle's three

inline SortedFace Sorted(const std::array<NodeId, 4>& nodes, int size) {
  SortedFace sorted = {-1, -1, -1, -1};
  std::copy_n(nodes.begin(), size, sorted.begin());
  // Insertion sort of ≤ 4 ids: std::sort here trips GCC 12's -Warray-bounds (as in mesh.cc).
  for (int k = 1; k < size; ++k) {
    for (int j = k; j > 0 && sorted[j - 1] > sorted[j]; --j) std::swap(sorted[j - 1], sorted[j]);
  }
  return sorted;
}

// Turns a face (3 or 4 nodes) the other way round, keeping its first node.
inline void ReverseFace(std::array<NodeId, 4>& nodes, int size) {
  std::swap(nodes[1], nodes[size - 1]);
}

}  // namespace getme::surface
