#include "getme/smoothing/sequential_smoother.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <limits>
#include <thread>
#include <utility>
#include <vector>

#include "absl/container/flat_hash_map.h"
#include "getme/elements/element_quality.h"
#include "getme/elements/transform.h"
#include "getme/elements/vec3.h"
#include "getme/mesh/element_neighbours.h"
#include "getme/parallel/lowest_keys_heap.h"

namespace getme {
namespace {

// Picks between two looks at the cancellation token: a pick costs about a microsecond.
constexpr std::int64_t kCancelCheckInterval = 256;

// Fewer picks per batch than this cost more in synchronisation than a second thread gains
// (measured on cub_wedge_like, 112k elements: batches of 6 made the default run 25 % slower with
// 2 threads; docs/parallel-sequential.md).
constexpr std::int64_t kMinimumBatch = 16;

// The sliding stop rule's window (SequentialStop::kHandOnToPolish) is at most this many picks per
// distinct element picked so far, and at least kMinimumWindow. The picks cycle through a working
// set of bad elements (penalties keep one from being picked again and again), and on large meshes
// that set is a small part of the mesh: cub_wedge_like.vtk (112,393 elements) works on 578, and
// its last new best q_min came at pick 2,997 of the 31,040 a window of elements / 4 ran.
constexpr std::int64_t kActiveRounds = 8;
constexpr std::int64_t kMinimumWindow = 1000;

struct NodeBackup {
  NodeId node;
  double x, y, z;
};

// At most this many element ids in the one-pick path's kept lists (FindAffectedOfOnePick): 16 MB.
constexpr std::int64_t kMaxKeptAffected = std::int64_t{4} << 20;

// A key update that moves entries of a heap, left for the serial part of a batch.
struct HeapUpdate {
  LowestKeysHeap* heap;
  std::int32_t item;
  double key;
};

// One pick of a batch: carried out in parallel by RunPick, which also updates the per-element state
// of the elements it evaluated (no other pick of the batch touches them), and finished in batch
// order by FinishBatch. The vectors are reused from batch to batch.
struct PickWork {
  ElementId element = -1;
  std::int32_t rank = -1;  // the element's canonical rank, when it came from the selection heap
  bool applied = false;
  // A selectable neighbour that an attempt of the step would have inverted (the last one found),
  // also when a shorter attempt then succeeded.
  ElementId blocker = -1;
  std::vector<NodeBackup> backup;
  std::vector<NodeBackup> target;
  std::vector<ElementId> affected;  // the element, then its neighbours through movable nodes
  std::vector<double> affected_quality;
  std::vector<const NodeId*> node_lists;  // of `affected`, for SmoothingContext::QualitiesOf
  std::vector<double> quality_gain;  // per affected element: its new q − its old q (invalid as 0)
  std::vector<HeapUpdate> heap_updates;
  ElementNeighbourFinder neighbour_finder;
  std::int64_t first_picks = 0;  // 1 if this pick was its element's first in the phase
};

class SequentialSubstep {
 public:
  SequentialSubstep(SmoothingContext& context, SelectionCriterion criterion, SequentialStop stop)
      : context_(context),
        mesh_(context.mesh),
        params_(context.params),
        criterion_(criterion),
        stop_(stop),
        phase_(criterion == SelectionCriterion::kMeanRatio ? Phase::kSequential : Phase::kWarpage),
        penalty_(mesh_.element_count(), 0.0),
        criterion_value_(criterion == SelectionCriterion::kMeanRatio ? 0 : mesh_.element_count()),
        picked_in_batch_(mesh_.element_count(), -1),
        batch_limit_(SequentialBatchLimit(params_, mesh_)),
        claimed_(batch_limit_ > 1 ? (mesh_.element_count() + 63) / 64 : 0, 0),
        selection_(mesh_.element_count(), 4 * batch_limit_, HeapStock(mesh_)),
        quality_min_(mesh_.element_count(), 1, HeapStock(mesh_)),
        criterion_min_(criterion == SelectionCriterion::kMeanRatio ? 0 : mesh_.element_count(), 1,
                       HeapStock(mesh_)) {}

