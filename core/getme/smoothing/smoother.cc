#include "getme/smoothing/smoother.h"

#include <algorithm>
#include <future>
#include <optional>
#include <utility>
#include <vector>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_join.h"
#include "getme/elements/vec3.h"
#include "getme/smoothing/element_passes_dispatch.h"
#include "getme/smoothing/laplace_smoother.h"
#include "getme/smoothing/layer_phase.h"
#include "getme/smoothing/polish.h"
#include "getme/smoothing/result_check.h"
#include "getme/smoothing/sequential_smoother.h"
#include "getme/smoothing/simultaneous_smoother.h"
#include "getme/smoothing/smoothing_context.h"
#include "getme/smoothing/untangle.h"

namespace getme {
namespace {

// "3 <adjective>elements, first: 4, 9, 12" for an error message.
std::string CountedElements(const MeshQuality& quality, absl::string_view adjective) {
  std::vector<std::string> listed;
  for (ElementId e : quality.first_invalid) listed.push_back(absl::StrCat(e));
  return absl::StrCat(quality.invalid, " ", adjective, "element", quality.invalid == 1 ? "" : "s",
                      ", first: ", absl::StrJoin(listed, ", "));
}

absl::Status InvalidInput(const MeshQuality& quality) {
  return absl::FailedPreconditionError(
      absl::StrCat("the mesh has ", CountedElements(quality, "invalid (inverted or degenerate) "),
                   "; enable untangling or repair the mesh"));
}

// Plain Laplace is quality-unaware (a baseline): inverting elements is what it does, not an
// engine fault, but its result is still a broken mesh and is not handed out as one.
absl::Status PlainLaplaceInverted(const MeshQuality& after) {
  return absl::FailedPreconditionError(
      absl::StrCat("plain Laplace smoothing inverted ", CountedElements(after, ""),
                   "; it does not check validity: use smart-laplace or getme"));
}

// A sliding boundary with the polish (issue 15), after the held run has run to its end: the
// sequential substep with the sliding nodes free, which hands on the best state it saw (its start
// included, so q_min does not fall), then the polish, which never lowers the q_min it is given.
// So a sliding boundary never ends below the held one. Sliding from the start does not promise
// that: GETMe does not maximise q_min, and its substeps and the polish take other paths from the
// first move. Measured on the eight pinned thin-layer arteries, sliding from the start ended below
// the held run on three of them (up to 22 % below), and with the polish's tangential steps still on
// one (docs/boundary.md).
template <typename Record>
absl::Status RunSlidingStages(SmoothingContext& context, Record& record) {
  if (auto s = record(
          RunSequential(context, SelectionCriterion::kMeanRatio, SequentialStop::kHandOnToPolish));
      !s.ok()) {
    return s;
  }
  return record(RunPolish(context));
}

// The phases of `method` itself, after untangling.
template <typename Record>
absl::Status RunMethod(SmoothingContext& context, Method method, Record& record) {
  switch (method) {
    case Method::kSimultaneous:
      return record(RunSimultaneous(context, SimultaneousStop::kSettled));
    case Method::kSequential:
      return record(RunSequential(context, SelectionCriterion::kMeanRatio));
    case Method::kSmartLaplace:
      return record(RunSmartLaplace(context));
    case Method::kGetme:
    case Method::kWarpage: {
      // With the polish to follow, the simultaneous substep only has to bring q_mean near its
      // plateau: the polish climbs the rest faster (simultaneous_smoother.h).
      const bool polish = method == Method::kGetme && context.params.polish;
      // With the polish, a sliding boundary first runs the held run itself (RunSlidingStages).
      // Where no node slides (a file that fixes its whole boundary, say) the held run is the
      // whole run: stages run again for no sliding node would make `slide` differ from `fixed`.
      std::optional<SlidingNodesHeld> held;
      if (polish && context.params.slide_boundary &&
          std::find(context.sliding.begin(), context.sliding.end(), 1) != context.sliding.end()) {
        held.emplace(context);
      }
      if (auto s = record(RunSimultaneous(
              context, polish ? SimultaneousStop::kHandOnToPolish : SimultaneousStop::kSettled));
          !s.ok()) {
        return s;
      }
      // The polish's colouring, made beside the sequential substep where that substep leaves a
      // core idle, one pick at a time (polish.h says why). Beside batches it would be a third
      // thread on the pool's cores, whose batches wait for their slowest thread. The future's
      // destructor waits for it if the substep fails.
      std::future<PolishColouring> colouring;
      if (polish && context.pool.thread_count() > 1 &&
          SequentialBatchLimit(context.params, context.mesh) == 1) {
        colouring = std::async(std::launch::async, [&context] {
          return MakePolishColouring(context.mesh, context.movable);
        });
      }
      if (auto s = record(RunSequential(
              context, SelectionCriterion::kMeanRatio,
              polish ? SequentialStop::kHandOnToPolish : SequentialStop::kStalledWindow));
          !s.ok()) {
        return s;
      }
      if (method == Method::kWarpage) {
        return record(RunSequential(context, SelectionCriterion::kQualityGamma));
      }
      // Issue 14, item 1: raise q_mean to the global optimiser's level after GETMe, without
      // lowering q_min (polish.h).
      if (!polish) return absl::OkStatus();
      if (auto s = record(RunPolish(context, colouring.valid()
                                                 ? std::optional<PolishColouring>(colouring.get())
                                                 : std::nullopt));
          !s.ok()) {
        return s;
      }
      if (!held.has_value()) return absl::OkStatus();
      held.reset();
      return RunSlidingStages(context, record);
    }
    case Method::kLaplace:
      break;
  }
  return absl::OkStatus();
}

absl::Status RunPhases(SmoothingContext& context, SmoothingResult& result) {
  auto record = [&](absl::StatusOr<PhaseSummary> phase) -> absl::Status {
    if (!phase.ok()) return phase.status();
    result.phases.push_back(*phase);
    switch (phase->phase) {
      case Phase::kUntangle:
        result.iterations_untangle += phase->iterations;
        break;
      case Phase::kSimultaneous:
        result.iterations_simultaneous += phase->iterations;
        break;
      case Phase::kSequential:
      case Phase::kWarpage:
        result.iterations_sequential += phase->iterations;
        break;
      case Phase::kSmartLaplace:
      case Phase::kLaplace:
        result.iterations_laplace += phase->iterations;
        break;
      case Phase::kPolish:
        result.iterations_polish += phase->iterations;
        break;
      case Phase::kLayers:
        result.iterations_layers += phase->iterations;
        break;
    }
    return absl::OkStatus();
  };

  const Method method = context.params.method;
  // Plain Laplace is quality-unaware and may itself invert elements: it runs on any input.
  if (method == Method::kLaplace) return record(RunLaplace(context));

  if (result.before.invalid > 0) {
    if (!context.params.untangle) return InvalidInput(result.before);
    if (auto s = record(RunUntangle(context)); !s.ok()) return s;
  }
  // Kept layers (layer_phase.h): columns straightened before the method, and with a sliding
  // boundary moved with their wall nodes after it, where the rest of the mesh has settled.
  const bool keep_layers = context.params.keep_layers && context.slide != nullptr &&
                           context.slide->kept_layers() != nullptr;
  if (keep_layers) {
    if (auto s = record(RunLayers(context, LayerStage::kStraighten)); !s.ok()) return s;
  }
  if (auto s = RunMethod(context, method, record); !s.ok()) return s;
  if (keep_layers && context.params.slide_boundary) {
    return record(RunLayers(context, LayerStage::kFollowWall));
  }
  return absl::OkStatus();
}

}  // namespace

absl::StatusOr<SmoothingResult> Smooth(Mesh& mesh, const SmoothingParams& params,
                                       const ProgressCallback& progress,
                                       const CancellationToken* cancel,
                                       const BoundarySlide* slide) {
  if (auto status = params.Validate(); !status.ok()) return status;
  const absl::StatusOr<const ElementPasses*> passes = ElementPassesFor(params.kernel_lanes);
  if (!passes.ok()) return passes.status();
  if ((params.slide_boundary || params.keep_layers) && slide == nullptr) {
    return absl::InvalidArgumentError(
        absl::StrCat(params.slide_boundary ? "slide_boundary" : "keep_layers",
                     " is set but no BoundarySlide was given: build one from the input mesh "
                     "(surface::SurfaceSlide) and pass it to Smooth"));
  }
  if (params.keep_layers && slide->kept_layers() == nullptr) {
    return absl::InvalidArgumentError(
        "keep_layers is set but the BoundarySlide given describes no layers: build it with kept "
        "layers (surface::SlideOptions::keep_layers)");
  }
  if (!params.slide_boundary && !params.keep_layers) slide = nullptr;
  ThreadPool pool(params.threads);
  SmoothingResult result;
  result.threads = pool.thread_count();
  result.kernel_lanes = (*passes)->lanes;
  SmoothingContext context(mesh, params, pool, progress, cancel, slide);
  // The measures MeasureElements takes one element at a time, with the same bits from the vector
  // passes: the context has just taken every element's mean ratio.
  result.before = SummarizeMeasures(mesh, MeasuresFrom(context.quality, context.Warpages()), pool);
  // Untangling with untangle_free_boundary may move boundary nodes of invalid elements: the check
  // must expect exactly those to move, and no other immovable node.
  const bool untangles =
      params.method != Method::kLaplace && params.untangle && result.before.invalid > 0;
  // Kept columns move in the layer phase only, their boundary nodes on the input's surface.
  std::vector<std::uint8_t> movable = context.movable;
  std::vector<std::uint8_t> sliding = context.sliding;
  for (NodeId node = 0; node < mesh.node_count(); ++node) {
    if (!context.column_movable[node]) continue;
    movable[node] = 1;
    if (params.fix_boundary && mesh.is_boundary(node)) sliding[node] = 1;
  }
  const ResultCheck check(
      mesh, untangles ? UntangleMovable(mesh, params, movable, context.quality) : movable, slide,
      sliding);
  // The sliding nodes' input positions, to count the ones that moved.
  std::vector<std::pair<NodeId, Vec3>> slide_start;
  if (slide != nullptr) {
    for (NodeId node = 0; node < mesh.node_count(); ++node) {
      if (sliding[node]) {
        slide_start.emplace_back(node, Vec3(mesh.x()[node], mesh.y()[node], mesh.z()[node]));
      }
    }
  }
  if (auto status = RunPhases(context, result); !status.ok()) return status;
  if (slide != nullptr) {
    BoundarySlideSummary summary;
    summary.sliding_nodes = static_cast<std::int64_t>(slide_start.size());
    if (params.keep_layers && slide->kept_layers() != nullptr) {
      summary.layer_nodes = static_cast<std::int64_t>(slide->kept_layers()->nodes.size());
    }
    for (const auto& [node, start] : slide_start) {
      const Vec3 now(mesh.x()[node], mesh.y()[node], mesh.z()[node]);
      if (now != start) ++summary.slid_nodes;
      summary.max_distance = std::max(summary.max_distance, slide->DistanceToSurface(node, now));
    }
    result.boundary_slide = summary;
  }
  // Fresh mean ratios of the final state from the vector passes: the phases keep
  // context.quality up to date, but a measure reported to the user is taken anew.
  context.RefreshQuality();
  result.after_elements = MeasuresFrom(context.quality, context.Warpages());
  result.after = SummarizeMeasures(mesh, result.after_elements, pool);
  result.seconds = context.ElapsedSeconds();
  if (params.method == Method::kLaplace && result.after.invalid > 0) {
    return PlainLaplaceInverted(result.after);
  }
  if (auto status = check.Check(mesh, result.after); !status.ok()) return status;
  return result;
}

}  // namespace getme
