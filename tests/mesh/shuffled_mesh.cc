#include "shuffled_mesh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <vector>

namespace getme::mesh_test {

Mesh Shuffled(const Mesh& mesh, std::uint64_t seed) {
  std::mt19937_64 random(seed);
  std::vector<NodeId> new_id(mesh.node_count());
  std::iota(new_id.begin(), new_id.end(), 0);
  std::shuffle(new_id.begin(), new_id.end(), random);
  std::vector<NodeId> old_id(mesh.node_count());
  for (NodeId node = 0; node < mesh.node_count(); ++node) old_id[new_id[node]] = node;
  std::vector<ElementId> elements(mesh.element_count());
  std::iota(elements.begin(), elements.end(), 0);
  std::shuffle(elements.begin(), elements.end(), random);
  MeshBuilder builder;
  for (NodeId node = 0; node < mesh.node_count(); ++node) {
    const NodeId old = old_id[node];
    builder.AddNode(mesh.x()[old], mesh.y()[old], mesh.z()[old]);
    if (mesh.is_fixed(old)) builder.SetFixed(node);
  }
  std::vector<std::int64_t> nodes;
  for (ElementId element : elements) {
    nodes.clear();
    for (NodeId node : mesh.element_nodes(element)) nodes.push_back(new_id[node]);
    builder.AddElement(mesh.type(element), nodes);
  }
  absl::StatusOr<Mesh> shuffled = std::move(builder).Build();
  EXPECT_TRUE(shuffled.ok()) << shuffled.status();
  return shuffled.ok() ? *std::move(shuffled) : mesh;
}

}  // namespace getme::mesh_test
