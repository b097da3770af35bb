#include "getme/parallel/thread_pool.h"

#include <algorithm>
#include <chrono>

namespace getme {

ThreadPool::ThreadPool(int threads) {
  if (threads <= 0) threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  workers_.reserve(threads - 1);
  for (int i = 1; i < threads; ++i) workers_.emplace_back([this, i] { WorkerLoop(i); });
}

ThreadPool::~ThreadPool() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  work_ready_.notify_all();
  for (std::thread& worker : workers_) worker.join();
}

void ThreadPool::RunChunks() {
  for (;;) {
    std::int64_t begin;
    const std::function<void(std::int64_t, std::int64_t)>* body;
    {
      std::lock_guard lock(mutex_);
      begin = next_chunk_;
      if (begin >= count_) return;
      next_chunk_ = std::min(count_, begin + grain_);
      body = body_;
      published_running_.store(++running_, std::memory_order_relaxed);
    }
    (*body)(begin, std::min(count_, begin + grain_));
    {
      std::lock_guard lock(mutex_);
      published_running_.store(--running_, std::memory_order_release);
      if (running_ == 0) work_done_.notify_all();
    }
  }
}

void ThreadPool::WorkerLoop(int thread) {
  std::uint64_t seen_generation = 0;
  for (;;) {
    // Back-to-back ParallelFor calls (the sequential substep's batches: a few hundred
    // microseconds each) would otherwise wait for a sleeping worker to be woken every time; a
    // short spin catches the next call while it is still coming.
    const auto spin_end = std::chrono::steady_clock::now() + kSpin;
    for (int i = 0; published_generation_.load(std::memory_order_acquire) == seen_generation; ++i) {
      SpinPause();
      if (i % 64 == 63 && std::chrono::steady_clock::now() >= spin_end) break;
    }
    const std::function<void(int)>* thread_body;
    {
      std::unique_lock lock(mutex_);
      work_ready_.wait(lock, [&] { return stopping_ || generation_ != seen_generation; });
      if (stopping_) return;
      seen_generation = generation_;
      thread_body = thread_body_;
    }
    if (thread_body == nullptr) {
      RunChunks();
      continue;
    }
    (*thread_body)(thread);
    std::lock_guard lock(mutex_);
    published_running_.store(--running_, std::memory_order_release);
    if (running_ == 0) work_done_.notify_all();
  }
}

void ThreadPool::ParallelFor(std::int64_t count, std::int64_t grain,
                             const std::function<void(std::int64_t, std::int64_t)>& body) {
  if (count <= 0) return;
  grain = std::max<std::int64_t>(1, grain);
  if (workers_.empty() || count <= grain) {
    for (std::int64_t begin = 0; begin < count; begin += grain) {
      body(begin, std::min(count, begin + grain));
    }
    return;
  }
  {
    std::lock_guard lock(mutex_);
    body_ = &body;
    thread_body_ = nullptr;
    count_ = count;
    grain_ = grain;
    next_chunk_ = 0;
    ++generation_;
    published_generation_.store(generation_, std::memory_order_release);
  }
  work_ready_.notify_all();
  RunChunks();
  // Every chunk is taken: wait only for the chunks still running. A worker that wakes later finds
  // nothing left and never touches `body`, so the caller does not wait for it to wake.
  WaitForRunning();
  std::lock_guard lock(mutex_);
  body_ = nullptr;
}

void ThreadPool::ForEachThread(const std::function<void(int)>& body) {
  if (workers_.empty()) {
    body(0);
    return;
  }
  {
    std::lock_guard lock(mutex_);
    thread_body_ = &body;
    count_ = 0;  // a worker still finishing an earlier ParallelFor finds no chunk
    next_chunk_ = 0;
    running_ = static_cast<int>(workers_.size());
    published_running_.store(running_, std::memory_order_relaxed);
    ++generation_;
    published_generation_.store(generation_, std::memory_order_release);
  }
  work_ready_.notify_all();
  body(0);
  WaitForRunning();
  std::lock_guard lock(mutex_);
  thread_body_ = nullptr;
}

void ThreadPool::WaitForRunning() {
  // The wait spins first. Callers issue ParallelFors back to back (Step 2 runs one per tile
  // colour, about ten per iteration), and the other thread's last chunk is usually microseconds
  // from done; sleeping on the condition variable would cost a futex wake-up each time, tens of
  // microseconds: it made a 10k-element iteration on 2 threads 0.38-0.57 ms instead of 0.31 ms
  // (docs/benchmarks.md, "Small meshes at 2 threads").
  const auto spin_end = std::chrono::steady_clock::now() + kSpin;
  for (int i = 0; published_running_.load(std::memory_order_acquire) != 0; ++i) {
    SpinPause();
    if (i % 64 == 63 && std::chrono::steady_clock::now() >= spin_end) break;
  }
  std::unique_lock lock(mutex_);
  work_done_.wait(lock, [&] { return running_ == 0; });
}

}  // namespace getme