  absl::StatusOr<PhaseSummary> Run();

 private:
  // q_γ = min(q, γ(1 − w/2)) of Sec. 4.4 (QualityGamma in element_quality.h) from the quality
  // the pick has just evaluated, so that only the warpage is computed again.
  double QualityGammaOf(ElementId element, double quality) const;
  // The element's current criterion: max(0, q) for the mean ratio, else the stored q_γ.
  double CriterionValue(ElementId element) const {
    return criterion_value_.empty() ? std::max(0.0, context_.quality[element])
                                    : criterion_value_[element];
  }
  // How many of the lowest keys the heaps keep sorted: few enough that an update sifts through a
  // heap that stays in cache, enough that restocking (a pass over every element) is rare.
  static std::int64_t HeapStock(const Mesh& mesh) { return mesh.element_count() / 64; }
  double CriterionMinimum() {
    return criterion_ == SelectionCriterion::kMeanRatio ? quality_min_.top_key()
                                                        : criterion_min_.top_key();
  }
  // Fills work.affected: the element, then its neighbours through movable nodes.
  void FindAffected(PickWork& work);
  // FindAffected for the one-pick path, from the lists kept for elements picked before.
  void FindAffectedOfOnePick(PickWork& work);
  // Makes the batch just chosen the last batch, whose found candidates FindAffected copies.
  void RememberLastBatch();
  // The index in last_work_ of a found candidate of the last batch, or −1.
  std::int64_t FoundInLastBatch(ElementId element) const;
  // Claims work.affected for the batch being chosen if no earlier pick of it claimed any of them;
  // returns whether it did.
  bool TryClaim(const PickWork& work);
  // FindAffected for work_[begin, end), on every thread, while this thread claims them in order
  // (TryClaim) as they are found, until the batch is full.
  void FindAndClaim(std::int64_t begin, std::int64_t end);
  // Chooses the picks of the next batch: work_[picks_[i]], with their affected elements found.
  void ChooseBatch();
  // Steps 1.2–3.2 of one pick (Sec. 3.2). Writes only the pick's own movable nodes, the state of
  // the elements it evaluates, and `work`: the picks of a batch run in parallel.
  void RunPick(PickWork& work);
  void SetKey(LowestKeysHeap& heap, std::int32_t item, double key, PickWork& work) {
    if (!heap.UpdateOutsideHeap(item, key)) work.heap_updates.push_back({&heap, item, key});
  }
  // What of a pick is shared with the others (q_mean's running sum, the undo log, the heaps but
  // the selection), in batch order; returns the nodes reverted (0 if the step was applied).
  std::int64_t FinishPick(PickWork& work);
  // FinishPick for every pick of the batch, in batch order, and the selection heap's updates;
  // returns the nodes reverted.
  std::int64_t FinishBatch();
  void RestoreBest();
  // The sliding window in rounds over the elements the substep works on rather than in mesh
  // sizes: kActiveRounds picks per distinct element picked so far, at least kMinimumWindow
  // (SequentialStop::kHandOnToPolish, unless sequential_handoff_window sets the window).
  std::int64_t RoundsWindow() const {
    return std::max<std::int64_t>(kMinimumWindow, kActiveRounds * picked_elements_);
  }

