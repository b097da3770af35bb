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

}  // namespace

absl::Status CheckNoRepeatedElements(const Mesh& mesh) {
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
