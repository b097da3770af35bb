// ThreadPool::ParallelFor calls the body on consecutive ranges of at most `grain` indices that
// cover [0, n) exactly once, for any thread count, and a pool can be reused indefinitely;
// ForEachThread calls it once per thread, number 0 on the caller and each other number on the
// same worker every time, also when the two kinds of call alternate.

#include "getme/parallel/thread_pool.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <future>
#include <mutex>
#include <set>
#include <thread>
#include <vector>

namespace getme {
namespace {

// Runs one ParallelFor and checks the ranges it produced and that each index was visited once.
void ExpectExactCover(ThreadPool& pool, std::int64_t count, std::int64_t grain) {
  std::vector<std::atomic<int>> visits(static_cast<std::size_t>(std::max<std::int64_t>(count, 0)));
  std::mutex ranges_mutex;
  std::vector<std::pair<std::int64_t, std::int64_t>> ranges;
  pool.ParallelFor(count, grain, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t i = begin; i < end; ++i) visits[i].fetch_add(1, std::memory_order_relaxed);
    std::lock_guard lock(ranges_mutex);
    ranges.emplace_back(begin, end);
  });
  const std::int64_t effective_grain = std::max<std::int64_t>(1, grain);
  std::int64_t covered = 0;
  for (const auto& [begin, end] : ranges) {
    EXPECT_LE(0, begin) << "n " << count << " grain " << grain;
    EXPECT_LT(begin, end) << "empty range, n " << count << " grain " << grain;
    EXPECT_LE(end, count) << "n " << count << " grain " << grain;
    EXPECT_LE(end - begin, effective_grain) << "n " << count << " grain " << grain;
    covered += end - begin;
  }
  EXPECT_EQ(covered, std::max<std::int64_t>(count, 0)) << "n " << count << " grain " << grain;
  for (std::int64_t i = 0; i < count; ++i) {
    ASSERT_EQ(visits[i].load(), 1) << "index " << i << ", n " << count << " grain " << grain
                                   << " threads " << pool.thread_count();
  }
}

TEST(ThreadPool, ThreadCountIsWhatWasAskedFor) {
  for (int threads : {1, 2, 3, 8}) EXPECT_EQ(ThreadPool(threads).thread_count(), threads);
  EXPECT_GE(ThreadPool(0).thread_count(), 1);  // hardware concurrency
  EXPECT_GE(ThreadPool(-3).thread_count(), 1);
}

TEST(ThreadPool, ParallelForCoversEveryIndexExactlyOnce) {
  for (int threads : {1, 2, 3, 8}) {
    ThreadPool pool(threads);
    for (std::int64_t count : {0, 1, 2, 7, 63, 64, 65, 1000, 10007}) {
      for (std::int64_t grain : {1, 3, 64, 1000, 100000}) {
        ExpectExactCover(pool, count, grain);
        if (HasFatalFailure()) return;
      }
    }
  }
}

TEST(ThreadPool, NonPositiveCountCallsNothing) {
  ThreadPool pool(3);
  int calls = 0;
  pool.ParallelFor(0, 4, [&](std::int64_t, std::int64_t) { ++calls; });
  pool.ParallelFor(-5, 4, [&](std::int64_t, std::int64_t) { ++calls; });
  EXPECT_EQ(calls, 0);
}

TEST(ThreadPool, NonPositiveGrainActsAsOne) {
  ThreadPool pool(2);
  ExpectExactCover(pool, 100, 0);
  ExpectExactCover(pool, 100, -7);
}

TEST(ThreadPool, CountBelowGrainIsOneCallOnTheCaller) {
  ThreadPool pool(4);
  std::vector<std::thread::id> callers;
  std::vector<std::pair<std::int64_t, std::int64_t>> ranges;
  pool.ParallelFor(10, 64, [&](std::int64_t begin, std::int64_t end) {
    callers.push_back(std::this_thread::get_id());
    ranges.emplace_back(begin, end);
  });
  ASSERT_EQ(ranges.size(), 1u);
  EXPECT_EQ(ranges[0], std::make_pair(std::int64_t{0}, std::int64_t{10}));
  EXPECT_EQ(callers[0], std::this_thread::get_id());
}

TEST(ThreadPool, SingleThreadRunsInOrderOnTheCaller) {
  ThreadPool pool(1);
  const std::thread::id caller = std::this_thread::get_id();
  std::vector<std::int64_t> begins;
  pool.ParallelFor(10, 3, [&](std::int64_t begin, std::int64_t end) {
    EXPECT_EQ(std::this_thread::get_id(), caller);
    begins.push_back(begin);
    EXPECT_EQ(end, std::min<std::int64_t>(10, begin + 3));
  });
  EXPECT_EQ(begins, (std::vector<std::int64_t>{0, 3, 6, 9}));
}

// Fails (instead of hanging until the ctest timeout) if `work` does not finish in time.
template <typename Work>
void RunWithWatchdog(const char* what, Work&& work) {
  std::packaged_task<void()> task(std::forward<Work>(work));
  std::future<void> done = task.get_future();
  std::thread runner(std::move(task));
  if (done.wait_for(std::chrono::minutes(3)) != std::future_status::ready) {
    std::fprintf(stderr, "%s did not finish within 3 minutes: deadlock\n", what);
    std::abort();
  }
  runner.join();
  done.get();
}

