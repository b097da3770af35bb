#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "getme/parallel/indexed_min_heap.h"

namespace getme {

// The sequential substep's selection and its q_min (Sec. 3.2, Step 1.1): the item with the
// smallest (key, item), keys updated one by one, over every element of the mesh. Only the low end
// of the keys is ever asked for, so only the items whose key lies below a threshold are kept in an
// IndexedMinHeap; the others wait in a flat key array. An update of an item above the threshold —
// most of them: a transformed element and its neighbours improve — is then one store instead of a
// sift through a heap of the whole mesh (about 20 cache misses at a million elements, measured as
// most of a batch's serial time: docs/parallel-sequential.md). When fewer than `low_water` items
// are below the threshold, it is raised so that about `stock` are (a sample's quantile), and the
// heap refilled in one pass. Keys must be finite.
//
// The smallest (key, item) is always exact: every item outside the heap has a key at or above the
// threshold, every item inside one below it. So is VisitInKeyOrder, for as many items as the heap
// holds, which is at least low_water (or every item).
class LowestKeysHeap {
 public:
  LowestKeysHeap(std::int64_t capacity, std::int64_t low_water, std::int64_t stock)
      : heap_(capacity),
        key_(capacity, 0.0),
        present_(capacity, 0),
        low_water_(std::max<std::int64_t>(1, low_water)),
        stock_(std::max(stock, 2 * low_water_)) {}

  // Adds an item; until the next query the heap is rebuilt from scratch.
  void Insert(std::int32_t item, double key) {
    key_[item] = key;
    present_[item] = 1;
    ++size_;
    threshold_ = -std::numeric_limits<double>::infinity();
    heap_.Clear();
  }

  bool empty() const { return size_ == 0; }
  std::int64_t size() const { return size_; }
  bool contains(std::int32_t item) const { return present_[item] != 0; }
  // Asks for the cache lines an update of the item reads and writes (UpdateOutsideHeap).
  void Prefetch(std::int32_t item) const {
    __builtin_prefetch(&key_[item], 1);
    heap_.Prefetch(item);
  }
  // Asks for the cache line contains(item) reads.
  void PrefetchContains(std::int32_t item) const { __builtin_prefetch(&present_[item]); }

  void Update(std::int32_t item, double key) {
    key_[item] = key;
    if (heap_.contains(item)) {
      if (key < threshold_) {
        heap_.Update(item, key);
      } else {
        heap_.Remove(item);
      }
    } else if (key < threshold_) {
      heap_.Push(item, key);
    }
  }

  // Update(item, key) when that leaves the heap alone (the item stays above the threshold) and
  // then returns true; returns false, changing nothing, when Update must be called. Safe to call
  // from several threads for distinct items while no other member runs: most updates then need
  // no serial step at all.
  bool UpdateOutsideHeap(std::int32_t item, double key) {
    if (key < threshold_ || heap_.contains(item)) return false;
    key_[item] = key;
    return true;
  }

  std::int32_t top() {
    Restock();
    return heap_.top();
  }
  double top_key() {
    Restock();
    return heap_.top_key();
  }

  // As IndexedMinHeap::VisitInKeyOrder, over at least the low_water smallest items.
  template <typename Visit>
  void VisitInKeyOrder(std::vector<std::size_t>& frontier, Visit&& visit) {
    Restock();
    heap_.VisitInKeyOrder(frontier, visit);
  }
  // As IndexedMinHeap::ContinueInKeyOrder: no update may come between the two calls.
  template <typename Visit>
  void ContinueInKeyOrder(std::vector<std::size_t>& frontier, Visit&& visit) {
    heap_.ContinueInKeyOrder(frontier, visit);
  }

 private:
  void Restock() {
    if (heap_.size() >= std::min(low_water_, size_)) return;
    // A fixed-stride sample's quantile: the threshold depends only on the keys, never on timing.
    const std::int64_t capacity = static_cast<std::int64_t>(key_.size());
    const std::int64_t stride = std::max<std::int64_t>(1, stock_ / 64);
    sample_.clear();
    for (std::int64_t item = 0; item < capacity; item += stride) {
      if (present_[item]) sample_.push_back(key_[item]);
    }
    const auto rank = static_cast<std::size_t>(stock_ / stride);
    threshold_ = std::numeric_limits<double>::infinity();
    if (rank < sample_.size()) {
      std::nth_element(sample_.begin(), sample_.begin() + static_cast<std::ptrdiff_t>(rank),
                       sample_.end());
      threshold_ = std::nextafter(sample_[rank], std::numeric_limits<double>::infinity());
    }
    Fill();
    // The sample missed the low end: too few below its threshold. Take every item.
    if (heap_.size() < std::min(low_water_, size_)) {
      threshold_ = std::numeric_limits<double>::infinity();
      Fill();
    }
  }

  void Fill() {
    heap_.Clear();
    for (std::int32_t item = 0; item < static_cast<std::int32_t>(key_.size()); ++item) {
      if (present_[item] && key_[item] < threshold_) heap_.Push(item, key_[item]);
    }
  }

  IndexedMinHeap heap_;
  std::vector<double> key_;
  std::vector<std::uint8_t> present_;
  std::vector<double> sample_;
  std::int64_t size_ = 0;
  const std::int64_t low_water_;
  const std::int64_t stock_;
  // Items with key < threshold_ are in heap_; −∞ until the first query builds it.
  double threshold_ = -std::numeric_limits<double>::infinity();
};

}  // namespace getme
