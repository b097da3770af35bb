#pragma once

#include <array>
#include <cstdint>
#include <string_view>

#include "absl/status/status.h"
#include "absl/status/statusor.h"
#include "getme/elements/element_type.h"

namespace getme {

enum class Method {
  kGetme,         // simultaneous, sequential (Sec. 3.3), then the polish — the default
  kSimultaneous,  // Sec. 3.1 only
  kSequential,    // Sec. 3.2 only
  kWarpage,       // GETMe, then the sequential substep selecting by q_γ (Sec. 4.4)
  kSmartLaplace,  // baseline of Sec. 4 (docs/paper-notes.md#smart-laplace)
  kLaplace,       // plain Laplace: may invert elements, reported as invalid
};

const char* MethodName(Method method);
absl::StatusOr<Method> ParseMethod(std::string_view name);

// Per-element-type values, indexed by TypeIndex(type): tet, hex, pyramid, prism.
using PerType = std::array<double, kElementTypeCount>;

// Every engine parameter, with the paper's Section 4 defaults. Validate() names the first field
// that is out of range.
struct SmoothingParams {
  Method method = Method::kGetme;

  // --- Simultaneous substep (Sec. 3.1; defaults Sec. 4) ---
  // σ_j = σ_min + (σ_max − σ_min)(1 − q(E_j)), Step 1.1.
  PerType simultaneous_sigma_min = {0.77, 2.57, 1.86, 1.59};
  PerType simultaneous_sigma_max = {0.84, 3.45, 1.86, 1.59};
  double simultaneous_rho = 2.0 / 3.0;  // relaxation ρ, eq. (11), Step 1.2
  double simultaneous_eta = 0.25;       // weight exponent η of w_j = (1 − q)^η, Step 2.1
  // Stop when q_mean of two consecutive iterations differs by less than this (Sec. 4).
  double simultaneous_tolerance = 1e-6;
  std::int64_t simultaneous_max_iterations = 1000;
  // Beyond the paper, only when the polish follows (SimultaneousStop::kHandOnToPolish): hand on
  // once q_mean rose by less than simultaneous_handoff_gain per iteration, averaged over the last
  // simultaneous_handoff_window iterations (0: never; the paper's rule alone). Measured in
  // docs/quality.md: on cub_wedge_like it stops after 16 of 144 iterations.
  std::int64_t simultaneous_handoff_window = 5;
  double simultaneous_handoff_gain = 1e-4;
  // Safeguard (docs/thin-layers.md): before reverting a node of an invalid element to its old
  // position (Step 3.2), try moving it back only part of the way, halving its step up to this
  // many times. 0 gives the paper's literal Step 3.
  int simultaneous_backtracking_steps = 4;

  // --- Sequential substep (Sec. 3.2; defaults Sec. 4) ---
  PerType sequential_sigma = {0.81, 2.74, 1.82, 0.85};
  double sequential_rho = 0.01;
  double penalty_invalid = 0.01;   // Δπ_i: the transformation produced an invalid element
  double penalty_repeat = 0.0005;  // Δπ_r: the same element was picked in the previous step
  double penalty_success = 0.01;   // Δπ_s: subtracted after a successful transformation
  // The paper leaves the stop rule open (Sec. 3.2, Step 4;
  // docs/paper-notes.md#sequential-stop-rule). Here: stop when the best q_min of the phase rose by
  // less than sequential_improvement_tolerance over the last sequential_stall_iterations picks
  // (0: max(1000, elements)), or at sequential_max_iterations picks (0: 50 × elements). The
  // best-q_min state seen is handed on: q_min oscillates as neighbours take turns being the worst
  // element. Measured trade-offs in docs/quality.md.
  std::int64_t sequential_stall_iterations = 0;
  std::int64_t sequential_max_iterations = 0;
  double sequential_improvement_tolerance = 1e-3;
  // With the polish on (SequentialStop::kHandOnToPolish): stop once the last this many picks
  // (0: max(1000, min(elements / 4, 8 × distinct elements picked so far))) raised the best q_min
  // by less than the tolerance above.
  std::int64_t sequential_handoff_window = 0;
  // Safeguard (docs/quality.md): a step that would make a neighbour invalid is retried at half
  // its length up to this many times before it counts as reverted (Step 3.1). 0 = the paper.
  int sequential_backtracking_steps = 10;
  // Safeguard (docs/quality.md): when a step is reverted because it would invert a neighbour, that
  // neighbour is transformed next. The mean ratio averages node tetrahedra, so an element with one
  // nearly flat node tetrahedron can block its neighbours while never being the worst.
  bool sequential_transform_blockers = true;
  // Beyond the paper (issue 16, item 1): picks per batch. A batch takes the elements in key order
  // (criterion + π, canonical tie-break), skipping any that shares an element around its movable
  // nodes with one taken before it, so the picks of a batch are independent: they are evaluated in
  // parallel and applied in batch order, and the result is the same for every thread count. 1 is
  // the paper's one pick at a time (docs/parallel-sequential.md has what a batch changes and its
  // measured quality).
  std::int64_t sequential_batch = 128;
  // ...and at most one pick per this many elements; where that allows fewer than 16 picks (below
  // 262,144 elements by default), one pick at a time. Batches pay where picks are many (a million
  // elements take a million picks); on smaller meshes their overhead costs more than a second
  // thread gains, and a batch is a larger share of the mesh's worst elements.
  std::int64_t sequential_batch_elements = 16384;
  // Only elements whose key is at most this above the lowest key join a batch: where a few
  // elements lag behind the rest the batch shrinks toward the serial algorithm's single pick.
  double sequential_batch_band = 0.01;
  // Picks between two progress events / cancellation checks / q_mean evaluations (Sec. 3.2,
  // last paragraph: q_mean is evaluated only every prescribed number of iterations).
  std::int64_t sequential_cycle = 1000;

