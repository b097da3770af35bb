#include "getme/meshgen/artery.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <utility>
#include <vector>

#include "mesh_checks.h"

namespace getme::meshgen {
namespace {

using ::getme::NodePosition;
using ::getme::testing::CensusFaces;
using ::getme::testing::InvalidElements;

// The test-sized artery of docs/thin-layers.md: `getme-meshgen artery OUT --mesh-size 0.5`.
ArteryOptions SmallArtery() {
  ArteryOptions options;
  options.mesh_size = 0.5;
  return options;
}

std::vector<NodeId> Sorted(std::vector<NodeId> nodes) {
  std::sort(nodes.begin(), nodes.end());
  return nodes;
}

std::vector<NodeId> PrismTriangle(std::span<const NodeId> nodes, int first) {
  return Sorted({nodes[first], nodes[first + 1], nodes[first + 2]});
}

// The prism stacks of a mesh whose prisms are layers over a wall: each stack starts at a prism
// whose bottom is a tetrahedron face and climbs through prisms whose bottom is the previous top.
std::vector<std::vector<ElementId>> PrismStacks(const Mesh& mesh) {
  std::set<std::vector<NodeId>> tet_faces;
  std::map<std::vector<NodeId>, ElementId> prism_by_bottom;
  std::vector<ElementId> prisms;
  for (ElementId e = 0; e < mesh.element_count(); ++e) {
    const auto n = mesh.element_nodes(e);
    if (mesh.type(e) == ElementType::kTetrahedron) {
      for (const auto& f :
           std::vector<std::array<int, 3>>{{0, 1, 2}, {0, 1, 3}, {1, 2, 3}, {0, 2, 3}}) {
        tet_faces.insert(Sorted({n[f[0]], n[f[1]], n[f[2]]}));
      }
    } else if (mesh.type(e) == ElementType::kPrism) {
      prism_by_bottom[PrismTriangle(n, 0)] = e;
      prisms.push_back(e);
    }
  }
  std::vector<std::vector<ElementId>> stacks;
  for (const ElementId prism : prisms) {
    if (!tet_faces.contains(PrismTriangle(mesh.element_nodes(prism), 0))) continue;
    std::vector<ElementId> stack = {prism};
    while (true) {
      const auto next = prism_by_bottom.find(PrismTriangle(mesh.element_nodes(stack.back()), 3));
      if (next == prism_by_bottom.end() || stack.size() > 100) break;
      stack.push_back(next->second);
    }
    stacks.push_back(std::move(stack));
  }
  return stacks;
}

// Length of vertical edge k (node k to node k + 3) of a prism.
double VerticalEdge(const Mesh& mesh, ElementId prism, int k) {
  const auto n = mesh.element_nodes(prism);
  return (NodePosition(mesh, n[k + 3]) - NodePosition(mesh, n[k])).norm();
}

// Connected groups of faces (sharing an edge), from their sorted node lists.
int ConnectedComponents(const std::vector<std::vector<NodeId>>& faces) {
  std::vector<int> parent(faces.size());
  for (std::size_t i = 0; i < faces.size(); ++i) parent[i] = static_cast<int>(i);
  const auto find = [&](int i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  std::map<std::pair<NodeId, NodeId>, int> owner;
  for (std::size_t i = 0; i < faces.size(); ++i) {
    const auto& f = faces[i];
    for (std::size_t k = 0; k < f.size(); ++k) {
      for (std::size_t l = k + 1; l < f.size(); ++l) {
        const auto [it, inserted] = owner.try_emplace(std::minmax(f[k], f[l]), static_cast<int>(i));
        if (!inserted) parent[find(static_cast<int>(i))] = find(it->second);
      }
    }
  }
  std::set<int> roots;
  for (std::size_t i = 0; i < faces.size(); ++i) roots.insert(find(static_cast<int>(i)));
  return static_cast<int>(roots.size());
}

// Connected pieces of a graph given by its edges.
int EdgeGraphComponents(const std::vector<std::pair<NodeId, NodeId>>& edges) {
  std::map<NodeId, NodeId> parent;
  const auto find = [&](NodeId n) {
    while (parent.at(n) != n) n = parent[n] = parent[parent[n]];
    return n;
  };
  for (const auto& [a, b] : edges) {
    parent.try_emplace(a, a);
    parent.try_emplace(b, b);
  }
  for (const auto& [a, b] : edges) parent[find(a)] = find(b);
  std::set<NodeId> roots;
  for (const auto& [node, up] : parent) roots.insert(find(node));
  return static_cast<int>(roots.size());
}

class ArteryTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    absl::StatusOr<ArteryMesh> generated = GenerateArtery(SmallArtery());
    ASSERT_TRUE(generated.ok()) << generated.status();
    artery_ = new ArteryMesh(*std::move(generated));
  }
  static void TearDownTestSuite() {
    delete artery_;
    artery_ = nullptr;
  }
  static const ArteryMesh* artery_;
};
const ArteryMesh* ArteryTest::artery_ = nullptr;

TEST_F(ArteryTest, TetrahedraAndEightPrismLayersUnderTenThousandElements) {
  const Mesh& mesh = artery_->mesh;
  const std::int64_t tets = mesh.element_count(ElementType::kTetrahedron);
  const std::int64_t prisms = mesh.element_count(ElementType::kPrism);
  EXPECT_GT(tets, 1000);
  EXPECT_EQ(mesh.element_count(ElementType::kHexahedron), 0);
  EXPECT_EQ(mesh.element_count(ElementType::kPyramid), 0);
  EXPECT_EQ(prisms % 8, 0) << "6 inward + 2 outward layers over the same wall triangles";
  EXPECT_LT(mesh.element_count(), 10000);
  EXPECT_GT(mesh.element_count(), 5000);
}

TEST_F(ArteryTest, EveryElementIsValidFacesConformAndNoNodeIsFixed) {
  const Mesh& mesh = artery_->mesh;
  EXPECT_TRUE(InvalidElements(mesh).empty());
  for (const auto& [key, use] : CensusFaces(mesh)) {
    ASSERT_LE(use.elements.size(), 2u) << "face shared by " << use.elements.size();
  }
  for (NodeId node = 0; node < mesh.node_count(); ++node) {
    ASSERT_FALSE(mesh.is_fixed(node)) << "node " << node;
  }
}

// Measured from the prisms: every stack is 6 + 2 prisms high; along each vertical edge the
// layers grow by the growth ratio away from the wall on both sides; the two layers touching the
// wall are at most first_layer_ratio × (mean wall edge) thick, and exactly that where no stack
// had to be thinned.
TEST_F(ArteryTest, LayersHaveTheRequestedCountGrowthAndFirstHeight) {
  const ArteryOptions options = SmallArtery();
  const Mesh& mesh = artery_->mesh;
  const std::vector<std::vector<ElementId>> stacks = PrismStacks(mesh);
  ASSERT_EQ(static_cast<std::int64_t>(stacks.size()) * 8, mesh.element_count(ElementType::kPrism));
  const int inward = options.inward_layers;

  // The wall is the top of each stack's inward part: its mean edge length gives the first
  // layer height.
  std::set<std::pair<NodeId, NodeId>> wall_edges;
  for (const auto& stack : stacks) {
    ASSERT_EQ(stack.size(), 8u);
    const auto n = mesh.element_nodes(stack[inward - 1]);
    for (int k = 0; k < 3; ++k) wall_edges.insert(std::minmax(n[3 + k], n[3 + (k + 1) % 3]));
  }
  double total = 0.0;
  for (const auto& [a, b] : wall_edges) {
    total += (NodePosition(mesh, a) - NodePosition(mesh, b)).norm();
  }
  const double first = options.first_layer_ratio * total / static_cast<double>(wall_edges.size());
  EXPECT_NEAR(first, artery_->first_layer_height, 1e-12);

  const double g = options.growth_ratio;
  std::int64_t full_height_edges = 0, edges = 0;
  for (const auto& stack : stacks) {
    for (int k = 0; k < 3; ++k) {
      ++edges;
      const double inner_first = VerticalEdge(mesh, stack[inward - 1], k);
      const double outer_first = VerticalEdge(mesh, stack[inward], k);
      ASSERT_LE(inner_first, first * (1.0 + 1e-9));
      ASSERT_LE(outer_first, first * (1.0 + 1e-9));
      ASSERT_GT(inner_first, 0.0);
      if (std::abs(inner_first - first) < 1e-9 * first &&
          std::abs(outer_first - first) < 1e-9 * first) {
        ++full_height_edges;
      }
      for (int l = 0; l + 1 < inward; ++l) {  // inward: thicker towards the core
        ASSERT_NEAR(VerticalEdge(mesh, stack[l], k) / VerticalEdge(mesh, stack[l + 1], k), g, 1e-6)
            << "inward layer " << l;
      }
      for (std::size_t l = inward; l + 1 < stack.size(); ++l) {  // outward: thicker outward
        ASSERT_NEAR(VerticalEdge(mesh, stack[l + 1], k) / VerticalEdge(mesh, stack[l], k), g, 1e-6)
            << "outward layer " << l;
      }
    }
  }
  RecordProperty("full_height_fraction",
                 std::to_string(static_cast<double>(full_height_edges) / edges));
  EXPECT_GE(full_height_edges, 0.95 * edges);
  EXPECT_LE(artery_->layers.thinned_inward + artery_->layers.thinned_outward,
            artery_->layers.wall_vertices / 10);
}

// The boundary is the outer wall (tops of the outermost prisms) and the planar caps: inlet,
// outlet and one per branch. Each cap is one connected patch (tetrahedron triangles plus the
// layers' side quads) in its plane, with a single rim loop.
TEST_F(ArteryTest, BoundaryIsTheOuterWallAndOneCapPerOpening) {
  const ArteryOptions options = SmallArtery();
  const Mesh& mesh = artery_->mesh;
  std::set<std::vector<NodeId>> outer_tops;
  for (const auto& stack : PrismStacks(mesh)) {
    outer_tops.insert(PrismTriangle(mesh.element_nodes(stack.back()), 3));
  }
  const std::vector<CapPlane>& caps = artery_->caps;
  ASSERT_EQ(caps.size(), 2u + options.branches);
  std::vector<std::vector<std::vector<NodeId>>> cap_faces(caps.size());
  std::int64_t outer = 0, other = 0, cap_quads = 0;
  for (const auto& [key, use] : CensusFaces(mesh)) {
    if (use.elements.size() != 1) continue;
    if (outer_tops.contains(key)) {
      ++outer;
      continue;
    }
    int on_cap = -1;
    for (std::size_t c = 0; c < caps.size(); ++c) {
      const bool in_plane = std::all_of(key.begin(), key.end(), [&](NodeId n) {
        return std::abs((NodePosition(mesh, n) - caps[c].centre).dot(caps[c].normal)) < 1e-9 &&
               (NodePosition(mesh, n) - caps[c].centre).norm() < 1.5 * caps[c].radius;
      });
      if (in_plane) on_cap = static_cast<int>(c);
    }
    if (on_cap < 0) {
      ++other;
      continue;
    }
    cap_quads += key.size() == 4;
    cap_faces[on_cap].push_back(key);
  }
  EXPECT_EQ(outer, static_cast<std::int64_t>(outer_tops.size()));
  EXPECT_EQ(other, 0);
  EXPECT_GT(cap_quads, 0) << "the layers' side faces lie on the caps";
  for (std::size_t c = 0; c < caps.size(); ++c) {
    ASSERT_FALSE(cap_faces[c].empty()) << "cap " << c;
    EXPECT_EQ(ConnectedComponents(cap_faces[c]), 1) << "cap " << c;
    // One rim loop: the cap's edges used by exactly one of its faces form one connected cycle.
    std::map<std::pair<NodeId, NodeId>, int> uses;
    // Faces' sorted node lists lose the cyclic order, so take the edges from the elements.
    for (const auto& [key, use] : CensusFaces(mesh)) {
      if (use.elements.size() != 1 ||
          std::find(cap_faces[c].begin(), cap_faces[c].end(), key) == cap_faces[c].end()) {
        continue;
      }
      for (std::size_t k = 0; k < use.nodes.size(); ++k) {
        ++uses[std::minmax(use.nodes[k], use.nodes[(k + 1) % use.nodes.size()])];
      }
    }
    std::vector<std::pair<NodeId, NodeId>> rim;
    std::map<NodeId, int> degree;
    for (const auto& [edge, count] : uses) {
      if (count != 1) continue;
      rim.push_back(edge);
      ++degree[edge.first];
      ++degree[edge.second];
    }
    ASSERT_FALSE(rim.empty());
    EXPECT_EQ(EdgeGraphComponents(rim), 1) << "cap " << c << ": one rim loop";
    for (const auto& [node, d] : degree) EXPECT_EQ(d, 2) << "cap " << c << " rim node " << node;
  }
  RecordProperty("openings", std::to_string(caps.size()));
}

TEST(ArteryDeterminismTest, SameOptionsGiveBitIdenticalMeshes) {
  ArteryOptions options;
  options.mesh_size = 0.6;
  options.branches = 1;
  absl::StatusOr<Mesh> a = Artery(options);
  absl::StatusOr<Mesh> b = Artery(options);
  ASSERT_TRUE(a.ok() && b.ok());
  ASSERT_EQ(a->node_count(), b->node_count());
  ASSERT_EQ(a->element_count(), b->element_count());
  EXPECT_TRUE(std::ranges::equal(a->x(), b->x()));
  EXPECT_TRUE(std::ranges::equal(a->y(), b->y()));
  EXPECT_TRUE(std::ranges::equal(a->z(), b->z()));
  for (ElementId e = 0; e < a->element_count(); ++e) {
    ASSERT_EQ(a->type(e), b->type(e));
    ASSERT_TRUE(std::ranges::equal(a->element_nodes(e), b->element_nodes(e))) << e;
  }
}

// Other shapes the options reach: no, one and three branches, a straight centre line, inward
// layers only (the usual CFD mesh), a steeper growth and thinner first layer, sharp junctions.
TEST(ArteryVariantsTest, EveryVariantIsValidWithOneCapPerOpening) {
  struct Variant {
    int branches;
    double helix_radius;
    int inward, outward;
    double first, growth, fillet;
  };
  for (const Variant& v :
       {Variant{0, 2.0, 6, 2, 0.005, 1.2, 0.25}, Variant{1, 2.0, 4, 0, 0.005, 1.2, 0.25},
        Variant{3, 2.0, 8, 1, 0.002, 1.3, 0.25}, Variant{2, 0.0, 6, 2, 0.005, 1.2, 0.25},
        Variant{2, 2.0, 6, 2, 0.005, 1.2, 0.0}, Variant{3, 2.0, 6, 0, 0.005, 1.2, 0.0}}) {
    ArteryOptions options;
    options.mesh_size = 0.6;
    options.branches = v.branches;
    options.helix_radius = v.helix_radius;
    options.inward_layers = v.inward;
    options.outward_layers = v.outward;
    options.first_layer_ratio = v.first;
    options.growth_ratio = v.growth;
    options.junction_fillet = v.fillet;
    absl::StatusOr<ArteryMesh> artery = GenerateArtery(options);
    ASSERT_TRUE(artery.ok()) << artery.status();
    const Mesh& mesh = artery->mesh;
    EXPECT_TRUE(InvalidElements(mesh).empty()) << v.branches << " branches";
    const std::vector<std::vector<ElementId>> stacks = PrismStacks(mesh);
    ASSERT_FALSE(stacks.empty());
    for (const auto& stack : stacks) {
      ASSERT_EQ(static_cast<int>(stack.size()), v.inward + v.outward);
    }
    // Boundary faces off the outer wall, grouped by connectivity: one group per opening.
    std::set<std::vector<NodeId>> outer_tops;
    for (const auto& stack : stacks) {
      outer_tops.insert(PrismTriangle(mesh.element_nodes(stack.back()), 3));
    }
    std::vector<std::vector<NodeId>> openings;
    for (const auto& [key, use] : CensusFaces(mesh)) {
      if (use.elements.size() == 1 && !outer_tops.contains(key)) openings.push_back(key);
    }
    EXPECT_EQ(ConnectedComponents(openings), 2 + v.branches) << v.branches << " branches";
  }
}

// Layers thicker than the tetrahedra can give way to (here ~1.4 wall edges inward) are thinned
// stack by stack; a thinned stack keeps its growth ratio, and every element stays valid.
TEST(ArteryThinningTest, TooThickLayersAreThinnedLocallyAndStayValid) {
  ArteryOptions options;
  options.mesh_size = 0.6;
  options.inward_layers = 10;
  options.outward_layers = 1;
  options.growth_ratio = 1.4;
  options.first_layer_ratio = 0.02;
  absl::StatusOr<ArteryMesh> artery = GenerateArtery(options);
  ASSERT_TRUE(artery.ok()) << artery.status();
  EXPECT_GT(artery->layers.thinned_inward, 0);
  EXPECT_LT(artery->layers.min_inward_scale, 1.0);
  const Mesh& mesh = artery->mesh;
  EXPECT_TRUE(InvalidElements(mesh).empty());
  for (const auto& stack : PrismStacks(mesh)) {
    ASSERT_EQ(stack.size(), 11u);
    for (int k = 0; k < 3; ++k) {
      for (int l = 0; l + 1 < options.inward_layers; ++l) {
        ASSERT_NEAR(VerticalEdge(mesh, stack[l], k) / VerticalEdge(mesh, stack[l + 1], k), 1.4,
                    1e-6);
      }
      ASSERT_LE(VerticalEdge(mesh, stack[options.inward_layers - 1], k),
                artery->first_layer_height * (1.0 + 1e-9));
    }
  }
}

TEST(ArteryOptionsTest, RejectsBadOptions) {
  ArteryOptions options;
  options.branches = 4;
  EXPECT_EQ(Artery(options).status().code(), absl::StatusCode::kInvalidArgument);
  options = {};
  options.growth_ratio = 0.0;
  EXPECT_EQ(Artery(options).status().code(), absl::StatusCode::kInvalidArgument);
  options = {};
  options.radius = 2.0;  // the helix (curvature radius 2.03) would turn tighter than this
  options.length = 1.0;
  EXPECT_EQ(Artery(options).status().code(), absl::StatusCode::kInvalidArgument);
}

}  // namespace
}  // namespace getme::meshgen
