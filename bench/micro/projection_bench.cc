// The sliding boundary's nearest-point queries (issue 15, surface/getme_surface/
// surface_projector.h): nanoseconds per projection of a moved boundary node back onto its
// surface or feature curve, through CGAL's AABB trees, with the search started from the node's
// position before the move (what the smoothers do) and without (a k-d tree search for a start
// first). The mesh is the distorted hybrid block of the other benchmarks at 100k elements: six
// planar faces of many triangles and quads, twelve feature curves. Moves are random, up to a
// fifth of a cell in each axis, so a projection lands near where the node was.

#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "bench_meshes.h"
#include "getme_surface/surface_slide.h"

namespace getme::bench {
namespace {

struct Moves {
  std::vector<NodeId> nodes;
  std::vector<Vec3> from;
  std::vector<Vec3> to;
};

Moves RandomMoves(const Mesh& mesh, const surface::SurfaceSlide& slide) {
  Moves moves;
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> offset(-0.2, 0.2);
  for (NodeId node = 0; node < mesh.node_count(); ++node) {
    if (!mesh.is_boundary(node) || !slide.Slides(node)) continue;
    const Vec3 p(mesh.x()[node], mesh.y()[node], mesh.z()[node]);
    moves.nodes.push_back(node);
    moves.from.push_back(p);
    moves.to.push_back(p + Vec3(offset(random), offset(random), offset(random)));
  }
  return moves;
}

void BM_Projection(benchmark::State& state) {
  const bool from_last = state.range(0) != 0;
  const Mesh& mesh = HybridMeshNear(100'000);
  absl::StatusOr<std::unique_ptr<surface::SurfaceSlide>> slide = surface::SurfaceSlide::Build(mesh);
  if (!slide.ok()) {
    state.SkipWithError(std::string(slide.status().message()).c_str());
    return;
  }
  const Moves moves = RandomMoves(mesh, **slide);
  for (auto _ : state) {
    for (std::size_t i = 0; i < moves.nodes.size(); ++i) {
      const Vec3 placed =
          (*slide)->Project(moves.nodes[i], moves.to[i], from_last ? &moves.from[i] : nullptr);
      benchmark::DoNotOptimize(placed);
    }
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(moves.nodes.size()));
  // Inverted rate of n·1e-9 per iteration: seconds per projection, in nanoseconds.
  state.counters["ns_per_projection"] = benchmark::Counter(
      static_cast<double>(moves.nodes.size()) * 1e-9,
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  state.SetLabel(from_last ? "from the node's last position" : "k-d tree start");
}

BENCHMARK(BM_Projection)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace getme::bench
