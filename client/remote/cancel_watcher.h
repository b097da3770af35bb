#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <thread>

#include "grpcpp/client_context.h"

namespace getme::remote {

// Cancels a call when a flag turns true. A blocking stream Read cannot look at a flag itself (it
// may wait minutes for a queued job's first event), so a small thread polls the flag and calls
// ClientContext::TryCancel, which is thread-safe and makes the pending Read return. No thread
// when there is no flag.
class CancelWatcher {
 public:
  CancelWatcher(grpc::ClientContext& context, const std::atomic<bool>* flag);
  ~CancelWatcher();
  CancelWatcher(const CancelWatcher&) = delete;
  CancelWatcher& operator=(const CancelWatcher&) = delete;

  // Whether the flag cancelled the call.
  bool fired() const { return fired_.load(); }

 private:
  static constexpr std::chrono::milliseconds kPollInterval{20};

  std::mutex mutex_;
  std::condition_variable stop_requested_;
  bool stopping_ = false;
  std::atomic<bool> fired_{false};
  std::thread thread_;
};

}  // namespace getme::remote
