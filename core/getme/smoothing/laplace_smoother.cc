#include "getme/smoothing/laplace_smoother.h"

#include <cmath>
#include <vector>

#include "getme/mesh/node_neighbours.h"

namespace getme {
namespace {

constexpr std::int64_t kLaplaceNodeGrain = 4096;

struct Point {
  double x, y, z;
};

Point NeighbourMean(const Mesh& mesh, const CompressedRows& neighbours, NodeId node) {
  Point sum{0.0, 0.0, 0.0};
  const auto row = neighbours.Row(node);
  for (NodeId other : row) {
    sum.x += mesh.x()[other];
    sum.y += mesh.y()[other];
    sum.z += mesh.z()[other];
  }
  const double n = static_cast<double>(row.size());
  return {sum.x / n, sum.y / n, sum.z / n};
}

}  // namespace

absl::StatusOr<PhaseSummary> RunLaplace(SmoothingContext& context) {
  Mesh& mesh = context.mesh;
  const double phase_start = context.ElapsedSeconds();
  const CompressedRows neighbours = BuildEdgeNeighbours(mesh);
  std::vector<double> next_x(mesh.node_count()), next_y(mesh.node_count()),
      next_z(mesh.node_count());
  SmoothingContext::Summary current = context.Summarize();
  PhaseSummary summary{Phase::kLaplace, 0, 0.0, current.q_min, current.q_mean, 0};
  bool cancelled = false;
  for (std::int64_t iteration = 1; iteration <= context.params.laplace_max_iterations;
       ++iteration) {
    if (context.Cancelled()) {
      cancelled = true;
      break;
    }
    context.pool.ParallelFor(
        mesh.node_count(), kLaplaceNodeGrain, [&](std::int64_t begin, std::int64_t end) {
          for (std::int64_t node = begin; node < end; ++node) {
            Point p{mesh.x()[node], mesh.y()[node], mesh.z()[node]};
            if (context.movable[node] && neighbours.Row(node).size() > 0) {
              const auto id = static_cast<NodeId>(node);
              const Point mean = NeighbourMean(mesh, neighbours, id);
              const Vec3 placed =
                  context.Placed(id, Vec3(mean.x, mean.y, mean.z), Vec3(p.x, p.y, p.z));
              p = {placed[0], placed[1], placed[2]};
            }
            next_x[node] = p.x;
            next_y[node] = p.y;
            next_z[node] = p.z;
          }
        });
    std::copy(next_x.begin(), next_x.end(), mesh.x().begin());
    std::copy(next_y.begin(), next_y.end(), mesh.y().begin());
    std::copy(next_z.begin(), next_z.end(), mesh.z().begin());
    context.RefreshQuality();
    const double previous_q_mean = current.q_mean;
    current = context.Summarize();
    summary.iterations = iteration;
    context.Report({Phase::kLaplace, iteration, current.q_min, current.q_mean, current.invalid, 0,
                    context.ElapsedSeconds(), false});
    if (std::abs(current.q_mean - previous_q_mean) < context.params.laplace_tolerance) break;
  }
  context.FinishPhase(summary, current, phase_start);
  if (cancelled) return absl::CancelledError("smoothing cancelled during Laplacian smoothing");
  return summary;
}

absl::StatusOr<PhaseSummary> RunSmartLaplace(SmoothingContext& context) {
  Mesh& mesh = context.mesh;
  const double phase_start = context.ElapsedSeconds();
  const CompressedRows neighbours = BuildEdgeNeighbours(mesh);
  auto x = mesh.x();
  auto y = mesh.y();
  auto z = mesh.z();
  std::vector<double> candidate_quality;
  SmoothingContext::Summary current = context.Summarize();
  PhaseSummary summary{Phase::kSmartLaplace, 0, 0.0, current.q_min, current.q_mean, 0};
  bool cancelled = false;
  for (std::int64_t sweep = 1; sweep <= context.params.laplace_max_iterations; ++sweep) {
    if (context.Cancelled()) {
      cancelled = true;
      break;
    }
    std::int64_t rejected = 0;
    for (std::int64_t i = 0; i < mesh.node_count(); ++i) {
      const auto node = static_cast<NodeId>(i);
      if (!context.movable[node] || neighbours.Row(node).empty()) continue;
      const auto elements = mesh.node_elements(node);
      double old_sum = 0.0;
      for (ElementId e : elements) old_sum += context.quality[e];
      const Point old_position{x[node], y[node], z[node]};
      const Point mean = NeighbourMean(mesh, neighbours, node);
      const Vec3 target = context.Placed(node, Vec3(mean.x, mean.y, mean.z),
                                         Vec3(old_position.x, old_position.y, old_position.z));
      x[node] = target[0];
      y[node] = target[1];
      z[node] = target[2];
      candidate_quality.clear();
      double new_sum = 0.0;
      bool valid = true;
      for (ElementId e : elements) {
        const double q = ElementQualityOrInvalid(mesh, e);
        if (q < 0.0) {
          valid = false;
          break;
        }
        candidate_quality.push_back(q);
        new_sum += q;
      }
      if (valid && new_sum > old_sum) {
        for (std::size_t k = 0; k < elements.size(); ++k) {
          context.quality[elements[k]] = candidate_quality[k];
        }
      } else {
        x[node] = old_position.x;
        y[node] = old_position.y;
        z[node] = old_position.z;
        ++rejected;
      }
    }
    const double previous_q_mean = current.q_mean;
    current = context.Summarize();
    summary.iterations = sweep;
    summary.reverted_nodes += rejected;
    context.Report({Phase::kSmartLaplace, sweep, current.q_min, current.q_mean, current.invalid,
                    rejected, context.ElapsedSeconds(), false});
    if (std::abs(current.q_mean - previous_q_mean) < context.params.laplace_tolerance) break;
  }
  context.FinishPhase(summary, current, phase_start);
  if (cancelled)
    return absl::CancelledError("smoothing cancelled during smart Laplacian smoothing");
  return summary;
}

}  // namespace getme
