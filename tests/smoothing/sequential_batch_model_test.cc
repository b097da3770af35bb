// The batched sequential substep (issue 16, item 1) against an independent model of its rules, as
// docs/parallel-sequential.md ("What a batch is") states them. The model shares none of the
// engine's machinery for choosing a batch: no heaps (the selectable elements are sorted afresh
// for every batch), no claim bits, nothing found in parallel, and no list copied from the batch
// before (each candidate's elements are collected afresh from the node→element rows). It runs a
// batch's picks one after the other in batch order. Only the element kernels (the transform of
// Def. 1 with eqs. 8 and 11, the mean ratio of Def. 3 and q_γ of Sec. 4.4) are the engine's,
// tested on their own elsewhere. So a wrong candidate order, band, look-ahead depth, claim,
// blocker, penalty or copied list in the engine shows here as different coordinates, even where it
// is deterministic, which the thread-count tests cannot see.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <vector>

#include "getme/elements/element_quality.h"
#include "getme/elements/transform.h"
#include "getme/elements/vec3.h"
#include "getme/smoothing/sequential_smoother.h"
#include "getme/smoothing/smoother.h"
#include "smoothing_test_support.h"

namespace getme {
namespace {

// What the model's run went through: the test asserts that each rule was exercised.
struct ModelCounts {
  std::int64_t batches = 0;
  std::int64_t picks = 0;
  std::int64_t full_batches = 0;        // as many picks as the limit allows
  std::int64_t dependent = 0;           // candidates turned away by an earlier pick's claim
  std::int64_t blocker_candidates = 0;  // candidates that came as blockers of the batch before
  std::int64_t deep_batches = 0;        // batches that took a candidate past the first 2 × limit
  std::int64_t band_cut_batches = 0;    // batches whose ranked candidates the band cut short
  std::int64_t reverted = 0;            // picks whose step was reverted (Δπ_i)
  std::int64_t repeated = 0;            // picks of an element picked in the batch before (Δπ_r)
  std::int64_t by_warpage = 0;          // picks whose criterion was q_γ's warpage term, not q
  std::int64_t distinct = 0;            // elements picked at least once
};

// The sequential substep with its boundary fixed, batched, stopped by its pick cap or by the
// pinned minimum, handing on its best state (Sec. 3.2 with the changes of
// docs/parallel-sequential.md), selecting by the mean ratio or by q_γ (Sec. 4.4).
class BatchedSequentialModel {
 public:
  BatchedSequentialModel(Mesh& mesh, const SmoothingParams& params,
                         SelectionCriterion criterion = SelectionCriterion::kMeanRatio)
      : mesh_(mesh),
        params_(params),
        criterion_kind_(criterion),
        movable_(mesh.node_count()),
        selectable_(mesh.element_count()),
        quality_(mesh.element_count()),
        criterion_(mesh.element_count()),
        penalty_(mesh.element_count(), 0.0),
        picked_in_batch_(mesh.element_count(), -1) {
    for (NodeId node = 0; node < mesh.node_count(); ++node) {
      movable_[node] = !mesh.is_boundary(node);
    }
    for (ElementId element = 0; element < mesh.element_count(); ++element) {
      for (NodeId node : mesh.element_nodes(element)) selectable_[element] |= movable_[node];
      quality_[element] = QualityOf(element);
      criterion_[element] = CriterionOf(element, quality_[element]);
    }
  }

  std::int64_t Limit() const {
    const std::int64_t limit = std::min(params_.sequential_batch,
                                        mesh_.element_count() / params_.sequential_batch_elements);
    return limit >= std::min<std::int64_t>(16, params_.sequential_batch) ? limit : 1;
  }

