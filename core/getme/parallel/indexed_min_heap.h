#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace getme {

// Binary min-heap over items 0..n-1 with a key each, supporting key updates in O(log n): the
// element selection of the sequential substep (Sec. 3.2, Step 1.1). Ties break on the smaller
// item id so the pick order is fully determined.
class IndexedMinHeap {
 public:
  explicit IndexedMinHeap(std::int64_t capacity) : position_(capacity, kAbsent) {}

  bool empty() const { return heap_.empty(); }
  std::int64_t size() const { return static_cast<std::int64_t>(heap_.size()); }
  bool contains(std::int32_t item) const { return position_[item] != kAbsent; }
  // Asks for the cache line contains(item) reads.
  void Prefetch(std::int32_t item) const { __builtin_prefetch(&position_[item]); }
  std::int32_t top() const { return heap_.front().item; }
  double top_key() const { return heap_.front().key; }
  double key(std::int32_t item) const { return heap_[position_[item]].key; }

  void Push(std::int32_t item, double key) {
    heap_.push_back({key, item});
    position_[item] = static_cast<std::int32_t>(heap_.size() - 1);
    SiftUp(heap_.size() - 1);
  }

  // Calls visit(item, key) for the items in ascending (key, item) order until it returns false,
  // without changing the heap: a best-first walk of the heap tree, whose frontier (heap
  // positions, itself kept as a binary heap in `frontier`, reused between calls) holds at most
  // one more entry per visited item. Visiting the k smallest items costs O(k log k).
  template <typename Visit>
  void VisitInKeyOrder(std::vector<std::size_t>& frontier, Visit&& visit) const {
    frontier.clear();
    if (heap_.empty()) return;
    frontier.push_back(0);
    ContinueInKeyOrder(frontier, visit);
  }

  // Goes on with a walk that VisitInKeyOrder (or this) stopped, from the item at which visit
  // returned false: that item is visited again. The heap must not have changed in between. So a
  // caller can walk only as deep as it turns out to need (the sequential substep's batches).
  template <typename Visit>
  void ContinueInKeyOrder(std::vector<std::size_t>& frontier, Visit&& visit) const {
    const auto later = [this](std::size_t a, std::size_t b) { return heap_[b] < heap_[a]; };
    while (!frontier.empty()) {
      const std::size_t at = frontier.front();
      if (!visit(heap_[at].item, heap_[at].key)) return;
      std::pop_heap(frontier.begin(), frontier.end(), later);
      frontier.pop_back();
      for (std::size_t child = 2 * at + 1; child <= 2 * at + 2 && child < heap_.size(); ++child) {
        frontier.push_back(child);
        std::push_heap(frontier.begin(), frontier.end(), later);
      }
    }
  }

  void Remove(std::int32_t item) {
    const std::size_t at = position_[item];
    position_[item] = kAbsent;
    const Entry last = heap_.back();
    heap_.pop_back();
    if (at == heap_.size()) return;
    heap_[at] = last;
    position_[last.item] = static_cast<std::int32_t>(at);
    if (at > 0 && last < heap_[(at - 1) / 2]) {
      SiftUp(at);
    } else {
      SiftDown(at);
    }
  }

  void Clear() {
    for (const Entry& entry : heap_) position_[entry.item] = kAbsent;
    heap_.clear();
  }

  void Update(std::int32_t item, double key) {
    const std::size_t at = position_[item];
    const double old_key = heap_[at].key;
    heap_[at].key = key;
    if (key < old_key) {
      SiftUp(at);
    } else {
      SiftDown(at);
    }
  }

 private:
  static constexpr std::int32_t kAbsent = -1;
  struct Entry {
    double key;
    std::int32_t item;
    bool operator<(const Entry& other) const {
      return key < other.key || (key == other.key && item < other.item);
    }
  };

  void Place(std::size_t at, const Entry& entry) {
    heap_[at] = entry;
    position_[entry.item] = static_cast<std::int32_t>(at);
  }

  void SiftUp(std::size_t at) {
    const Entry entry = heap_[at];
    while (at > 0) {
      const std::size_t parent = (at - 1) / 2;
      if (!(entry < heap_[parent])) break;
      Place(at, heap_[parent]);
      at = parent;
    }
    Place(at, entry);
  }

  void SiftDown(std::size_t at) {
    const Entry entry = heap_[at];
    const std::size_t n = heap_.size();
    for (;;) {
      std::size_t child = 2 * at + 1;
      if (child >= n) break;
      if (child + 1 < n && heap_[child + 1] < heap_[child]) ++child;
      if (!(heap_[child] < entry)) break;
      Place(at, heap_[child]);
      at = child;
    }
    Place(at, entry);
  }

  std::vector<Entry> heap_;
  std::vector<std::int32_t> position_;
};

}  // namespace getme
