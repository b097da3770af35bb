#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <map>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include "getme/v1/smoother.pb.h"

namespace getme::server {

// Counters that only the moment they happen can count (RPCs, HTTP requests, finished jobs, work
// done), kept for the server's lifetime so Prometheus counters never go down when the registry
// forgets old jobs. Gauges (jobs by state, queue length) are read from the registry at scrape time.
class ServerMetrics {
 public:
  // Upper bounds (seconds) of the job duration histogram buckets; +Inf is implied.
  static constexpr std::array<double, 10> kDurationBuckets = {0.1, 0.5, 1,   5,   10,
                                                              30,  60,  300, 900, 3600};

  struct DurationHistogram {
    std::array<std::uint64_t, kDurationBuckets.size()> cumulative{};  // count <= bound
    std::uint64_t count = 0;
    double sum = 0;
  };
  struct Snapshot {
    std::map<std::pair<std::string, std::string>, std::uint64_t> rpcs;  // (method, code)
    std::map<std::pair<std::string, int>, std::uint64_t> http;          // (route, status)
    std::map<v1::JobState, std::uint64_t> finished_jobs;
    DurationHistogram durations;
    std::uint64_t element_iterations = 0;
  };

  void CountRpc(std::string method, std::string code);
  void CountHttpRequest(std::string route, int status);
  // A job reached a final state; `ran_seconds` < 0 for jobs that never ran (cancelled queued).
  void CountFinishedJob(v1::JobState state, double ran_seconds);
  void AddElementIterations(std::uint64_t count) {
    element_iterations_.fetch_add(count, std::memory_order_relaxed);
  }

  Snapshot Read() const;

 private:
  mutable std::mutex mutex_;
  std::map<std::pair<std::string, std::string>, std::uint64_t> rpcs_;
  std::map<std::pair<std::string, int>, std::uint64_t> http_;
  std::map<v1::JobState, std::uint64_t> finished_jobs_;
  DurationHistogram durations_;
  std::atomic<std::uint64_t> element_iterations_{0};
};

}  // namespace getme::server
