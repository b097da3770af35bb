#pragma once

#include <mutex>
#include <string>

#include "absl/container/flat_hash_map.h"
#include "absl/status/statusor.h"
#include "absl/strings/string_view.h"

namespace getme::server {

// The client host of a gRPC peer ("ipv4:10.0.0.7:53012" → "10.0.0.7", "ipv6:[::1]:53012" →
// "[::1]"); other peer kinds (unix sockets) are returned unchanged.
std::string ClientHost(absl::string_view peer);

// Bounds the open streaming calls (Smooth, SubmitJob, WatchJob, GetResult, EvaluateQuality) per
// client host (--max_streams_per_client). Each holds a handler thread and, while uploading, a
// partial mesh, so one client opening thousands of them could starve the others. Keyed by host,
// not connection: a client gets around a per-connection cap by opening more connections.
class ClientStreamLimiter {
 public:
  explicit ClientStreamLimiter(int max_per_client) : max_per_client_(max_per_client) {}

  // Releases its stream when destroyed.
  class Slot {
   public:
    Slot(Slot&& other) noexcept : limiter_(other.limiter_), host_(std::move(other.host_)) {
      other.limiter_ = nullptr;
    }
    Slot& operator=(Slot&&) = delete;
    ~Slot();

   private:
    friend class ClientStreamLimiter;
    Slot(ClientStreamLimiter* limiter, std::string host)
        : limiter_(limiter), host_(std::move(host)) {}
    ClientStreamLimiter* limiter_;
    std::string host_;
  };

  // RESOURCE_EXHAUSTED naming the host and the limit when its streams are all in use.
  absl::StatusOr<Slot> Acquire(absl::string_view peer);
  int OpenStreams(absl::string_view peer) const;

 private:
  void Release(const std::string& host);

  const int max_per_client_;
  mutable std::mutex mutex_;
  absl::flat_hash_map<std::string, int> open_;  // hosts with at least one open stream
};

}  // namespace getme::server
