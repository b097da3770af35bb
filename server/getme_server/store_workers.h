#pragma once

#include <atomic>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "absl/container/flat_hash_map.h"
#include "absl/time/time.h"
#include "getme_server/job.h"
#include "getme_server/job_registry.h"
#include "getme_server/job_time_limit.h"
#include "getme_server/server_metrics.h"
#include "getme_server/server_options.h"
#include "getme_server/shared_job_store.h"

namespace getme::server {

// This replica's workers on a shared job store (--job_store): `options.workers` threads each take
// the next queued job from the store (whichever replica queued it), rebuild its mesh from the
// stored upload and run it as a local Job (tracked in `local` for the time limit, metrics and
// shutdown), writing its progress events and finally its result back to the store. One keeper
// thread renews the leases of the jobs running here (and passes on cancel requests from other
// replicas), flushes their events every --progress_interval, requeues jobs whose lease expired
// anywhere (their replica died), and records this replica as alive.
class StoreWorkers {
 public:
  StoreWorkers(SharedJobStore& store, JobRegistry& local, const ServerOptions& options,
               ServerMetrics* metrics);
  ~StoreWorkers();  // StopTaking, Join
  StoreWorkers(const StoreWorkers&) = delete;
  StoreWorkers& operator=(const StoreWorkers&) = delete;

  // Takes no new job (a drain); jobs running here go on. A job a worker took before this returns
  // is already registered as running here, so WaitUntilNoneRunning waits for it.
  void StopTaking();
  // Waits until no job taken here is running (each counts from the moment it was taken, while its
  // mesh is still being rebuilt, to the moment it ended), or `deadline`; true if none is.
  bool WaitUntilNoneRunning(absl::Time deadline);
  // Gives the jobs still running here back to the store (their lease ends now, so another
  // replica restarts them) and stops them here.
  void ReleaseRunning(absl::string_view reason);
  // Waits for the workers (after StopTaking) and stops the keeper.
  void Join();

 private:
  // A job running here: what its event sink collected since the last flush.
  struct Running {
    std::string id;
    std::shared_ptr<Job> job;  // null while its mesh is rebuilt (the lease is renewed already)
    std::uint32_t attempt = 1;
    double created_unix_seconds = 0;
    std::mutex mutex;                  // guards the fields below; taken by the job's event sink
    std::vector<std::string> pending;  // phase_done events, in order
    std::optional<v1::ProgressEvent> latest;  // the newest intermediate event
    std::optional<v1::ProgressEvent> final_event;
    std::uint64_t last_sequence = 0;     // of the events collected
    std::uint64_t flushed_sequence = 0;  // of the events in the store
    bool lost = false;                   // the lease went to another replica
    std::string cancel_applied;
  };

  void WorkLoop();
  void KeeperLoop();
  // The taken job's entry in running_, or null if this replica stopped taking (then the caller
  // gives it back): checked and registered under one lock, so no job slips past a drain.
  std::shared_ptr<Running> Register(const TakenJob& taken);
  void RunTaken(TakenJob taken, std::shared_ptr<Running> running);
  void Unregister(const std::string& id);
  void Flush(Running& running);
  v1::Job DescribeForStore(const Job& job, const Running& running) const;
  std::vector<std::shared_ptr<Running>> RunningNow() const;

  SharedJobStore& store_;
  JobRegistry& local_;
  const ServerOptions options_;
  ServerMetrics* const metrics_;
  JobTimeLimit time_limit_;

  mutable std::mutex mutex_;
  absl::flat_hash_map<std::string, std::shared_ptr<Running>> running_;
  std::condition_variable none_running_;  // notified when running_ shrinks
  std::condition_variable keeper_wake_;
  bool keeper_stop_ = false;

  std::atomic<bool> taking_{true};  // written under mutex_ (Register reads it there)
  std::vector<std::thread> workers_;
  std::thread keeper_;
};

}  // namespace getme::server
