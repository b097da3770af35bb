#pragma once

#include <cstdint>
#include <optional>

#include "getme/smoothing/smoothing_params.h"

namespace getme::cmdline {

// The flags that select the engine's parameters, as `getme smooth` spells them: --method,
// --threads, --max-iterations, --boundary (and its spelling --free-boundary), --feature-angle,
// --literal, --no-untangle, --untangle-boundary, --no-polish, --sequential-batch. getme-bench takes
// a subset with the same meaning.
struct SmoothingFlags {
  Method method = Method::kGetme;
  int threads = 0;  // 0 = all cores
  std::optional<std::int64_t> max_iterations;
  bool free_boundary = false;
  bool slide_boundary = false;  // --boundary slide (issue 15)
  double feature_angle_degrees = 45.0;
  bool keep_layers = false;        // --keep-layers (issue 15)
  bool literal = false;            // the paper's literal algorithm, safeguards off
  bool no_untangle = false;        // refuse invalid input instead of untangling it
  bool no_polish = false;          // end --method getme after the sequential substep
  bool untangle_boundary = false;  // boundary nodes of invalid elements may move while untangling
  // --sequential-batch N: sequential picks per batch (1: one at a time, as the paper); 0: the
  // engine's default
  std::int64_t sequential_batch = 0;
};

// The engine parameters the flags select: method, threads, fix_boundary, untangle, polish, the
// literal algorithm, and the iteration cap applied to every phase (polish: sweeps).
SmoothingParams ToSmoothingParams(const SmoothingFlags& flags);

}  // namespace getme::cmdline
