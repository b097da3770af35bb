#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <string_view>

namespace getme {

// kPolish goes beyond the paper (polish.h); the others are its phases and baselines.
enum class Phase {
  kUntangle,
  kSimultaneous,
  kSequential,
  kWarpage,
  kSmartLaplace,
  kLaplace,
  kPolish,
  kLayers,  // kept boundary layers: whole columns move (layer_phase.h, issue 15)
};

const char* PhaseName(Phase phase);

// One event per iteration of a phase (per sequential_cycle picks in the sequential phases, per
// sweep over the free nodes in the polish),
// the last one of each phase marked final. The service streams exactly these.
struct ProgressEvent {
  Phase phase = Phase::kSimultaneous;
  std::int64_t iteration = 0;  // iterations (sequential: picks) done in this phase so far
  double q_min = 0.0;
  double q_mean = 0.0;
  std::int64_t invalid = 0;         // invalid elements now (untangle and plain Laplace)
  std::int64_t reverted_nodes = 0;  // node reverts in this iteration (sequential: this cycle)
  double elapsed_seconds = 0.0;     // since the smoothing call started
  bool phase_done = false;
};

using ProgressCallback = std::function<void(const ProgressEvent&)>;

// Cooperative cancellation: smoothers check it at least once per iteration (sequential: every
// few hundred picks) and return CANCELLED with the mesh left in a valid state.
class CancellationToken {
 public:
  void Cancel() { cancelled_.store(true, std::memory_order_relaxed); }
  bool cancelled() const { return cancelled_.load(std::memory_order_relaxed); }

 private:
  std::atomic<bool> cancelled_{false};
};

}  // namespace getme
