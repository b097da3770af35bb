#include "getme/mesh/mesh_conformity.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_join.h"

namespace getme {
namespace {

std::string Named(const Mesh& mesh, ElementId element) {
  return absl::StrCat(element, " (", TypeName(mesh.type(element)), ")");
}

// The element's node ids, sorted; unused entries stay at the end as the largest id.
std::array<NodeId, 8> SortedNodes(const Mesh& mesh, ElementId element) {
  std::array<NodeId, 8> sorted;
  sorted.fill(std::numeric_limits<NodeId>::max());
  const std::span<const NodeId> nodes = mesh.element_nodes(element);
  std::copy(nodes.begin(), nodes.end(), sorted.begin());
  // Insertion sort of ≤ 8 ids (std::sort here trips a GCC 12 -Warray-bounds false positive).
  for (std::size_t k = 1; k < nodes.size(); ++k) {
    for (std::size_t j = k; j > 0 && sorted[j - 1] > sorted[j]; --j)
      std::swap(sorted[j - 1], sorted[j]);
  }
  return sorted;
}

// A node id spread over 64 bits (a multiplicative hash, then a shift-xor).
std::uint64_t MixedId(NodeId node) {
  const std::uint64_t mixed = (static_cast<std::uint64_t>(node) + 1) * 0x9E3779B97F4A7C15ull;
  return mixed ^ (mixed >> 31);
}

// Whether two elements of one type have the same nodes. Each element gets a 64-bit key, the sum
// of its nodes' mixed ids plus its type (the same for any order of its nodes); elements are grouped
// by their key's top bits with a counting sort, about two a group, and only elements of one group
// with equal keys are compared. The search by each element's smallest node below reads every
// element around it, scattered over the mesh (8.5 ms of cub_wedge_like.vtk's 112k tetrahedra,
// 2026-11-29), so it runs only when this finds a repeat, to name the first one. (The plain sum of
// the ids would not do here: on a mesh numbered in space, elements nearby have nearly the same
// sums, and many share one.)
bool HasRepeatedElements(const Mesh& mesh) {
  const std::int64_t count = mesh.element_count();
  std::vector<std::uint64_t> key(static_cast<std::size_t>(count));
  for (ElementId element = 0; element < count; ++element) {
    std::uint64_t sum = TypeIndex(mesh.type(element));
    for (const NodeId node : mesh.element_nodes(element)) sum += MixedId(node);
    key[element] = sum;
  }
  int bits = 0;
  while (bits < 31 && (std::int64_t{2} << bits) < count) ++bits;
  const auto group_of = [&](ElementId element) -> std::size_t {
    return bits == 0 ? 0 : static_cast<std::size_t>(key[element] >> (64 - bits));
  };
  const std::size_t groups = std::size_t{1} << bits;
  std::vector<std::int32_t> start(groups + 1, 0);
  for (ElementId element = 0; element < count; ++element) ++start[group_of(element) + 1];
  for (std::size_t group = 0; group < groups; ++group) start[group + 1] += start[group];
  std::vector<ElementId> grouped(static_cast<std::size_t>(count));
  std::vector<std::int32_t> cursor(start.begin(), start.end() - 1);
  for (ElementId element = 0; element < count; ++element) {
    grouped[cursor[group_of(element)]++] = element;
  }
  for (std::size_t group = 0; group < groups; ++group) {
    for (std::int32_t i = start[group] + 1; i < start[group + 1]; ++i) {
      for (std::int32_t j = start[group]; j < i; ++j) {
        const ElementId a = grouped[i];
        const ElementId b = grouped[j];
        if (key[a] == key[b] && mesh.type(a) == mesh.type(b) &&
            SortedNodes(mesh, a) == SortedNodes(mesh, b)) {
          return true;
        }
      }
    }
  }
  return false;
}

}  // namespace

absl::Status CheckNoRepeatedElements(const Mesh& mesh) {
  if (!HasRepeatedElements(mesh)) return absl::OkStatus();
  // A repeat shares every node with the original, so it is among the elements of the original's
  // smallest node: no table of all elements' node sets is needed. The sum of an element's node
  // ids is the same for any order of its nodes, so comparing sums first leaves the sorting to the
  // rare candidates that could be repeats (sorting every neighbour of every element cost a
  // quarter of reading a 112k-tetrahedron file).
  std::vector<std::int64_t> node_sum(static_cast<std::size_t>(mesh.element_count()));
  for (ElementId element = 0; element < mesh.element_count(); ++element) {
    std::int64_t sum = 0;
    for (const NodeId node : mesh.element_nodes(element)) sum += node;
    node_sum[element] = sum;
  }
  for (ElementId element = 0; element < mesh.element_count(); ++element) {
    const std::span<const NodeId> element_nodes = mesh.element_nodes(element);
    const NodeId smallest = *std::min_element(element_nodes.begin(), element_nodes.end());
    for (const ElementId other : mesh.node_elements(smallest)) {
      if (other >= element || mesh.type(other) != mesh.type(element)) continue;
      if (node_sum[other] != node_sum[element]) continue;
      if (SortedNodes(mesh, other) == SortedNodes(mesh, element)) {
        return absl::InvalidArgumentError(
            absl::StrCat("element ", Named(mesh, element), " repeats element ", other,
                         ": both use the nodes {", absl::StrJoin(mesh.element_nodes(other), ", "),
                         "}; a mesh lists each element once (remove the duplicate)"));
      }
    }
  }
  return absl::OkStatus();
}

absl::Status NonManifoldFaceError(const Mesh& mesh, std::span<const NodeId> face_nodes,
                                  std::int64_t element_uses) {
  std::vector<std::string> sharing;
  for (const ElementId element : mesh.node_elements(face_nodes[0])) {
    const std::span<const NodeId> nodes = mesh.element_nodes(element);
    const bool has_face = std::all_of(face_nodes.begin(), face_nodes.end(), [&](NodeId node) {
      return std::find(nodes.begin(), nodes.end(), node) != nodes.end();
    });
    if (has_face) sharing.push_back(Named(mesh, element));
  }
  std::sort(sharing.begin(), sharing.end());
  return absl::InvalidArgumentError(absl::StrCat(
      "the face with nodes {", absl::StrJoin(face_nodes, ", "), "} belongs to ", element_uses,
      " elements (", absl::StrJoin(sharing, ", "),
      "); in a volume mesh a face belongs to one element (boundary) or two: the elements overlap"));
}

}  // namespace getme