  ModelCounts Run() {
    const std::int64_t limit = Limit();
    const std::int64_t cap = params_.sequential_max_iterations;
    double pinned_min = std::numeric_limits<double>::infinity();
    for (ElementId element = 0; element < mesh_.element_count(); ++element) {
      if (!selectable_[element]) pinned_min = std::min(pinned_min, criterion_[element]);
    }
    double best_min = Minimum();
    testing::CoordinateSnapshot best(mesh_);
    std::vector<ElementId> blockers;
    ModelCounts counts;
    for (std::int64_t batch = 1; counts.picks < cap; ++batch) {
      // Candidates: the blockers of the batch before, then the selectable elements in (key,
      // canonical rank) order while their key is within the band above the lowest, at most 4 ×
      // the limit of them.
      std::vector<ElementId> candidates = blockers;
      counts.blocker_candidates += static_cast<std::int64_t>(blockers.size());
      blockers.clear();
      const std::vector<ElementId> ranked = InKeyOrder(static_cast<std::size_t>(4 * limit));
      const double band_end = Key(ranked.front()) + params_.sequential_batch_band;
      for (std::size_t i = 0; i < ranked.size(); ++i) {
        if (static_cast<std::int64_t>(i) == 4 * limit) break;
        if (i > 0 && Key(ranked[i]) > band_end) {
          ++counts.band_cut_batches;
          break;
        }
        candidates.push_back(ranked[i]);
      }
      // Independence: a candidate is taken if none of the elements it evaluates is evaluated by
      // a pick taken before it.
      std::vector<std::uint8_t> claimed(mesh_.element_count(), 0);
      std::vector<ElementId> picks;
      for (std::size_t i = 0; i < candidates.size(); ++i) {
        if (static_cast<std::int64_t>(picks.size()) == limit) break;
        const std::vector<ElementId> affected = Affected(candidates[i]);
        if (std::any_of(affected.begin(), affected.end(),
                        [&](ElementId element) { return claimed[element] != 0; })) {
          ++counts.dependent;
          continue;
        }
        for (ElementId element : affected) claimed[element] = 1;
        picks.push_back(candidates[i]);
        if (i >= static_cast<std::size_t>(2 * limit)) ++counts.deep_batches;
      }
      if (static_cast<std::int64_t>(picks.size()) > cap - counts.picks) {
        picks.resize(cap - counts.picks);
      }
      counts.full_batches += static_cast<std::int64_t>(picks.size()) == limit;
      for (ElementId pick : picks) {
        const ElementId blocker = RunPick(pick, batch, counts);
        if (blocker >= 0) blockers.push_back(blocker);
      }
      ++counts.batches;
      counts.picks += static_cast<std::int64_t>(picks.size());
      if (const double current = Minimum(); current > best_min) {
        best_min = current;
        best = testing::CoordinateSnapshot(mesh_);
      }
      if (best_min >= pinned_min) break;
    }
    std::copy(best.x.begin(), best.x.end(), mesh_.x().begin());
    std::copy(best.y.begin(), best.y.end(), mesh_.y().begin());
    std::copy(best.z.begin(), best.z.end(), mesh_.z().begin());
    return counts;
  }

 private:
  double Key(ElementId element) const { return criterion_[element] + penalty_[element]; }

  double Minimum() const { return *std::min_element(criterion_.begin(), criterion_.end()); }

  // The first `count` selectable elements in (key, canonical rank) order (all if fewer).
  std::vector<ElementId> InKeyOrder(std::size_t count) const {
    std::vector<ElementId> order;
    for (ElementId element = 0; element < mesh_.element_count(); ++element) {
      if (selectable_[element]) order.push_back(element);
    }
    count = std::min(count, order.size());
    std::partial_sort(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(count),
                      order.end(), [&](ElementId a, ElementId b) {
                        if (Key(a) != Key(b)) return Key(a) < Key(b);
                        return mesh_.canonical_rank(a) < mesh_.canonical_rank(b);
                      });
    order.resize(count);
    return order;
  }

