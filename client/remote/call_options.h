#pragma once

#include <atomic>
#include <cstddef>
#include <functional>

#include "absl/time/time.h"
#include "getme/v1/smoother.pb.h"
#include "getme_wire/mesh_chunker.h"

namespace getme::remote {

// Retries of a call that failed with UNAVAILABLE (the server is down, restarting or draining),
// only where the server cannot have kept anything from the failed attempt, so a job never runs
// twice: reads (GetJob, ListJobs, CancelJob, EvaluateQuality) always; WatchJob and GetResult when
// nothing had arrived yet; Smooth when nothing had arrived yet (a Smooth job ends with its call);
// SubmitJob only when the upload had not been sent completely (the server queues a job only once
// it has read the whole upload). Waits initial_backoff, doubling up to max_backoff, in between;
// the CallOptions timeout covers all attempts.
struct RetryPolicy {
  int max_attempts = 4;  // 1 = no retries; the default waits 0.25 + 0.5 + 1 s in all
  absl::Duration initial_backoff = absl::Milliseconds(250);
  absl::Duration max_backoff = absl::Seconds(2);
};

// How one call is made.
struct CallOptions {
  // The call fails with DEADLINE_EXCEEDED after this long (the server then stops the job too).
  absl::Duration timeout = absl::InfiniteDuration();
  // Polled while the call runs: once true, the call is cancelled (ClientContext::TryCancel), the
  // server stops the job within one iteration, and the call returns CANCELLED. A plain atomic
  // flag, so a signal handler may set it.
  const std::atomic<bool>* cancel = nullptr;
  // Upload chunk size (MeshChunk messages).
  std::size_t chunk_bytes = wire::kDefaultChunkBytes;
  RetryPolicy retry;
};

// What a smoothing job is asked to do.
struct SmoothJobOptions {
  v1::SmoothingParameters parameters;
  v1::ResultOptions result_options;
};

// Receives each progress event as it arrives, in order.
using ProgressHandler = std::function<void(const v1::ProgressEvent&)>;

}  // namespace getme::remote
