#pragma once

#include <atomic>
#include <cstddef>
#include <functional>

#include "absl/time/time.h"
#include "getme/v1/smoother.pb.h"
#include "remote/mesh_chunks.h"

namespace getme::remote {

// How one call is made.
struct CallOptions {
  // The call fails with DEADLINE_EXCEEDED after this long (the server then stops the job too).
  absl::Duration timeout = absl::InfiniteDuration();
  // Polled while the call runs: once true, the call is cancelled (ClientContext::TryCancel), the
  // server stops the job within one iteration, and the call returns CANCELLED. A plain atomic
  // flag, so a signal handler may set it.
  const std::atomic<bool>* cancel = nullptr;
  // Upload chunk size (MeshChunk messages).
  std::size_t chunk_bytes = kDefaultChunkBytes;
};

// What a smoothing job is asked to do.
struct SmoothJobOptions {
  v1::SmoothingParameters parameters;
  v1::ResultOptions result_options;
};

// Receives each progress event as it arrives, in order.
using ProgressHandler = std::function<void(const v1::ProgressEvent&)>;

}  // namespace getme::remote