  // The element, then every other element with one of its movable nodes, in canonical order.
  std::vector<ElementId> Affected(ElementId element) const {
    std::vector<ElementId> others;
    for (NodeId node : mesh_.element_nodes(element)) {
      if (!movable_[node]) continue;
      for (ElementId other : mesh_.node_elements(node)) {
        if (other != element) others.push_back(other);
      }
    }
    std::sort(others.begin(), others.end(), [&](ElementId a, ElementId b) {
      return mesh_.canonical_rank(a) < mesh_.canonical_rank(b);
    });
    others.erase(std::unique(others.begin(), others.end()), others.end());
    others.insert(others.begin(), element);
    return others;
  }

  // q, or q_γ = min(q, γ(1 − w/2)) (Sec. 4.4, QualityGamma), of the element at its nodes'
  // current positions; an invalid element counts as 0.
  double CriterionOf(ElementId element, double quality) const {
    if (criterion_kind_ == SelectionCriterion::kMeanRatio) return std::max(0.0, quality);
    const NodeId* ids = mesh_.element_nodes(element).data();
    return DispatchElementType(mesh_.type(element), [&]<ElementType kType>() {
      return QualityGamma<kType>(GatherNodes<kType>(mesh_, ids), params_.gamma);
    });
  }

  double QualityOf(ElementId element) const {
    const NodeId* ids = mesh_.element_nodes(element).data();
    return DispatchElementType(mesh_.type(element), [&]<ElementType kType>() {
      return MeanRatioOrInvalid<kType>(GatherNodes<kType>(mesh_, ids));
    });
  }

  // Steps 1.2–3.2 of one pick; returns its blocker (−1 if none).
  ElementId RunPick(ElementId pick, std::int64_t batch, ModelCounts& counts) {
    counts.by_warpage += criterion_[pick] < std::max(0.0, quality_[pick]);
    struct Move {
      NodeId node;
      Vec3 from, to;
    };
    std::vector<Move> moves;
    const std::span<const NodeId> ids = mesh_.element_nodes(pick);
    DispatchElementType(mesh_.type(pick), [&]<ElementType kType>() {
      const auto moved = RegularizingStep<kType>(GatherNodes<kType>(mesh_, ids.data()),
                                                 params_.sequential_sigma[TypeIndex(kType)],
                                                 params_.sequential_rho);
      for (int k = 0; k < ElementTable<kType>::kNodes; ++k) {
        const NodeId node = ids[k];
        if (!movable_[node]) continue;
        moves.push_back({node, Vec3(mesh_.x()[node], mesh_.y()[node], mesh_.z()[node]), moved[k]});
      }
    });
    const std::vector<ElementId> affected = Affected(pick);
    std::vector<double> quality(affected.size());
    ElementId blocker = -1;
    bool valid = false;
    double fraction = 1.0;
    for (int attempt = 0; attempt <= params_.sequential_backtracking_steps && !valid;
         ++attempt, fraction *= 0.5) {
      for (const Move& move : moves) {
        mesh_.x()[move.node] = move.from.x() + fraction * (move.to.x() - move.from.x());
        mesh_.y()[move.node] = move.from.y() + fraction * (move.to.y() - move.from.y());
        mesh_.z()[move.node] = move.from.z() + fraction * (move.to.z() - move.from.z());
      }
      valid = true;
      for (std::size_t i = 0; i < affected.size(); ++i) {
        quality[i] = QualityOf(affected[i]);
        if (quality[i] >= 0.0) continue;
        // The first invalid element of the list is the blocker, if it can be picked.
        valid = false;
        if (params_.sequential_transform_blockers && selectable_[affected[i]]) {
          blocker = affected[i];
        }
        break;
      }
    }
    if (picked_in_batch_[pick] == -1) ++counts.distinct;
    if (picked_in_batch_[pick] == batch - 1) {
      penalty_[pick] += params_.penalty_repeat;  // Δπ_r
      ++counts.repeated;
    }
    picked_in_batch_[pick] = batch;
    if (!valid) {
      for (const Move& move : moves) {
        mesh_.x()[move.node] = move.from.x();
        mesh_.y()[move.node] = move.from.y();
        mesh_.z()[move.node] = move.from.z();
      }
      penalty_[pick] += params_.penalty_invalid;  // Δπ_i
      ++counts.reverted;
      return blocker;
    }
    penalty_[pick] = std::max(0.0, penalty_[pick] - params_.penalty_success);  // Δπ_s
    for (std::size_t i = 0; i < affected.size(); ++i) {
      quality_[affected[i]] = quality[i];
      criterion_[affected[i]] = CriterionOf(affected[i], quality[i]);
    }
    return blocker;
  }