TEST(ThreadPool, OnePoolReusedAThousandTimesInSequence) {
  RunWithWatchdog("1000 consecutive ParallelFor calls", [] {
    ThreadPool pool(3);
    std::vector<std::int64_t> sums(1000);
    for (int round = 0; round < 1000; ++round) {
      const std::int64_t count = 1 + (round * 37) % 500;
      std::vector<std::int64_t> values(count, 0);
      pool.ParallelFor(count, 1 + round % 7, [&](std::int64_t begin, std::int64_t end) {
        for (std::int64_t i = begin; i < end; ++i) values[i] = i + round;
      });
      std::int64_t sum = 0;
      for (std::int64_t v : values) sum += v;
      sums[round] = sum;
    }
    for (int round = 0; round < 1000; ++round) {
      const std::int64_t count = 1 + (round * 37) % 500;
      EXPECT_EQ(sums[round], count * (count - 1) / 2 + count * round) << "round " << round;
    }
  });
}

// The server runs several jobs side by side, each with its own pool.
TEST(ThreadPool, SeparatePoolsRunConcurrentlyFromDifferentThreads) {
  RunWithWatchdog("two pools used concurrently", [] {
    auto job = [](int threads) {
      ThreadPool pool(threads);
      std::int64_t total = 0;
      for (int round = 0; round < 200; ++round) {
        std::vector<std::int64_t> values(3000);
        pool.ParallelFor(3000, 17, [&](std::int64_t begin, std::int64_t end) {
          for (std::int64_t i = begin; i < end; ++i) values[i] = 1;
        });
        for (std::int64_t v : values) total += v;
      }
      return total;
    };
    auto first = std::async(std::launch::async, job, 2);
    auto second = std::async(std::launch::async, job, 3);
    EXPECT_EQ(first.get(), 200 * 3000);
    EXPECT_EQ(second.get(), 200 * 3000);
  });
}

TEST(ThreadPool, ForEachThreadRunsEachNumberOnceAndAlwaysOnTheSameThread) {
  RunWithWatchdog("ForEachThread between ParallelFor calls", [] {
    for (int threads : {1, 2, 3, 8}) {
      ThreadPool pool(threads);
      std::vector<std::thread::id> first_seen(threads);
      for (int round = 0; round < 300; ++round) {
        std::vector<std::atomic<int>> calls(threads);
        std::vector<std::thread::id> seen(threads);
        pool.ForEachThread([&](int thread) {
          ASSERT_GE(thread, 0);
          ASSERT_LT(thread, threads);
          calls[thread].fetch_add(1, std::memory_order_relaxed);
          seen[thread] = std::this_thread::get_id();  // one writer per number
        });
        ASSERT_EQ(seen[0], std::this_thread::get_id()) << "threads " << threads;
        for (int thread = 0; thread < threads; ++thread) {
          ASSERT_EQ(calls[thread].load(), 1) << "thread " << thread << " round " << round;
          if (round == 0) first_seen[thread] = seen[thread];
          ASSERT_EQ(seen[thread], first_seen[thread]) << "thread " << thread << " round " << round;
        }
        ASSERT_EQ(std::set<std::thread::id>(seen.begin(), seen.end()).size(),
                  static_cast<std::size_t>(threads));
        // A ParallelFor in between, whose late workers must not take the next call's numbers.
        if (round % 2 == 0) ExpectExactCover(pool, 1 + round % 50, 1);
      }
    }
  });
}

// The sequential substep's way of using it: the caller consumes in order what every thread
// produces, the others stopping once the caller has enough.
TEST(ThreadPool, ForEachThreadLetsTheCallerWaitForTheOthers) {
  RunWithWatchdog("a producer and consumer round", [] {
    ThreadPool pool(3);
    for (int round = 0; round < 200; ++round) {
      constexpr int kItems = 64;
      std::vector<int> value(kItems, 0);
      std::vector<std::uint8_t> ready(kItems, 0);
      std::atomic<int> next{0};
      std::atomic<bool> enough{false};
      int consumed_sum = 0;
      const int wanted = 1 + round % kItems;
      const auto produce = [&] {
        const int i = next.fetch_add(1);
        if (i >= kItems) return false;
        value[i] = i * i;
        std::atomic_ref(ready[i]).store(1, std::memory_order_release);
        return true;
      };
      pool.ForEachThread([&](int thread) {
        if (thread != 0) {
          while (!enough.load() && produce()) {
          }
          return;
        }
        for (int i = 0; i < wanted;) {
          if (std::atomic_ref(ready[i]).load(std::memory_order_acquire)) {
            consumed_sum += value[i++];
          } else if (!produce()) {
            SpinPause();
          }
        }
        enough.store(true);
      });
      ASSERT_EQ(consumed_sum, (wanted - 1) * wanted * (2 * wanted - 1) / 6) << "round " << round;
    }
  });
}

TEST(ThreadPool, DestroyingAnIdlePoolJoinsItsWorkers) {
  RunWithWatchdog("creating and destroying pools", [] {
    for (int i = 0; i < 200; ++i) {
      ThreadPool pool(1 + i % 8);
      if (i % 2 == 0) pool.ParallelFor(100, 1, [](std::int64_t, std::int64_t) {});
      if (i % 3 == 0) pool.ForEachThread([](int) {});
    }
  });
}

}  // namespace
}  // namespace getme
