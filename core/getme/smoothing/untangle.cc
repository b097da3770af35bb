#include "getme/smoothing/untangle.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_join.h"
#include "getme/elements/element_quality.h"
#include "getme/elements/transform.h"
#include "getme/elements/vec3.h"
#include "getme/mesh/element_neighbours.h"
#include "getme/mesh/node_neighbours.h"

namespace getme {
namespace {

constexpr int kListedElements = 10;
constexpr std::array<double, 4> kRelaxations = {1.0, 0.5, 0.25, 0.1};

// How tangled a set of elements is: the count of invalid ones, then the sum of their negative
// node-tetrahedron determinants scaled by the element's mean edge length cubed (scale-free).
struct Tangle {
  std::int64_t invalid = 0;
  double inversion = 0.0;

  bool BetterThan(const Tangle& other) const {
    if (invalid != other.invalid) return invalid < other.invalid;
    return inversion < other.inversion * (1.0 - 1e-9);
  }
};

template <ElementType kType>
double Inversion(const ElementNodes<kType>& p) {
  const double length = MeanEdgeLength<kType>(p);
  if (!(length > 0.0)) return 1.0;
  double negative = 0.0;
  for (int k = 0; k < static_cast<int>(ElementTable<kType>::kNodeTets.size()); ++k) {
    negative += std::max(0.0, -NodeTetDeterminant<kType>(p, k)) / (length * length * length);
  }
  return negative;
}

class Untangler {
 public:
  explicit Untangler(SmoothingContext& context)
      : context_(context), mesh_(context.mesh), neighbours_(BuildEdgeNeighbours(mesh_)) {}

  absl::StatusOr<PhaseSummary> Run();

 private:
  Tangle Measure(std::span<const ElementId> elements) const;
  // Mean length of the edges at a node: the scale of moves tried for it.
  double LocalLength(NodeId node) const;
  // Tries the candidate moves for one invalid element; keeps the best if it improves.
  bool Repair(ElementId element);
  std::vector<ElementId> InvalidElements() const;
  absl::Status Unrepairable(const std::vector<ElementId>& invalid, std::string_view why) const;