  Mesh& mesh_;
  const SmoothingParams& params_;
  const SelectionCriterion criterion_kind_;
  std::vector<std::uint8_t> movable_;
  std::vector<std::uint8_t> selectable_;
  std::vector<double> quality_;
  std::vector<double> criterion_;
  std::vector<double> penalty_;
  std::vector<std::int64_t> picked_in_batch_;
};

// One configuration of the substep on a shared mesh, each chosen for the rules it exercises.
struct ModelCase {
  const char* mesh;  // a shared Mesquite mesh
  double band;
  std::int64_t batch_elements;  // small, so that these meshes of about 11k elements get batches
  int backtracking;
};

TEST(BatchModelTest, EngineMakesTheModelsPicksOnEveryThreadCount) {
  const ModelCase cases[] = {
      // The default band, which ends most batches: batches full and cut short, second rounds,
      // blockers.
      {"cub_fru.vtk", 0.01, 512, 10},
      // No band and no backtracking: reverted steps (Δπ_i) and their blockers, deep batches.
      {"cub_fru.vtk", 2.0, 256, 0},
      // No band on tets: the same elements picked batch after batch (Δπ_r).
      {"tire.vtk", 2.0, 512, 10},
  };
  ModelCounts total;
  for (const ModelCase& c : cases) {
    SCOPED_TRACE(::testing::Message()
                 << c.mesh << ", band " << c.band << ", one pick per " << c.batch_elements
                 << " elements, " << c.backtracking << " halvings");
    const auto make = [&c]() -> absl::StatusOr<Mesh> { return testing::LoadSharedMesh(c.mesh); };
    SmoothingParams params;
    params.method = Method::kSequential;
    params.sequential_batch_elements = c.batch_elements;
    params.sequential_batch_band = c.band;
    params.sequential_backtracking_steps = c.backtracking;
    params.sequential_max_iterations = 6000;
    // The cap or the pinned minimum ends the run, not the stall rule.
    params.sequential_stall_iterations = std::int64_t{1} << 40;

    auto model_mesh = make();
    ASSERT_TRUE(model_mesh.ok()) << model_mesh.status();
    BatchedSequentialModel model(*model_mesh, params);
    ASSERT_GE(model.Limit(), 16) << "too few elements for batches";
    const ModelCounts counts = model.Run();
    EXPECT_GT(counts.picks, counts.batches) << "the batches hold more than one pick";
    total.full_batches += counts.full_batches;
    total.dependent += counts.dependent;
    total.blocker_candidates += counts.blocker_candidates;
    total.deep_batches += counts.deep_batches;
    total.band_cut_batches += counts.band_cut_batches;
    total.reverted += counts.reverted;
    total.repeated += counts.repeated;

    const auto runs = testing::SmoothAtThreadCounts(make, params, {1, 2});
    ASSERT_EQ(runs.size(), 2u);
    for (const auto& run : runs) {
      EXPECT_EQ(run.result.iterations_sequential, counts.picks) << run.result.threads << " threads";
      EXPECT_TRUE(run.coordinates == testing::CoordinateSnapshot(*model_mesh))
          << run.result.threads << " threads: the engine's batches are not the model's";
    }
  }
  // Every rule had something to decide in one run or another.
  EXPECT_GT(total.full_batches, 0);
  EXPECT_GT(total.dependent, 0);
  EXPECT_GT(total.blocker_candidates, 0);
  EXPECT_GT(total.deep_batches, 0);
  EXPECT_GT(total.band_cut_batches, 0);
  EXPECT_GT(total.reverted, 0);
  EXPECT_GT(total.repeated, 0);
}

// One pick at a time (the paper's substep: a mesh too small for batches, as every shared mesh
// is by default). The engine keeps what each picked element evaluates for its later picks
// (FindAffectedOfOnePick), and most picks are of elements picked before; the model finds every
// list afresh. Same picks, same coordinates to the bit.
TEST(BatchModelTest, EngineMakesTheModelsPicksOneAtATime) {
  SmoothingParams params;
  params.method = Method::kSequential;
  params.sequential_max_iterations = 6000;
  params.sequential_stall_iterations = std::int64_t{1} << 40;
  Mesh model_mesh = testing::LoadSharedMesh("cub_fru.vtk");
  BatchedSequentialModel model(model_mesh, params);
  ASSERT_EQ(model.Limit(), 1) << "cub_fru.vtk should be below the batches' size";
  const ModelCounts counts = model.Run();
  EXPECT_EQ(counts.batches, counts.picks);
  EXPECT_GT(counts.picks, 4 * counts.distinct) << "few elements were picked again";
  EXPECT_GT(counts.reverted + counts.blocker_candidates, 0);
  const auto runs = testing::SmoothAtThreadCounts(
      [] { return absl::StatusOr<Mesh>(testing::LoadSharedMesh("cub_fru.vtk")); }, params, {1, 2});
  ASSERT_EQ(runs.size(), 2u);
  for (const auto& run : runs) {
    EXPECT_EQ(run.result.iterations_sequential, counts.picks) << run.result.threads << " threads";
    EXPECT_TRUE(run.coordinates == testing::CoordinateSnapshot(model_mesh))
        << run.result.threads << " threads: the engine's picks are not the model's";
  }
}

// The warpage variant's criterion q_γ (Sec. 4.4), which the substep keeps per element beside the
// quality and in a heap of its own: the substep alone (RunSequential), started from the file's
// mesh, against the model selecting by q_γ.
TEST(BatchModelTest, WarpageCriterionMakesTheModelsPicksOnEveryThreadCount) {
  SmoothingParams params;
  params.sequential_batch_elements = 512;
  params.sequential_max_iterations = 6000;
  params.sequential_stall_iterations = std::int64_t{1} << 40;
  // Below the default 0.25, so that the warpage term decides the criterion of most elements of
  // this mesh as it comes (q_min 0.06), not only after GETMe has lifted its worst ones.
  params.gamma = 0.1;
  Mesh model_mesh = testing::LoadSharedMesh("cub_fru.vtk");
  BatchedSequentialModel model(model_mesh, params, SelectionCriterion::kQualityGamma);
  ASSERT_GE(model.Limit(), 16);
  const ModelCounts counts = model.Run();
  EXPECT_GT(counts.picks, counts.batches);
  EXPECT_GT(counts.dependent, 0);
  EXPECT_GT(counts.by_warpage, counts.picks / 10) << "the warpage term decided few picks";
  for (const int threads : {1, 2}) {
    Mesh mesh = testing::LoadSharedMesh("cub_fru.vtk");
    ThreadPool pool(threads);
    const ProgressCallback no_progress;
    SmoothingContext context(mesh, params, pool, no_progress, nullptr);
    const absl::StatusOr<PhaseSummary> summary =
        RunSequential(context, SelectionCriterion::kQualityGamma);
    ASSERT_TRUE(summary.ok()) << summary.status();
    EXPECT_EQ(summary->iterations, counts.picks) << threads << " threads";
    EXPECT_TRUE(testing::CoordinateSnapshot(mesh) == testing::CoordinateSnapshot(model_mesh))
        << threads << " threads: the engine's batches are not the model's";
  }
}

}  // namespace
}  // namespace getme
