#include "cmdline/smoothing_flags.h"

namespace getme::cmdline {

SmoothingParams ToSmoothingParams(const SmoothingFlags& flags) {
  SmoothingParams params;
  params.method = flags.method;
  params.threads = flags.threads;
  params.fix_boundary = !flags.free_boundary;
  params.slide_boundary = flags.slide_boundary;
  params.feature_angle_degrees = flags.feature_angle_degrees;
  params.keep_layers = flags.keep_layers;
  params.untangle = !flags.no_untangle;
  if (flags.literal) params.UseLiteralPaperAlgorithm();
  if (flags.no_polish) params.polish = false;
  if (flags.sequential_batch > 0) params.sequential_batch = flags.sequential_batch;
  params.untangle_free_boundary = flags.untangle_boundary;
  if (flags.max_iterations) {
    params.untangle_max_iterations = *flags.max_iterations;
    params.simultaneous_max_iterations = *flags.max_iterations;
    params.sequential_max_iterations = *flags.max_iterations;
    params.laplace_max_iterations = *flags.max_iterations;
    params.polish_max_sweeps = *flags.max_iterations;
    params.polish_worst_max_sweeps = *flags.max_iterations;
    params.polish_cluster_max_rounds = *flags.max_iterations;
  }
  return params;
}

}  // namespace getme::cmdline