  // --- Warpage variant (Sec. 4.4) ---
  double gamma = 0.25;  // γ of q_γ = min(q, γ(1 − w/2))

  // --- Laplace baselines (Secs. 1 and 4; docs/paper-notes.md#smart-laplace) ---
  double laplace_tolerance = 1e-6;
  std::int64_t laplace_max_iterations = 1000;

  // --- Untangling (goes beyond the paper, which requires a valid input; docs/untangling.md) ---
  bool untangle = true;
  // Sweeps of the node-local Newton untangler over the free nodes (untangle.h); it stops earlier
  // when no element is invalid or a sweep makes no progress.
  std::int64_t untangle_max_iterations = 200;
  // With fix_boundary, a boundary node never moves, so an inverted corner whose node tetrahedron
  // lies on the boundary cannot be repaired (the untangler then fails with a proof). This lets the
  // untangler move the boundary nodes of the elements that are invalid when it starts; nodes the
  // input marked fixed still never move, and the smoothing after untangling keeps the boundary
  // fixed again. Off by default: it changes the boundary, which the paper (Sec. 3) keeps.
  // Requires untangle.
  bool untangle_free_boundary = false;

  // --- Polish (goes beyond the paper; issue 14, item 1) ---
  // GETMe's fixed point is not the optimum of q_mean (the paper's tables put it ~0.01 below
  // Mesquite's global optimiser), so Method::kGetme can end with node-local damped Newton steps
  // on the inverse mean ratio of each free node's elements (mean_ratio_derivatives.h), in
  // independent sets of a node colouring so any thread count gives the same bits
  // (core/getme/smoothing/polish.h). A step is kept only if it lowers the node's cost, inverts
  // nothing and does not lower the smallest mean ratio of the node's elements: q_min never falls.
  bool polish = true;
  // Stop when the q_mean still to gain, extrapolated from the gains of the last two sweeps over
  // all free nodes (they shrink about geometrically), is below this; or when a sweep gains no
  // q_mean at all...
  double polish_tolerance = 1e-4;
  // The same rule where the mean stage's end is the polish's result (no worst-cluster stage
  // starts from it, polish.cc says why they differ): q_mean given up for time, against the 0.002
  // of Mesquite's q_mean issue 14 allows. Measured in docs/quality.md#polish.
  double polish_final_tolerance = 3e-4;
  // ...or after this many sweeps: a bound on the time, not the rule that normally stops it.
  std::int64_t polish_max_sweeps = 200;
  // A node whose Newton step would lower its cost by less than this fraction of it counts as
  // converged and stays (and a node is tried again only once something around it moved).
  double polish_node_tolerance = 1e-6;
  // Worst-element stage, before the mean stage: the same node-local Newton steps on Σ c(E)^p with
  // p = polish_worst_exponent (0 or 1: no such stage), which weights the worst elements most and
  // so lifts q_min, with no floor while it runs (a node may trade one element's quality for a
  // worse neighbour's, which a max-min step cannot) and its best-q_min state handed on. Stops
  // when the q_min still to gain, extrapolated as in the mean stage, is below
  // polish_worst_tolerance × q_min, after two sweeps without a new best, or after
  // polish_worst_max_sweeps.
  double polish_worst_exponent = 6.0;
  double polish_worst_tolerance = 1e-3;
  std::int64_t polish_worst_max_sweeps = 100;
  // Worst-cluster stage (worst_cluster.h), after the mean stage: all free nodes of the elements
  // within polish_cluster_band (relative) of q_min move together, by L-BFGS on
  // Σ (q_min / q_e)^polish_cluster_exponent over every element around them, in rounds while q_min
  // rises by more than polish_cluster_tolerance (relative), at most polish_cluster_max_rounds, each
  // of at most polish_cluster_iterations iterations; the mean stage then runs again above the new
  // q_min. It runs only where q_min < polish_cluster_trigger × q_mean, i.e. where the worst
  // elements lag far behind the rest (pinned thin boundary layers: docs/thin-layers.md); 0 turns
  // it off. Measured in docs/quality.md#polish. A stalled round is tried once more with twice the
  // band; when that stalls too, a round takes up to polish_cluster_ascent_iterations
  // steepest-ascent steps of the minimum itself (0: none, and the stage ends), and where that
  // gains more than polish_cluster_tolerance the L-BFGS rounds go on from its end.
  double polish_cluster_trigger = 1.0 / 3.0;
  double polish_cluster_band = 0.25;
  double polish_cluster_exponent = 20.0;
  double polish_cluster_tolerance = 2e-3;
  std::int64_t polish_cluster_max_rounds = 30;
  std::int64_t polish_cluster_iterations = 200;
  std::int64_t polish_cluster_ascent_iterations = 200;
  // Each node first tries its Newton step times this factor (successive over-relaxation), then
  // the plain step, then halvings. Measured in docs/quality.md#polish: on the thin-layer artery
  // meshes 1.8 needs 17 sweeps where 1.0 needs 97, for a higher q_mean. 1 = plain Gauss–Seidel.
  double polish_over_relaxation = 1.8;
  // Halvings of a rejected Newton (or gradient) step before the node stays where it is.
  int polish_backtracking_steps = 10;