  SmoothingContext& context_;
  Mesh& mesh_;
  const CompressedRows neighbours_;
  ElementNeighbourFinder neighbour_finder_;
  std::vector<ElementId> region_;
};

Tangle Untangler::Measure(std::span<const ElementId> elements) const {
  Tangle tangle;
  for (ElementId element : elements) {
    const NodeId* ids = mesh_.element_nodes(element).data();
    DispatchElementType(mesh_.type(element), [&]<ElementType kType>() {
      const auto nodes = GatherNodes<kType>(mesh_, ids);
      if (!IsValid<kType>(nodes)) {
        ++tangle.invalid;
        tangle.inversion += Inversion<kType>(nodes);
      }
    });
  }
  return tangle;
}

double Untangler::LocalLength(NodeId node) const {
  const Vec3 p(mesh_.x()[node], mesh_.y()[node], mesh_.z()[node]);
  double sum = 0.0;
  for (NodeId other : neighbours_.Row(node)) {
    sum += (Vec3(mesh_.x()[other], mesh_.y()[other], mesh_.z()[other]) - p).norm();
  }
  return neighbours_.Row(node).empty() ? 0.0
                                       : sum / static_cast<double>(neighbours_.Row(node).size());
}

bool Untangler::Repair(ElementId element) {
  region_.assign(1, element);
  const auto neighbours = neighbour_finder_.Find(mesh_, element);
  region_.insert(region_.end(), neighbours.begin(), neighbours.end());
  const std::span<const NodeId> ids = mesh_.element_nodes(element);
  auto x = mesh_.x();
  auto y = mesh_.y();
  auto z = mesh_.z();

  const int n = static_cast<int>(ids.size());
  std::array<Vec3, kMaxElementNodes> original;
  for (int k = 0; k < n; ++k) original[k] = Vec3(x[ids[k]], y[ids[k]], z[ids[k]]);
  auto place = [&](const std::array<Vec3, kMaxElementNodes>& position, int only_node) {
    for (int k = 0; k < n; ++k) {
      const NodeId node = ids[k];
      if (!context_.movable[node]) continue;
      const Vec3& p = (only_node < 0 || only_node == k) ? position[k] : original[k];
      x[node] = p.x();
      y[node] = p.y();
      z[node] = p.z();
    }
  };

  // Candidates: the whole element transformed with decreasing relaxation, then each free node
  // alone at its transformed position or at the mean of its edge neighbours.
  std::vector<std::pair<std::array<Vec3, kMaxElementNodes>, int>> candidates;
  for (double rho : kRelaxations) {
    std::array<Vec3, kMaxElementNodes> moved;
    DispatchElementType(mesh_.type(element), [&]<ElementType kType>() {
      const auto step =
          RegularizingStep<kType>(GatherNodes<kType>(mesh_, ids.data()),
                                  context_.params.sequential_sigma[TypeIndex(kType)], rho);
      std::copy(step.begin(), step.end(), moved.begin());
    });
    candidates.emplace_back(moved, -1);
    if (rho == 1.0) {
      for (int k = 0; k < n; ++k) {
        if (context_.movable[ids[k]]) candidates.emplace_back(moved, k);
      }
    }
  }
  for (int k = 0; k < n; ++k) {
    if (!context_.movable[ids[k]] || neighbours_.Row(ids[k]).empty()) continue;
    std::array<Vec3, kMaxElementNodes> moved = original;
    Vec3 mean = Vec3::Zero();
    for (NodeId other : neighbours_.Row(ids[k])) mean += Vec3(x[other], y[other], z[other]);
    moved[k] = mean / static_cast<double>(neighbours_.Row(ids[k]).size());
    candidates.emplace_back(moved, k);
  }

  // Steepest descent of the region's inversion for each free node: where the transformed shape
  // does not fit between fixed nodes, a short move that only un-inverts helps.
  for (int k = 0; k < n; ++k) {
    if (!context_.movable[ids[k]]) continue;
    const double length = LocalLength(ids[k]);
    const double h = 1e-6 * length;
    Vec3 gradient;
    for (int axis = 0; axis < 3; ++axis) {
      std::array<Vec3, kMaxElementNodes> probe = original;
      probe[k][axis] += h;
      place(probe, k);
      const double plus = Measure(region_).inversion;
      probe[k][axis] -= 2.0 * h;
      place(probe, k);
      const double minus = Measure(region_).inversion;
      gradient[axis] = (plus - minus) / (2.0 * h);
    }
    place(original, -1);
    const double norm = gradient.norm();
    if (!(norm > 0.0)) continue;
    for (double step = 0.5; step > 1e-3; step *= 0.5) {
      std::array<Vec3, kMaxElementNodes> moved = original;
      moved[k] -= (step * length / norm) * gradient;
      candidates.emplace_back(moved, k);
    }
  }

  const Tangle before = Measure(region_);
  Tangle best = before;
  int best_candidate = -1;
  for (int c = 0; c < static_cast<int>(candidates.size()); ++c) {
    place(candidates[c].first, candidates[c].second);
    const Tangle after = Measure(region_);
    if (after.BetterThan(best)) {
      best = after;
      best_candidate = c;
    }
    place(original, -1);
  }
  if (best_candidate < 0) return false;
  place(candidates[best_candidate].first, candidates[best_candidate].second);
  return true;
}

std::vector<ElementId> Untangler::InvalidElements() const {
  std::vector<ElementId> invalid;  // canonical order, the order repairs are tried in
  for (ElementId e : mesh_.canonical_order()) {
    if (context_.quality[e] < 0.0) invalid.push_back(e);
  }
  return invalid;
}

absl::Status Untangler::Unrepairable(const std::vector<ElementId>& invalid,
                                     std::string_view why) const {
  std::vector<std::string> listed;
  for (std::size_t i = 0; i < invalid.size() && i < kListedElements; ++i) {
    listed.push_back(absl::StrCat(invalid[i], " (", TypeName(mesh_.type(invalid[i])), ")"));
  }
  return absl::FailedPreconditionError(
      absl::StrCat("could not untangle ", invalid.size(), " invalid element",
                   invalid.size() == 1 ? "" : "s", ": ", absl::StrJoin(listed, ", "),
                   invalid.size() > kListedElements ? ", ..." : "", " (", std::string(why), ")"));
}

absl::StatusOr<PhaseSummary> Untangler::Run() {
  const double phase_start = context_.ElapsedSeconds();
  std::vector<ElementId> invalid = InvalidElements();
  PhaseSummary summary{Phase::kUntangle, 0, 0.0, 0.0, 0.0, 0};
  for (std::int64_t pass = 1; !invalid.empty() && pass <= context_.params.untangle_max_iterations;
       ++pass) {
    if (context_.Cancelled()) return absl::CancelledError("smoothing cancelled while untangling");
    std::int64_t repaired = 0;
    for (ElementId element : invalid) {
      if (Repair(element)) ++repaired;
    }
    context_.RefreshQuality();
    invalid = InvalidElements();
    const SmoothingContext::Summary state = context_.Summarize();
    summary.iterations = pass;
    context_.Report({Phase::kUntangle, pass, state.q_min, state.q_mean, state.invalid, 0,
                     context_.ElapsedSeconds(), false});
    if (repaired == 0) break;
  }
  const SmoothingContext::Summary state = context_.Summarize();
  context_.FinishPhase(summary, state, phase_start);
  if (!invalid.empty()) {
    std::sort(invalid.begin(), invalid.end());  // the caller's numbering in the message
    std::vector<ElementId> pinned;
    for (ElementId element : invalid) {
      bool any_movable = false;
      for (NodeId node : mesh_.element_nodes(element)) any_movable |= context_.movable[node] != 0;
      if (!any_movable) pinned.push_back(element);
    }
    if (!pinned.empty()) {
      return Unrepairable(pinned, "all their nodes are fixed or on the boundary");
    }
    return Unrepairable(invalid, absl::StrCat("no move reduced the inversion after ",
                                              summary.iterations, " passes"));
  }
  return summary;
}

}  // namespace

absl::StatusOr<PhaseSummary> RunUntangle(SmoothingContext& context) {
  return Untangler(context).Run();
}

}  // namespace getme
