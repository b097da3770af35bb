#include "getme/mesh/element_neighbours.h"

#include <algorithm>

namespace getme {
namespace {

// Merges the sorted runs of `keys` (run r ends at run_ends[r]) into one sorted run without
// repeats. Every node's row is already in canonical order: merging the rows pairwise costs a few
// linear passes where sorting their concatenation took three times as long (measured with
// callgrind).
template <typename Key>
void MergeRuns(std::vector<Key>& keys, std::vector<std::size_t>& run_ends,
               std::vector<Key>& scratch) {
  while (run_ends.size() > 1) {
    scratch.resize(keys.size());
    std::size_t kept = 0;
    for (std::size_t run = 0; run < run_ends.size(); run += 2) {
      const std::size_t begin = run == 0 ? 0 : run_ends[run - 1];
      const std::size_t middle = run_ends[run];
      const std::size_t end = run + 1 < run_ends.size() ? run_ends[run + 1] : middle;
      std::merge(keys.begin() + begin, keys.begin() + middle, keys.begin() + middle,
                 keys.begin() + end, scratch.begin() + begin);
      run_ends[kept++] = end;
    }
    run_ends.resize(kept);
    keys.swap(scratch);
  }
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
}

}  // namespace

std::span<const ElementId> ElementNeighbourFinder::Find(const Mesh& mesh, ElementId element,
                                                        std::span<const std::uint8_t> through) {
  // Where ids are ranks (Mesh::ids_in_canonical_order) the rows merge as they are. Otherwise each
  // entry is keyed by rank above id, so the merged keys give the ids back without a second
  // random read per neighbour (canonical_order()[rank]); the neighbours are cache misses, and
  // those reads were a quarter of the sequential substep on a 1M-element hybrid mesh.
  //
  // The rows and the ranks lie anywhere in a large mesh, so each is asked for before it is read
  // (the rows' bounds, then every entry's rank while the rows are read), and the cache misses
  // overlap instead of coming one after another.
  const bool ids_are_ranks = mesh.ids_in_canonical_order();
  neighbours_.clear();
  keyed_.clear();
  row_ends_.clear();
  const std::span<const NodeId> nodes = mesh.element_nodes(element);
  for (NodeId node : nodes) {
    if (through.empty() || through[node]) mesh.PrefetchNodeElements(node);
  }
  for (NodeId node : nodes) {
    if (!through.empty() && !through[node]) continue;
    for (ElementId other : mesh.node_elements(node)) {
      if (other == element) continue;
      if (ids_are_ranks) {
        neighbours_.push_back(other);
      } else {
        mesh.PrefetchCanonicalRank(other);
        keyed_.push_back(static_cast<std::uint32_t>(other));
      }
    }
    row_ends_.push_back(ids_are_ranks ? neighbours_.size() : keyed_.size());
  }
  if (row_ends_.empty()) return neighbours_;
  if (ids_are_ranks) {
    MergeRuns(neighbours_, row_ends_, merged_);
    return neighbours_;
  }
  for (std::uint64_t& key : keyed_) {
    key |= static_cast<std::uint64_t>(mesh.canonical_rank(static_cast<ElementId>(key))) << 32;
  }
  MergeRuns(keyed_, row_ends_, keyed_merged_);
  neighbours_.resize(keyed_.size());
  for (std::size_t i = 0; i < keyed_.size(); ++i) {
    neighbours_[i] = static_cast<ElementId>(static_cast<std::uint32_t>(keyed_[i]));
  }
  return neighbours_;
}

}  // namespace getme