  SmoothingContext& context_;
  Mesh& mesh_;
  const SmoothingParams& params_;
  const SelectionCriterion criterion_;
  const SequentialStop stop_;
  const Phase phase_;
  std::vector<double> penalty_;  // π_j ≥ 0
  // q_γ(E_j) for the warpage criterion; left empty for the mean ratio, whose criterion is the
  // element's quality (CriterionValue): one array fewer for each of the ~60 elements a pick
  // evaluates, most of them cache misses on a large mesh.
  std::vector<double> criterion_value_;
  // The batch each element was last picked in (Δπ_r: picked in the batch before).
  std::vector<std::int64_t> picked_in_batch_;
  const std::int64_t batch_limit_;  // SequentialBatchLimit
  // With batches of more than one pick: a bit per element claimed by a pick of the batch being
  // chosen (TryClaim).
  std::vector<std::uint64_t> claimed_;
  // Keyed by criterion + π over elements with a movable node; items are canonical ranks, so ties
  // break in the canonical order (Mesh::canonical_order).
  LowestKeysHeap selection_;
  LowestKeysHeap quality_min_;  // keyed by q, every element: the mesh's q_min
  // Keyed by the criterion, every element; left empty for the mean-ratio criterion, whose key is
  // quality_min_'s (a valid element's q ≥ 0), so CriterionMinimum reads that heap instead.
  LowestKeysHeap criterion_min_;
  double quality_sum_ = 0.0;
  std::int64_t batch_ = 0;             // batches begun
  std::int64_t picked_elements_ = 0;   // distinct elements picked so far
  std::vector<ElementId> blockers_;    // neighbours that reverted steps of the last batch would
                                       // have inverted: picked first in the next one
  std::vector<std::size_t> frontier_;  // IndexedMinHeap::VisitInKeyOrder's scratch
  // The candidates of the batch being chosen: the blockers, as element ids, then canonical ranks
  // from the selection heap from index ranked_candidates_ on.
  std::vector<std::int32_t> candidates_;
  std::size_t ranked_candidates_ = 0;
  std::vector<PickWork> work_;       // one per candidate
  std::vector<std::int64_t> picks_;  // the batch: indices into work_
  std::vector<std::uint8_t> found_;  // per work_ entry: FindAffected done (FindAndClaim)
  // The last batch's candidates, and those of them that were found: most candidates a batch does
  // not take come back in the next one (RememberLastBatch, FindAffected).
  std::vector<PickWork> last_work_;
  std::vector<std::uint8_t> last_found_;
  // element → index into last_work_ of its found entry. Written between batches, read by every
  // thread during FindAndClaim.
  absl::flat_hash_map<ElementId, std::int64_t> last_found_index_;
  // One pick at a time: what each element picked so far evaluates (its FindAffected list), as
  // [begin, end) in kept_affected_, for when it is picked again (FindAffectedOfOnePick).
  absl::flat_hash_map<ElementId, std::pair<std::int64_t, std::int64_t>> kept_affected_at_;
  std::vector<ElementId> kept_affected_;
  std::vector<NodeBackup> undo_since_best_;
};

double SequentialSubstep::QualityGammaOf(ElementId element, double quality) const {
  const NodeId* ids = mesh_.element_nodes(element).data();
  const double warpage = DispatchElementType(mesh_.type(element), [&]<ElementType kType>() {
    return Warpage<kType>(GatherNodes<kType>(mesh_, ids));
  });
  return QualityGammaFrom(std::max(0.0, quality), warpage, params_.gamma);
}

// Which elements a pick evaluates depends only on the mesh's connectivity and which nodes may move,
// neither of which changes during the substep: a list found for the last batch is copied, not
// found again. On a 1M-element hybrid block 29 % of the candidates a batch finds were found by the
// batch before it and not taken (docs/parallel-sequential.md).
void SequentialSubstep::FindAffected(PickWork& work) {
  if (work.element < 0) work.element = mesh_.canonical_order()[work.rank];
  if (const std::int64_t last = FoundInLastBatch(work.element); last >= 0) {
    work.affected = last_work_[last].affected;
    return;
  }
  work.affected.assign(1, work.element);
  const auto neighbours = work.neighbour_finder.Find(mesh_, work.element, context_.movable);
  work.affected.insert(work.affected.end(), neighbours.begin(), neighbours.end());
}

// The picks cycle through a working set of bad elements, the penalties keeping any one from being
// picked again and again (kActiveRounds): on knowles-mixed-beam.vtk 13,217 picks go to 761
// elements, on cub_fru.vtk 37,866 to 1,641. What a pick evaluates depends only on the connectivity
// and the movable nodes, so the list found the first time an element is picked serves every later
// pick of it, and collecting and merging its nodes' rows (ElementNeighbourFinder) is done once per
// element, not once per pick. The kept lists are bounded (kMaxKeptAffected); past that, lists are
// found as before.
void SequentialSubstep::FindAffectedOfOnePick(PickWork& work) {
  if (const auto kept = kept_affected_at_.find(work.element); kept != kept_affected_at_.end()) {
    const auto [begin, end] = kept->second;
    work.affected.assign(kept_affected_.begin() + begin, kept_affected_.begin() + end);
    return;
  }
  FindAffected(work);
  const auto begin = static_cast<std::int64_t>(kept_affected_.size());
  if (begin + static_cast<std::int64_t>(work.affected.size()) > kMaxKeptAffected) return;
  kept_affected_.insert(kept_affected_.end(), work.affected.begin(), work.affected.end());
  kept_affected_at_.emplace(work.element,
                            std::pair(begin, static_cast<std::int64_t>(kept_affected_.size())));
}

// Two picks are independent when no element has a movable node of both: then neither reads a
// node the other moves nor evaluates an element the other evaluates, so evaluating them in
// parallel gives what evaluating them one after the other in either order gives. A pick taken
// into the batch claims the elements it evaluates (itself and those around its movable nodes); a
// candidate is independent of the batch when it would evaluate no claimed element. Claims are
// bits, cleared after the batch: at a million elements the bit set stays in a core's L2 cache.
bool SequentialSubstep::TryClaim(const PickWork& work) {
  for (ElementId element : work.affected) {
    if (claimed_[element >> 6] >> (element & 63) & 1) return false;
  }
  for (ElementId element : work.affected)
    claimed_[element >> 6] |= std::uint64_t{1} << (element & 63);
  return true;
}

void SequentialSubstep::RememberLastBatch() {
  std::swap(work_, last_work_);
  std::swap(found_, last_found_);
  last_found_index_.clear();  // keeps its capacity
  for (std::size_t i = 0; i < last_found_.size(); ++i) {
    if (last_found_[i]) last_found_index_.try_emplace(last_work_[i].element, i);
  }
  std::fill(found_.begin(), found_.end(), 0);
}

std::int64_t SequentialSubstep::FoundInLastBatch(ElementId element) const {
  const auto found = last_found_index_.find(element);
  return found == last_found_index_.end() ? -1 : found->second;
}

void SequentialSubstep::FindAndClaim(std::int64_t begin, std::int64_t end) {
  const auto limit = static_cast<std::size_t>(batch_limit_);
  if (static_cast<std::int64_t>(found_.size()) < end) found_.resize(end);
  std::fill(found_.begin() + begin, found_.begin() + end, 0);
  std::atomic<std::int64_t> next{begin};
  std::atomic<bool> full{false};
  // Finds the next candidate no thread has taken; false when there is none.
  const auto find_next = [&] {
    const std::int64_t i = next.fetch_add(1, std::memory_order_relaxed);
    if (i >= end) return false;
    FindAffected(work_[i]);
    std::atomic_ref(found_[i]).store(1, std::memory_order_release);
    return true;
  };
  context_.pool.ForEachThread([&](int thread) {
    if (thread != 0) {
      while (!full.load(std::memory_order_relaxed) && find_next()) {
      }
      return;
    }
    int waits = 0;
    for (std::int64_t i = begin; i < end && picks_.size() < limit;) {
      if (std::atomic_ref(found_[i]).load(std::memory_order_acquire)) {
        if (TryClaim(work_[i])) picks_.push_back(i);
        ++i;
      } else if (!find_next()) {
        // Another thread is finding candidate i: a few microseconds, unless the system runs more
        // threads than cores (the server's jobs side by side) and that one is not running, when
        // the core is handed over.
        if (++waits % 1024 == 0) {
          std::this_thread::yield();
        } else {
          SpinPause();
        }
      }
    }
    full.store(true, std::memory_order_relaxed);
  });
}

void SequentialSubstep::ChooseBatch() {
  const std::int64_t limit = batch_limit_;
  picks_.clear();
  candidates_.clear();
  // The serial algorithm: a blocker of the last pick, else the element with the lowest key.
  if (limit == 1) {
    candidates_.push_back(blockers_.empty() ? mesh_.canonical_order()[selection_.top()]
                                            : blockers_.front());
    blockers_.clear();
    if (work_.empty()) work_.resize(1);
    work_[0].element = candidates_[0];
    FindAffectedOfOnePick(work_[0]);
    picks_.push_back(0);
    return;
  }
  RememberLastBatch();
  // Batches: the last batch's blockers first, then the elements in key order, each taken if it is
  // independent of those taken before it. Looking at most 4 × the batch size deep keeps a batch
  // among the worst elements when they crowd together (the batch is then smaller).
  candidates_ = blockers_;
  blockers_.clear();
  ranked_candidates_ = candidates_.size();
  std::int64_t looked_at = 0;
  std::int64_t look_until = 0;
  const double band_end = selection_.top_key() + params_.sequential_batch_band;
  const auto look = [&](std::int32_t rank, double key) {
    if (looked_at == look_until || (looked_at > 0 && key > band_end)) return false;
    candidates_.push_back(rank);  // its element id is looked up in parallel, by FindAffected
    ++looked_at;
    return true;
  };
  // Finding what a candidate would evaluate reads the mesh's node→element rows around it, cold in
  // cache: the largest cost of choosing, so it runs on every thread while this one claims
  // (FindAndClaim). The walk through the selection heap, serial, goes deeper in rounds of as many
  // candidates as about give a full batch (measured: about half of the candidates are
  // independent); on a 1M-element hybrid block one batch in six needs a second round. A candidate
  // that a blocker duplicates is not taken twice: it claimed itself.
  for (std::int64_t begin = 0; static_cast<std::int64_t>(picks_.size()) < limit;
       begin += 2 * limit) {
    look_until = std::min(
        4 * limit, std::max<std::int64_t>(
                       0, begin + 2 * limit - static_cast<std::int64_t>(ranked_candidates_)));
    if (begin == 0) {
      selection_.VisitInKeyOrder(frontier_, look);
    } else {
      selection_.ContinueInKeyOrder(frontier_, look);
    }
    const auto count = static_cast<std::int64_t>(candidates_.size());
    if (begin >= count) break;
    const std::int64_t end = std::min(count, begin + 2 * limit);
    if (static_cast<std::int64_t>(work_.size()) < end) work_.resize(end);
    for (std::int64_t i = begin; i < end; ++i) {
      const bool ranked = i >= static_cast<std::int64_t>(ranked_candidates_);
      work_[i].element = ranked ? -1 : candidates_[i];
      work_[i].rank = ranked ? candidates_[i] : -1;
    }
    FindAndClaim(begin, end);
  }
  for (std::int64_t i : picks_) {
    for (ElementId element : work_[i].affected) claimed_[element >> 6] = 0;
  }
}

void SequentialSubstep::RunPick(PickWork& work) {
  const ElementId pick = work.element;
  // The elements around a pick lie anywhere in a large mesh, and each has its state in several
  // arrays: ask for all of it now, so the cache misses overlap each other and the transform
  // instead of coming one after another in the loops below.
  for (ElementId element : work.affected) {
    mesh_.PrefetchElement(element);
    __builtin_prefetch(&context_.quality[element], 1);
    if (!criterion_value_.empty()) __builtin_prefetch(&criterion_value_[element], 1);
    __builtin_prefetch(&penalty_[element]);
    quality_min_.Prefetch(element);
  }
  // Steps 1.2, 1.3 and 2: transform with the fixed σ^type, scale, relax, set the free nodes.
  auto x = mesh_.x();
  auto y = mesh_.y();
  auto z = mesh_.z();
  const std::span<const NodeId> ids = mesh_.element_nodes(pick);
  const ElementType type = mesh_.type(pick);
  work.backup.clear();
  work.target.clear();
  work.blocker = -1;
  DispatchElementType(type, [&]<ElementType kType>() {
    const auto moved =
        RegularizingStep<kType>(GatherNodes<kType>(mesh_, ids.data()),
                                params_.sequential_sigma[TypeIndex(kType)], params_.sequential_rho);
    for (int k = 0; k < ElementTable<kType>::kNodes; ++k) {
      const NodeId node = ids[k];
      if (!context_.movable[node]) continue;
      work.backup.push_back({node, x[node], y[node], z[node]});
      work.target.push_back({node, moved[k].x(), moved[k].y(), moved[k].z()});
    }
  });

  // Step 3.1: the element and its neighbours must stay valid. With backtracking (a safeguard,
  // docs/quality.md) a step that would invert a neighbour is retried at half the length. Only the
  // neighbours through a movable node change: the others keep their quality (and validity), so
  // they are not evaluated.
  work.affected_quality.resize(work.affected.size());
  context_.NodeListsOf(work.affected, work.node_lists);
  for (ElementId element : work.affected) {  // the selection's state, by rank (above)
    const std::int32_t rank = mesh_.canonical_rank(element);
    selection_.PrefetchContains(rank);
    selection_.Prefetch(rank);
  }
  bool valid = false;
  double fraction = 1.0;
  for (int attempt = 0; attempt <= params_.sequential_backtracking_steps && !valid;
       ++attempt, fraction *= 0.5) {
    for (std::size_t i = 0; i < work.target.size(); ++i) {
      const NodeBackup& from = work.backup[i];
      const NodeBackup& to = work.target[i];
      const Vec3 placed = context_.Placed(
          from.node,
          Vec3(from.x + fraction * (to.x - from.x), from.y + fraction * (to.y - from.y),
               from.z + fraction * (to.z - from.z)),
          Vec3(from.x, from.y, from.z));
      x[from.node] = placed[0];
      y[from.node] = placed[1];
      z[from.node] = placed[2];
    }
    // All of them at once, several side by side (element_passes.h); the first invalid one in
    // the list is the blocker, as when they were evaluated one by one up to it.
    context_.QualitiesOf(work.affected, work.node_lists, work.affected_quality);
    valid = true;
    for (std::size_t i = 0; i < work.affected.size() && valid; ++i) {
      valid = work.affected_quality[i] >= 0.0;
      if (!valid && params_.sequential_transform_blockers &&
          selection_.contains(mesh_.canonical_rank(work.affected[i]))) {
        work.blocker = work.affected[i];
      }
    }
  }
  work.applied = valid;
  work.heap_updates.clear();
  // Δπ_r: the same element was picked in the previous step (Step 3.2); with batches, in the
  // previous batch.
  if (picked_in_batch_[pick] == batch_ - 1) penalty_[pick] += params_.penalty_repeat;
  if (picked_in_batch_[pick] < 0) ++work.first_picks;
  picked_in_batch_[pick] = batch_;
  if (!valid) {
    for (const NodeBackup& b : work.backup) {
      x[b.node] = b.x;
      y[b.node] = b.y;
      z[b.node] = b.z;
    }
    penalty_[pick] += params_.penalty_invalid;  // Δπ_i
    SetKey(selection_, mesh_.canonical_rank(pick), CriterionValue(pick) + penalty_[pick], work);
    return;
  }
  penalty_[pick] = std::max(0.0, penalty_[pick] - params_.penalty_success);  // Δπ_s
  work.quality_gain.resize(work.affected.size());
  for (std::size_t i = 0; i < work.affected.size(); ++i) {
    const ElementId element = work.affected[i];
    const double q = work.affected_quality[i];
    work.quality_gain[i] = q - std::max(0.0, context_.quality[element]);
    context_.quality[element] = q;
    SetKey(quality_min_, element, q, work);
    if (criterion_ != SelectionCriterion::kMeanRatio) {
      criterion_value_[element] = QualityGammaOf(element, q);
      SetKey(criterion_min_, element, criterion_value_[element], work);
    }
    if (const std::int32_t rank = mesh_.canonical_rank(element); selection_.contains(rank)) {
      SetKey(selection_, rank, CriterionValue(element) + penalty_[element], work);
    }
  }
}

std::int64_t SequentialSubstep::FinishPick(PickWork& work) {
  if (work.blocker >= 0) blockers_.push_back(work.blocker);
  picked_elements_ += work.first_picks;
  work.first_picks = 0;
  if (work.applied) {
    undo_since_best_.insert(undo_since_best_.end(), work.backup.begin(), work.backup.end());
    for (double gain : work.quality_gain) quality_sum_ += gain;
  }
  for (const HeapUpdate& update : work.heap_updates) {
    if (update.heap != &selection_) update.heap->Update(update.item, update.key);
  }
  return work.applied ? 0 : static_cast<std::int64_t>(work.backup.size());
}

std::int64_t SequentialSubstep::FinishBatch() {
  // The selection heap on one thread, the rest on another: each in batch order, so the outcome is
  // the same as one thread doing both. The selection heap takes about half of this serial step.
  // Each side asks for the heap entries of the next pick's updates while it applies this pick's:
  // they are scattered over arrays of the mesh's size.
  const auto prefetch_updates = [&](std::size_t at, bool of_selection) {
    if (at >= picks_.size()) return;
    for (const HeapUpdate& update : work_[picks_[at]].heap_updates) {
      if ((update.heap == &selection_) == of_selection) update.heap->Prefetch(update.item);
    }
  };
  std::int64_t reverts = 0;
  auto update_selection = [&] {
    prefetch_updates(0, true);
    for (std::size_t at = 0; at < picks_.size(); ++at) {
      prefetch_updates(at + 1, true);
      for (const HeapUpdate& update : work_[picks_[at]].heap_updates) {
        if (update.heap == &selection_) selection_.Update(update.item, update.key);
      }
    }
  };
  auto finish_the_rest = [&] {
    prefetch_updates(0, false);
    for (std::size_t at = 0; at < picks_.size(); ++at) {
      prefetch_updates(at + 1, false);
      reverts += FinishPick(work_[picks_[at]]);
    }
  };
  if (picks_.size() == 1 || context_.pool.thread_count() == 1) {
    update_selection();
    finish_the_rest();
    return reverts;
  }
  context_.pool.ForEachThread([&](int thread) {
    if (thread == 0) update_selection();
    if (thread == 1) finish_the_rest();
  });
  return reverts;
}

void SequentialSubstep::RestoreBest() {
  auto x = mesh_.x();
  auto y = mesh_.y();
  auto z = mesh_.z();
  for (auto it = undo_since_best_.rbegin(); it != undo_since_best_.rend(); ++it) {
    x[it->node] = it->x;
    y[it->node] = it->y;
    z[it->node] = it->z;
  }
  undo_since_best_.clear();
  context_.RefreshQuality();
}

absl::StatusOr<PhaseSummary> SequentialSubstep::Run() {
  const double phase_start = context_.ElapsedSeconds();
  const std::int64_t elements = mesh_.element_count();
  const bool sliding = stop_ == SequentialStop::kHandOnToPolish;
  const std::int64_t window = sliding ? (params_.sequential_handoff_window > 0
                                             ? params_.sequential_handoff_window
                                             : std::max<std::int64_t>(kMinimumWindow, elements / 4))
                                      : (params_.sequential_stall_iterations > 0
                                             ? params_.sequential_stall_iterations
                                             : std::max<std::int64_t>(kMinimumWindow, elements));
  const bool window_in_rounds = sliding && params_.sequential_handoff_window == 0;
  const std::int64_t cap =
      params_.sequential_max_iterations > 0 ? params_.sequential_max_iterations : 50 * elements;

  // The lowest criterion value among elements with no movable node: no pick changes them, so the
  // mesh's minimum can never rise above it.
  double pinned_min = std::numeric_limits<double>::infinity();
  for (ElementId element : mesh_.canonical_order()) {  // the running sum's order matters
    const double q = std::max(0.0, context_.quality[element]);
    quality_sum_ += q;
    quality_min_.Insert(element, q);
    if (criterion_ != SelectionCriterion::kMeanRatio) {
      criterion_value_[element] = QualityGammaOf(element, q);
      criterion_min_.Insert(element, criterion_value_[element]);
    }
    if (context_.HasMovableNode(element)) {
      selection_.Insert(mesh_.canonical_rank(element), CriterionValue(element));
    } else {
      pinned_min = std::min(pinned_min, CriterionValue(element));
    }
  }

  PhaseSummary summary{phase_, 0, 0.0, 0.0, 0.0, 0};
  double best_min = CriterionMinimum();
  double window_start_min = best_min;
  std::int64_t window_start = 0;
  // Sliding rule: the pick at which the best minimum last rose by the tolerance, and that value.
  double risen_min = best_min;
  std::int64_t risen_pick = 0;
  std::int64_t cycle_reverts = 0;
  bool cancelled = false;
  std::int64_t pick = 0;
  while (!selection_.empty() && pick < cap) {
    ++batch_;
    ChooseBatch();
    if (static_cast<std::int64_t>(picks_.size()) > cap - pick) picks_.resize(cap - pick);
    const auto batch_size = static_cast<std::int64_t>(picks_.size());
    if (batch_size == 1) {
      RunPick(work_[picks_[0]]);
    } else {
      context_.pool.ParallelFor(batch_size, 4, [&](std::int64_t begin, std::int64_t end) {
        for (std::int64_t i = begin; i < end; ++i) RunPick(work_[picks_[i]]);
      });
    }
    cycle_reverts += FinishBatch();
    const std::int64_t picks_before = pick;
    pick += batch_size;
    const double current_min = CriterionMinimum();
    if (current_min > best_min) {
      best_min = current_min;
      undo_since_best_.clear();
    }
    // Once the minimum is an element no pick can change, no later state can be a new best, and
    // the best state is handed on (RestoreBest): every further pick would be undone. Stopping
    // here hands on the same state, bit for bit, that either stop rule would, a window later.
    // On tire.vtk the rules ran 2,774 such picks after the 46th.
    const bool minimum_pinned = best_min >= pinned_min;
    // Stop rule: the best minimum rose by less than the tolerance over the last window of picks.
    bool stalled = false;
    if (sliding) {
      if (best_min - risen_min >= params_.sequential_improvement_tolerance) {
        risen_min = best_min;
        risen_pick = pick;
      }
      stalled = pick - risen_pick >= (window_in_rounds ? std::min(window, RoundsWindow()) : window);
    } else if (pick - window_start >= window) {
      stalled = best_min - window_start_min < params_.sequential_improvement_tolerance;
      window_start_min = best_min;
      window_start = pick;
    }
    const auto passed = [&](std::int64_t interval) {
      return pick / interval > picks_before / interval;
    };
    if (passed(params_.sequential_cycle) || stalled || minimum_pinned || pick == cap) {
      summary.reverted_nodes += cycle_reverts;
      context_.Report({phase_, pick, quality_min_.top_key(),
                       quality_sum_ / static_cast<double>(elements), 0, cycle_reverts,
                       context_.ElapsedSeconds(), false});
      cycle_reverts = 0;
    }
    if (passed(kCancelCheckInterval) && context_.Cancelled()) {
      cancelled = true;
      break;
    }
    if (stalled || minimum_pinned) break;
  }
  summary.reverted_nodes += cycle_reverts;
  summary.iterations = pick;
  RestoreBest();
  const SmoothingContext::Summary state = context_.Summarize();
  context_.FinishPhase(summary, state, phase_start);
  if (cancelled) return absl::CancelledError("smoothing cancelled during the sequential substep");
  return summary;
}

}  // namespace

std::int64_t SequentialBatchLimit(const SmoothingParams& params, const Mesh& mesh) {
  const std::int64_t limit =
      std::min(params.sequential_batch, mesh.element_count() / params.sequential_batch_elements);
  return limit >= std::min(kMinimumBatch, params.sequential_batch) ? limit : 1;
}

absl::StatusOr<PhaseSummary> RunSequential(SmoothingContext& context, SelectionCriterion criterion,
                                           SequentialStop stop) {
  return SequentialSubstep(context, criterion, stop).Run();
}

}  // namespace getme
