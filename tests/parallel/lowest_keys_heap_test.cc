// LowestKeysHeap against a brute-force model after every operation: the smallest (key, item) is
// exact whatever the threshold, the in-order walk gives at least the low-water mark's smallest
// items in order, and an update it takes without the heap (UpdateOutsideHeap) leaves the same
// state as a full Update.

#include "getme/parallel/lowest_keys_heap.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <random>
#include <utility>
#include <vector>

namespace getme {
namespace {

using Model = std::map<std::int32_t, double>;  // item → key

std::vector<std::pair<double, std::int32_t>> Sorted(const Model& model) {
  std::vector<std::pair<double, std::int32_t>> sorted;
  for (const auto& [item, key] : model) sorted.push_back({key, item});
  std::sort(sorted.begin(), sorted.end());
  return sorted;
}

void ExpectMatches(LowestKeysHeap& heap, const Model& model, std::int64_t low_water, int step) {
  ASSERT_EQ(heap.size(), static_cast<std::int64_t>(model.size())) << "after op " << step;
  ASSERT_EQ(heap.empty(), model.empty());
  if (model.empty()) return;
  const auto sorted = Sorted(model);
  ASSERT_EQ(heap.top(), sorted.front().second) << "after op " << step;
  ASSERT_EQ(heap.top_key(), sorted.front().first) << "after op " << step;
  std::vector<std::pair<double, std::int32_t>> visited;
  std::vector<std::size_t> frontier;
  heap.VisitInKeyOrder(frontier, [&](std::int32_t item, double key) {
    visited.push_back({key, item});
    return true;
  });
  const std::size_t promised = std::min<std::size_t>(low_water, sorted.size());
  ASSERT_GE(visited.size(), promised) << "after op " << step;
  for (std::size_t i = 0; i < visited.size(); ++i) {
    ASSERT_EQ(visited[i], sorted[i]) << "position " << i << " after op " << step;
  }
}

void RunRandomOperations(int capacity, std::int64_t low_water, std::int64_t stock, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_int_distribution<std::int32_t> pick_item(0, capacity - 1);
  std::uniform_int_distribution<int> coarse(0, 40);
  std::uniform_real_distribution<double> rise(0.0, 0.3);
  LowestKeysHeap heap(capacity, low_water, stock);
  Model model;
  // Every other item, keys from a coarse grid so ties are frequent.
  for (std::int32_t item = 0; item < capacity; item += 2) {
    const double key = coarse(random) * 0.025;
    heap.Insert(item, key);
    model[item] = key;
  }
  ExpectMatches(heap, model, low_water, -1);
  for (int step = 0; step < 4000; ++step) {
    // Mostly the smallest items rise, as transformed elements do; sometimes any item moves
    // anywhere, below the threshold too.
    std::int32_t item = heap.top();
    if (step % 3 == 0) {
      do item = pick_item(random);
      while (!model.count(item));
    }
    const double key = step % 5 == 0 ? coarse(random) * 0.025 : model[item] + rise(random);
    if (step % 2 == 0 || !heap.UpdateOutsideHeap(item, key)) heap.Update(item, key);
    model[item] = key;
    ExpectMatches(heap, model, low_water, step);
    if (::testing::Test::HasFatalFailure()) return;
  }
}

TEST(LowestKeysHeap, RandomUpdatesMatchBruteForceWithASmallStock) {
  RunRandomOperations(2000, 4, 32, 11);
}

TEST(LowestKeysHeap, RandomUpdatesMatchBruteForceWithALargeLowWaterMark) {
  RunRandomOperations(3000, 256, 512, 12);
}

TEST(LowestKeysHeap, StockLargerThanTheItemsKeepsEveryItem) {
  RunRandomOperations(100, 1, 100000, 13);
}

TEST(LowestKeysHeap, UpdateOutsideHeapRefusesWhatWouldChangeTheHeap) {
  LowestKeysHeap heap(1000, 1, 4);
  for (std::int32_t item = 0; item < 1000; ++item) heap.Insert(item, item * 0.001);
  ASSERT_EQ(heap.top(), 0);  // builds the heap: about 4 of the smallest keys below the threshold
  EXPECT_FALSE(heap.UpdateOutsideHeap(0, 5.0)) << "item 0 is in the heap";
  EXPECT_FALSE(heap.UpdateOutsideHeap(900, -1.0)) << "a key below every other must enter it";
  EXPECT_TRUE(heap.UpdateOutsideHeap(900, 0.95));
  EXPECT_EQ(heap.top(), 0);
  heap.Update(900, -1.0);
  EXPECT_EQ(heap.top(), 900);
  EXPECT_EQ(heap.top_key(), -1.0);
}

}  // namespace
}  // namespace getme
