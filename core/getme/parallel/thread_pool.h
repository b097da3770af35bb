#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace getme {

// Tells the core that this is a spin loop, so a sibling hardware thread gets its resources.
inline void SpinPause() {
#if defined(__x86_64__) || defined(__i386__)
  __builtin_ia32_pause();
#elif defined(__aarch64__)
  asm volatile("yield");
#endif
}

// A fixed set of worker threads running ParallelFor over statically partitioned chunks.
//
// Why not TBB or OpenMP: results must be bit-identical for any thread count, which the engine
// achieves by never accumulating across chunks in scheduling order; it needs only a blocking
// "run these independent chunks" primitive with an exact thread count per job (the server runs
// several jobs side by side), and it must stay clean under ThreadSanitizer, which does not see
// libgomp's synchronisation. That is 100 lines of std::thread.
class ThreadPool {
 public:
  // threads <= 0 means std::thread::hardware_concurrency().
  explicit ThreadPool(int threads = 1);
  ~ThreadPool();
  ThreadPool(const ThreadPool&) = delete;
  ThreadPool& operator=(const ThreadPool&) = delete;

  int thread_count() const { return static_cast<int>(workers_.size()) + 1; }

  // Calls body(begin, end) for consecutive ranges covering [0, count), each at most `grain`
  // long, on all threads (the caller included), and returns when all are done. Bodies must
  // write disjoint data.
  void ParallelFor(std::int64_t count, std::int64_t grain,
                   const std::function<void(std::int64_t, std::int64_t)>& body);

  // Calls body(thread) once on every thread, thread 0 being the caller and 1..thread_count()-1
  // the workers, always the same worker for the same number, and returns when all are done. For
  // work whose data should stay in one core's cache from call to call (the sequential substep's
  // heaps: docs/parallel-sequential.md); ParallelFor hands chunks to whichever thread is free.
  void ForEachThread(const std::function<void(int)>& body);

 private:
  void WorkerLoop(int thread);
  void RunChunks();
  // Until no chunk or thread body is running: spins for kSpin, then sleeps.
  void WaitForRunning();

  std::vector<std::thread> workers_;
  std::mutex mutex_;
  std::condition_variable work_ready_;
  std::condition_variable work_done_;
  const std::function<void(std::int64_t, std::int64_t)>* body_ = nullptr;
  const std::function<void(int)>* thread_body_ = nullptr;  // ForEachThread's; guarded by mutex_
  std::int64_t count_ = 0;
  std::int64_t grain_ = 1;
  std::int64_t next_chunk_ = 0;  // guarded by mutex_
  int running_ = 0;              // chunks being run, on any thread; guarded by mutex_
  // running_, readable without the mutex by the spinning caller of ParallelFor.
  std::atomic<int> published_running_{0};
  std::uint64_t generation_ = 0;
  // generation_, readable without the mutex by a spinning worker.
  std::atomic<std::uint64_t> published_generation_{0};
  // How long a worker that finished its chunks spins for the next ParallelFor before it sleeps,
  // and how long the caller spins for the chunks still running before it sleeps.
  static constexpr std::chrono::microseconds kSpin{200};
  bool stopping_ = false;
};

}  // namespace getme
