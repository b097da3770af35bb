#pragma once

#include <condition_variable>
#include <deque>
#include <memory>
#include <mutex>
#include <optional>
#include <vector>

#include "absl/time/time.h"
#include "getme/v1/smoother.pb.h"
#include "getme_server/job_handle.h"

namespace getme::server {

// Fans a job's progress events out to any number of watchers without ever blocking the job:
// each watcher has its own mailbox. Intermediate events are throttled per watcher to one per
// `interval` (a newer one replaces a waiting older one), and a watcher that falls far behind
// loses its oldest intermediate events; phase_done events and the final event are always
// delivered, in order.
class ProgressFanout {
 public:
  class Watcher;
  using NextResult = EventSource::NextResult;

  explicit ProgressFanout(absl::Duration interval) : interval_(interval) {}

  // Called by the job (one thread at a time). The event marked `final` closes the fan-out.
  void Publish(const v1::ProgressEvent& event);
  // A new watcher; it starts with the latest event published so far (if any).
  std::shared_ptr<Watcher> Watch();

  class Watcher : public EventSource {
   public:
    NextResult Next(absl::Duration timeout, v1::ProgressEvent& event) override;

   private:
    friend class ProgressFanout;
    explicit Watcher(ProgressFanout* fanout) : fanout_(fanout) {}
    void Offer(const v1::ProgressEvent& event, absl::Duration interval);  // fanout mutex held

    ProgressFanout* fanout_;
    std::deque<v1::ProgressEvent> pending_;
    std::optional<absl::Time> last_intermediate_;
    bool final_delivered_ = false;
  };

 private:
  // Bounds a stalled watcher's mailbox; older intermediate events are dropped first.
  static constexpr std::size_t kMaxPending = 4096;

  const absl::Duration interval_;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::vector<std::weak_ptr<Watcher>> watchers_;
  std::optional<v1::ProgressEvent> latest_;
};

}  // namespace getme::server
