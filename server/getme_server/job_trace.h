#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "getme/v1/smoother.pb.h"

namespace getme::server {

// What a job keeps of its progress events besides handing them to watchers: a thinned trace, so a
// dashboard opened late or reloaded can draw the whole run, and the count of element transforms
// (a simultaneous-type iteration transforms every element, a sequential pick one) for the
// job's rate and the server's metrics. Not thread-safe: the job calls it under its lock.
class JobTrace {
 public:
  // At most about this many events are kept: every phase_done and the final event, and an
  // evenly thinned share of the others.
  static constexpr std::size_t kMaxEvents = 1000;

  explicit JobTrace(std::uint64_t elements) : elements_(elements) {}

  // Records a stamped event (sequence set); returns the element transforms it adds.
  std::uint64_t Record(const v1::ProgressEvent& event);

  const std::vector<v1::ProgressEvent>& events() const { return events_; }
  const std::optional<v1::ProgressEvent>& latest() const { return latest_; }
  std::uint64_t element_iterations() const { return element_iterations_; }

 private:
  std::uint64_t CountElementIterations(const v1::ProgressEvent& event) const;

  const std::uint64_t elements_;
  std::optional<v1::ProgressEvent> latest_;
  std::uint64_t element_iterations_ = 0;
  std::vector<v1::ProgressEvent> events_;
  std::uint64_t stride_ = 1;  // keep every stride_-th intermediate event
};

}  // namespace getme::server
