#include "getme_server/job_trace.h"

namespace getme::server {

std::uint64_t JobTrace::CountElementIterations(const v1::ProgressEvent& event) const {
  if (event.final()) return 0;
  const bool same_phase = latest_.has_value() && latest_->phase() == event.phase() &&
                          !latest_->phase_done() && !latest_->final();
  const std::int64_t before = same_phase ? latest_->iteration() : 0;
  if (event.iteration() <= before) return 0;
  const bool picks = event.phase() == v1::PHASE_SEQUENTIAL || event.phase() == v1::PHASE_WARPAGE;
  return static_cast<std::uint64_t>(event.iteration() - before) * (picks ? 1 : elements_);
}

std::uint64_t JobTrace::Record(const v1::ProgressEvent& event) {
  const std::uint64_t count = CountElementIterations(event);
  element_iterations_ += count;
  latest_ = event;
  const bool must_keep = event.phase_done() || event.final();
  if (!must_keep && event.sequence() % stride_ != 0) return count;
  events_.push_back(event);
  if (events_.size() < kMaxEvents) return count;
  // Full: keep every other intermediate event from now on, and thin the past to match.
  stride_ *= 2;
  std::erase_if(events_, [this](const v1::ProgressEvent& e) {
    return !e.phase_done() && !e.final() && e.sequence() % stride_ != 0;
  });
  return count;
}

}  // namespace getme::server
