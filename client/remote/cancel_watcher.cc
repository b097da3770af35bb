#include "remote/cancel_watcher.h"

namespace getme::remote {

CancelWatcher::CancelWatcher(grpc::ClientContext& context, const std::atomic<bool>* flag) {
  if (flag == nullptr) return;
  thread_ = std::thread([this, &context, flag] {
    std::unique_lock lock(mutex_);
    while (!stopping_) {
      if (flag->load()) {
        fired_.store(true);
        context.TryCancel();
        return;
      }
      stop_requested_.wait_for(lock, kPollInterval);
    }
  });
}

CancelWatcher::~CancelWatcher() {
  if (!thread_.joinable()) return;
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  stop_requested_.notify_all();
  thread_.join();
}

}  // namespace getme::remote
