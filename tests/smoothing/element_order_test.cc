// The service numbers elements by type (all tetrahedra, then hexahedra, wedges, pyramids), a file
// interleaves them. Both must smooth to bit-identical results: the engine follows the canonical
// order (Mesh::canonical_order) wherever order matters.

#include <gtest/gtest.h>

#include <array>

#include "getme/meshgen/hybrid_block.h"
#include "getme/smoothing/smoother.h"
#include "smoothing_test_support.h"

namespace getme {
namespace {

// The same nodes and elements, elements added in the given order of ids.
Mesh Rebuild(const Mesh& mesh, const std::vector<ElementId>& order) {
  MeshBuilder builder;
  for (NodeId node = 0; node < mesh.node_count(); ++node) {
    builder.AddNode(mesh.x()[node], mesh.y()[node], mesh.z()[node]);
  }
  for (ElementId e : order) {
    const auto nodes = mesh.element_nodes(e);
    const std::vector<std::int64_t> ids(nodes.begin(), nodes.end());
    builder.AddElement(mesh.type(e), ids);
  }
  auto rebuilt = std::move(builder).Build();
  EXPECT_TRUE(rebuilt.ok()) << rebuilt.status();
  return std::move(*rebuilt);
}

std::vector<ElementId> InsertionOrder(const Mesh& mesh) {
  std::vector<ElementId> ids(mesh.element_count());
  for (ElementId e = 0; e < mesh.element_count(); ++e) ids[e] = e;
  return ids;
}

TEST(ElementOrderTest, TypeGroupedAndInterleavedOrdersSmoothIdentically) {
  auto original = meshgen::HybridBlock(8, 8, 6, 0.3, 31);
  ASSERT_TRUE(original.ok()) << original.status();
  // Interleave the types round-robin (a different interleaving from the generator's), keeping
  // each type's own order, as a file and the type-grouped wire message do.
  std::array<std::vector<ElementId>, kElementTypeCount> by_type;
  for (ElementId e : original->canonical_order())
    by_type[TypeIndex(original->type(e))].push_back(e);
  std::vector<ElementId> interleaved;
  for (std::size_t i = 0; interleaved.size() < original->canonical_order().size(); ++i) {
    for (const auto& ids : by_type) {
      if (i < ids.size()) interleaved.push_back(ids[i]);
    }
  }
  const std::vector<ElementId> grouped(original->canonical_order().begin(),
                                       original->canonical_order().end());
  Mesh a = Rebuild(*original, interleaved);
  Mesh b = Rebuild(*original, grouped);
  // The element ids really differ between the two meshes.
  ASSERT_NE(std::vector<ElementId>(a.canonical_order().begin(), a.canonical_order().end()),
            std::vector<ElementId>(b.canonical_order().begin(), b.canonical_order().end()));

  for (Method method : {Method::kGetme, Method::kWarpage, Method::kSmartLaplace}) {
    Mesh smoothed_a = Rebuild(a, InsertionOrder(a));
    Mesh smoothed_b = Rebuild(b, InsertionOrder(b));
    SmoothingParams params;
    params.method = method;
    auto result_a = Smooth(smoothed_a, params);
    auto result_b = Smooth(smoothed_b, params);
    ASSERT_TRUE(result_a.ok() && result_b.ok());
    EXPECT_EQ(result_a->after.q_mean, result_b->after.q_mean) << MethodName(method);
    EXPECT_EQ(result_a->after.q_min, result_b->after.q_min) << MethodName(method);
    EXPECT_EQ(result_a->iterations_sequential, result_b->iterations_sequential);
    EXPECT_TRUE(testing::CoordinateSnapshot(smoothed_a) == testing::CoordinateSnapshot(smoothed_b))
        << MethodName(method);
  }
}

}  // namespace
}  // namespace getme
