// IndexedMinHeap against a brute-force scan after every operation: the top is the smallest key,
// ties going to the smaller item id, and contains/key/size agree.

#include "getme/parallel/indexed_min_heap.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <random>
#include <utility>
#include <vector>

namespace getme {
namespace {

// What the heap should hold: item → key.
using Model = std::map<std::int32_t, double>;

void ExpectHeapMatchesModel(const IndexedMinHeap& heap, const Model& model, int capacity,
                            int step) {
  ASSERT_EQ(heap.size(), static_cast<std::int64_t>(model.size())) << "after op " << step;
  ASSERT_EQ(heap.empty(), model.empty()) << "after op " << step;
  for (std::int32_t item = 0; item < capacity; ++item) {
    const auto it = model.find(item);
    ASSERT_EQ(heap.contains(item), it != model.end()) << "item " << item << " after op " << step;
    if (it != model.end()) {
      ASSERT_EQ(heap.key(item), it->second) << "item " << item;
    }
  }
  if (model.empty()) return;
  // Brute force: the smallest key, the smallest id among equal keys (the map iterates ids up).
  std::int32_t best = -1;
  double best_key = std::numeric_limits<double>::infinity();
  for (const auto& [item, key] : model) {
    if (best < 0 || key < best_key) {
      best = item;
      best_key = key;
    }
  }
  ASSERT_EQ(heap.top(), best) << "after op " << step;
  ASSERT_EQ(heap.top_key(), best_key) << "after op " << step;
  if (step % 97 != 0) return;  // the full in-order walk now and then: it is O(n log n)
  std::vector<std::pair<double, std::int32_t>> sorted;
  for (const auto& [item, key] : model) sorted.push_back({key, item});
  std::sort(sorted.begin(), sorted.end());
  std::vector<std::pair<double, std::int32_t>> visited;
  std::vector<std::size_t> frontier;
  heap.VisitInKeyOrder(frontier, [&](std::int32_t item, double key) {
    visited.push_back({key, item});
    return true;
  });
  ASSERT_EQ(visited, sorted) << "after op " << step;
}

// Keys from a small set so that ties are frequent, plus occasional wide values.
double RandomKey(std::mt19937& random) {
  std::uniform_int_distribution<int> kind(0, 9);
  std::uniform_int_distribution<int> small(-4, 12);
  std::uniform_real_distribution<double> wide(-1e6, 1e6);
  return kind(random) < 8 ? small(random) * 0.25 : wide(random);
}

void RunRandomOperations(int capacity, int operations, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_int_distribution<std::int32_t> pick_item(0, capacity - 1);
  IndexedMinHeap heap(capacity);
  Model model;
  ExpectHeapMatchesModel(heap, model, capacity, -1);
  for (int step = 0; step < operations; ++step) {
    const std::int32_t item = pick_item(random);
    double key = RandomKey(random);
    if (!model.count(item)) {
      heap.Push(item, key);
    } else {
      // Sometimes keep the key, sometimes move it just above or below: the sift direction edges.
      const int variant = std::uniform_int_distribution<int>(0, 5)(random);
      if (variant == 0) key = model[item];
      if (variant == 1) key = std::nextafter(model[item], -1e300);
      if (variant == 2) key = std::nextafter(model[item], 1e300);
      heap.Update(item, key);
    }
    model[item] = key;
    ExpectHeapMatchesModel(heap, model, capacity, step);
    if (::testing::Test::HasFatalFailure()) return;
  }
}

TEST(IndexedMinHeap, RandomPushAndUpdateMatchBruteForce) { RunRandomOperations(200, 10000, 12345); }

TEST(IndexedMinHeap, RandomOperationsOnAFewItemsMatchBruteForce) {
  RunRandomOperations(5, 10000, 777);
}

TEST(IndexedMinHeap, RandomOperationsOnManyItemsMatchBruteForce) {
  RunRandomOperations(3000, 10000, 4242);
}

TEST(IndexedMinHeap, EqualKeysPopInItemOrder) {
  IndexedMinHeap heap(6);
  for (std::int32_t item : {5, 3, 4, 0, 2, 1}) heap.Push(item, 0.5);
  EXPECT_EQ(heap.top(), 0);
  // Raising the top hands the minimum to the next id with the same key, in id order.
  for (std::int32_t expected = 0; expected < 6; ++expected) {
    ASSERT_EQ(heap.top(), expected);
    heap.Update(expected, 1.0 + expected);
  }
  EXPECT_EQ(heap.top(), 0);
  EXPECT_EQ(heap.top_key(), 1.0);
}

TEST(IndexedMinHeap, VisitInKeyOrderStopsWhenAskedAndLeavesTheHeapAlone) {
  IndexedMinHeap heap(8);
  for (std::int32_t item : {6, 2, 7, 0, 5, 1, 4, 3}) heap.Push(item, item % 3 * 0.5);
  // Keys: 0 → items 0, 3, 6; 0.5 → 1, 4, 7; 1 → 2, 5. The first five in (key, item) order:
  std::vector<std::int32_t> first;
  std::vector<std::size_t> frontier;
  heap.VisitInKeyOrder(frontier, [&](std::int32_t item, double) {
    first.push_back(item);
    return first.size() < 5;
  });
  EXPECT_EQ(first, (std::vector<std::int32_t>{0, 3, 6, 1, 4}));
  EXPECT_EQ(heap.top(), 0);
  EXPECT_EQ(heap.size(), 8);
  IndexedMinHeap empty(3);
  empty.VisitInKeyOrder(frontier, [&](std::int32_t, double) -> bool {
    ADD_FAILURE() << "an empty heap has nothing to visit";
    return true;
  });
}

// A walk stopped and continued, in pieces of any length, visits what one walk visits, each item
// once: the item at which a piece stops is the first of the next.
TEST(IndexedMinHeap, ContinueInKeyOrderGoesOnWhereTheWalkStopped) {
  std::mt19937 random(99);
  IndexedMinHeap heap(500);
  for (std::int32_t item = 0; item < 500; ++item) heap.Push(item, RandomKey(random));
  std::vector<std::pair<double, std::int32_t>> whole;
  std::vector<std::size_t> frontier;
  heap.VisitInKeyOrder(frontier, [&](std::int32_t item, double key) {
    whole.push_back({key, item});
    return true;
  });
  ASSERT_EQ(whole.size(), 500u);
  for (int piece : {1, 2, 7, 64, 499, 500, 1000}) {
    std::vector<std::pair<double, std::int32_t>> pieces;
    std::size_t until = 0;
    const auto visit = [&](std::int32_t item, double key) {
      if (pieces.size() == until) return false;
      pieces.push_back({key, item});
      return true;
    };
    until = piece;
    heap.VisitInKeyOrder(frontier, visit);
    while (pieces.size() == until) {
      until += piece;
      heap.ContinueInKeyOrder(frontier, visit);
    }
    EXPECT_EQ(pieces, whole) << "pieces of " << piece;
  }
  // A walk that has ended stays ended.
  bool called = false;
  heap.ContinueInKeyOrder(frontier, [&](std::int32_t, double) { return called = true; });
  EXPECT_FALSE(called);
}

TEST(IndexedMinHeap, DecreasingAKeyToATieWithTheTopPrefersTheSmallerId) {
  IndexedMinHeap heap(4);
  heap.Push(2, 0.1);
  heap.Push(3, 0.9);
  heap.Push(1, 0.7);
  heap.Update(3, 0.1);
  EXPECT_EQ(heap.top(), 2);
  heap.Update(1, 0.1);
  EXPECT_EQ(heap.top(), 1);
  EXPECT_FALSE(heap.contains(0));
  EXPECT_EQ(heap.size(), 3);
}

}  // namespace
}  // namespace getme
