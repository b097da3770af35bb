#include "getme_server/progress_fanout.h"

#include <algorithm>
#include <chrono>

#include "absl/time/clock.h"

namespace getme::server {
namespace {

bool MustDeliver(const v1::ProgressEvent& event) { return event.phase_done() || event.final(); }

}  // namespace

void ProgressFanout::Watcher::Offer(const v1::ProgressEvent& event, absl::Duration interval) {
  if (!MustDeliver(event)) {
    const absl::Time now = absl::Now();
    const bool throttled = last_intermediate_.has_value() && now - *last_intermediate_ < interval;
    if (throttled) {
      // Keep only the newest of the events that arrive within one interval.
      if (!pending_.empty() && !MustDeliver(pending_.back())) pending_.back() = event;
      return;
    }
    last_intermediate_ = now;
  }
  pending_.push_back(event);
  if (pending_.size() > kMaxPending) {
    auto oldest_intermediate = std::find_if(pending_.begin(), pending_.end(),
                                            [](const auto& e) { return !MustDeliver(e); });
    if (oldest_intermediate != pending_.end()) pending_.erase(oldest_intermediate);
  }
}

void ProgressFanout::Publish(const v1::ProgressEvent& event) {
  {
    std::lock_guard lock(mutex_);
    latest_ = event;
    std::erase_if(watchers_, [](const auto& w) { return w.expired(); });
    for (const auto& weak : watchers_) {
      if (auto watcher = weak.lock()) watcher->Offer(event, interval_);
    }
  }
  changed_.notify_all();
}

std::shared_ptr<ProgressFanout::Watcher> ProgressFanout::Watch() {
  std::shared_ptr<Watcher> watcher(new Watcher(this));
  std::lock_guard lock(mutex_);
  if (latest_.has_value()) watcher->pending_.push_back(*latest_);
  if (!latest_.has_value() || !latest_->final()) watchers_.push_back(watcher);
  return watcher;
}

ProgressFanout::NextResult ProgressFanout::Watcher::Next(absl::Duration timeout,
                                                         v1::ProgressEvent& event) {
  std::unique_lock lock(fanout_->mutex_);
  if (final_delivered_) return NextResult::kEnded;
  const bool ready = fanout_->changed_.wait_for(lock, absl::ToChronoNanoseconds(timeout),
                                                [this] { return !pending_.empty(); });
  if (!ready) return NextResult::kTimeout;
  event = std::move(pending_.front());
  pending_.pop_front();
  if (event.final()) final_delivered_ = true;
  return NextResult::kEvent;
}

}  // namespace getme::server
