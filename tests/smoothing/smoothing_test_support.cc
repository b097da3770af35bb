#include "smoothing_test_support.h"

#include <gtest/gtest.h>

#include "formats/grid_mesh.h"
#include "formats/vtk_reader.h"
#include "getme/elements/element_quality.h"
#include "getme/mesh/mesh_quality.h"
#include "getme/meshgen/distorted_hex_block.h"
#include "getme/meshgen/hybrid_block.h"
#include "getme/parallel/thread_pool.h"

namespace getme::testing {

Mesh LoadSharedMesh(const std::string& name) {
  const std::string path = std::string(GETME_SHARED_MESHES) + "/mesquite/" + name;
  auto file = formats::ReadVtkFile(path);
  EXPECT_TRUE(file.ok()) << file.status();
  auto converted = formats::GridToMesh(*file);
  EXPECT_TRUE(converted.ok()) << converted.status();
  return std::move(converted->mesh);
}

CoordinateSnapshot::CoordinateSnapshot(const Mesh& mesh)
    : x(mesh.x().begin(), mesh.x().end()),
      y(mesh.y().begin(), mesh.y().end()),
      z(mesh.z().begin(), mesh.z().end()) {}

std::vector<NodeId> ImmovableNodes(const Mesh& mesh, const SmoothingParams& params) {
  std::vector<NodeId> nodes;
  for (NodeId i = 0; i < mesh.node_count(); ++i) {
    if (mesh.is_fixed(i) || (params.fix_boundary && mesh.is_boundary(i))) nodes.push_back(i);
  }
  return nodes;
}

std::int64_t CountInvalid(const Mesh& mesh) {
  std::int64_t invalid = 0;
  for (ElementId e = 0; e < mesh.element_count(); ++e) {
    const NodeId* ids = mesh.element_nodes(e).data();
    const bool valid = DispatchElementType(mesh.type(e), [&]<ElementType kType>() {
      return IsValid<kType>(GatherNodes<kType>(mesh, ids));
    });
    if (!valid) ++invalid;
  }
  return invalid;
}

std::vector<ThreadCountRun> SmoothAtThreadCounts(
    const std::function<absl::StatusOr<Mesh>()>& make_mesh, SmoothingParams params,
    std::initializer_list<int> thread_counts) {
  std::vector<ThreadCountRun> runs;
  for (const int threads : thread_counts) {
    absl::StatusOr<Mesh> mesh = make_mesh();
    if (!mesh.ok()) {
      ADD_FAILURE() << mesh.status();
      break;
    }
    params.threads = threads;
    absl::StatusOr<SmoothingResult> result = Smooth(*mesh, params);
    if (!result.ok()) {
      ADD_FAILURE() << "threads " << threads << ": " << result.status();
      break;
    }
    runs.push_back({CoordinateSnapshot(*mesh), *std::move(result)});
  }
  return runs;
}

void ExpectSameForEveryThreadCount(const std::vector<ThreadCountRun>& runs,
                                   std::initializer_list<int> thread_counts) {
  ASSERT_EQ(runs.size(), thread_counts.size());
  std::size_t i = 0;
  for (const int threads : thread_counts) {
    const ThreadCountRun& run = runs[i++];
    EXPECT_EQ(run.result.threads, threads);
    EXPECT_TRUE(run.coordinates == runs[0].coordinates)
        << "threads " << threads << " differ from " << *thread_counts.begin() << " thread(s)";
    EXPECT_EQ(run.result.after.q_mean, runs[0].result.after.q_mean);
    EXPECT_EQ(run.result.after.q_min, runs[0].result.after.q_min);
  }
}

void ExpectUnmoved(const CoordinateSnapshot& before, const Mesh& mesh,
                   const std::vector<NodeId>& nodes) {
  const CoordinateSnapshot after(mesh);
  for (NodeId node : nodes) {
    ASSERT_EQ(after.x[node], before.x[node]) << "node " << node << " moved";
    ASSERT_EQ(after.y[node], before.y[node]) << "node " << node << " moved";
    ASSERT_EQ(after.z[node], before.z[node]) << "node " << node << " moved";
  }
}

std::vector<NamedMesh> DistortedBlocks(int n, std::initializer_list<std::uint64_t> seeds) {
  std::vector<NamedMesh> meshes;
  for (std::uint64_t seed : seeds) {
    meshes.push_back({"hybrid_" + std::to_string(seed),
                      [n, seed] { return meshgen::HybridBlock(n, n, n - 1, 0.35, seed); }});
    meshes.push_back({"distorted_hex_" + std::to_string(seed),
                      [n, seed] { return meshgen::DistortedHexBlock(n, n, n, 0.35, seed); }});
  }
  return meshes;
}

void FixSomeInteriorNodes(Mesh& mesh) {
  for (NodeId node = 0; node < mesh.node_count(); node += 7) mesh.set_fixed(node, true);
}

double PinElementOfQualityAtLeast(Mesh& mesh, double at_least) {
  ThreadPool pool(1);
  const std::vector<double> quality = ComputeElementQualities(mesh, pool);
  ElementId pinned = -1;
  for (ElementId e = 0; e < mesh.element_count(); ++e) {
    if (quality[e] >= at_least && (pinned < 0 || quality[e] < quality[pinned])) pinned = e;
  }
  EXPECT_GE(pinned, 0) << "no element of quality at least " << at_least;
  if (pinned < 0) return -1.0;
  for (NodeId node : mesh.element_nodes(pinned)) mesh.set_fixed(node, true);
  return quality[pinned];
}

}  // namespace getme::testing