  // --- Nodes and threads ---
  bool fix_boundary = true;  // Sec. 3: boundary nodes stay fixed
  // Issue 15: boundary nodes slide on the input's own surface instead (surface and feature nodes;
  // corners stay). Smooth() then needs a BoundarySlide built from the input (boundary_slide.h;
  // the CLI builds it with surface/). Requires fix_boundary: a free boundary has nothing to slide
  // on. Off by default, as the paper keeps the boundary (Sec. 3).
  bool slide_boundary = false;
  // The angle between two boundary faces' normals above which their edge is a feature edge, along
  // which nodes slide only (docs/boundary.md: why 45). Used by whoever builds the BoundarySlide.
  double feature_angle_degrees = 45.0;
  // Issue 15: nodes in boundary-layer columns (prisms or hexahedra stacked on a wall face) keep
  // their input distance from the wall, so every layer keeps its height while its skew is
  // smoothed away (docs/boundary.md#layers). The BoundarySlide given to Smooth() finds the
  // columns and holds the nodes (surface/). Requires fix_boundary (held or sliding): a free
  // boundary moves the wall the heights are measured from.
  bool keep_layers = false;
  int threads = 0;  // 0 = hardware concurrency; results do not depend on it
  // Issue 16: doubles per vector in the whole-mesh element passes (element_passes.h): 0 = the
  // widest this machine runs (8 with AVX-512, 4 with AVX2, else 2), or 2, 4 or 8 exactly. Results
  // do not depend on it, so it is a benchmark's and a test's knob, not on the wire.
  int kernel_lanes = 0;

  absl::Status Validate() const;

  // Switches off everything that goes beyond the paper's Sections 3.1–3.3 (simultaneous and
  // sequential backtracking, transforming blocking neighbours, batches of sequential picks, the
  // polish and with it the simultaneous hand-on rule), for comparison with the literal algorithm.
  // Untangling and the sequential stop rule are unaffected.
  void UseLiteralPaperAlgorithm() {
    simultaneous_backtracking_steps = 0;
    sequential_backtracking_steps = 0;
    sequential_transform_blockers = false;
    sequential_batch = 1;
    polish = false;
  }
};

}  // namespace getme
