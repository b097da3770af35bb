#pragma once

#include <cstdint>
#include <vector>

#include "absl/container/flat_hash_map.h"

namespace getme::formats {

// Node or element tag → index in file order. Gmsh tags are usually dense (1..n), sometimes
// sparse or huge (partitioned or merged meshes): tags below a bound derived from the declared
// count go into a vector, larger ones into a hash map, so neither case costs much memory.
class GmshTagIndex {
 public:
  // `expected` must already be checked against the input size by the caller.
  explicit GmshTagIndex(std::int64_t expected) : dense_limit_(4 * expected + 1024) {}

  // False (and nothing changes) if `tag` is already present.
  bool Insert(std::int64_t tag, std::int64_t index) {
    if (tag < dense_limit_) {
      if (tag >= static_cast<std::int64_t>(dense_.size())) {
        const std::int64_t grown = std::max<std::int64_t>(tag + 1, 2 * dense_.size());
        dense_.resize(std::min(grown, dense_limit_), -1);
      }
      if (dense_[tag] >= 0) return false;
      dense_[tag] = index;
      return true;
    }
    return sparse_.try_emplace(tag, index).second;
  }

  // -1 if absent.
  std::int64_t Find(std::int64_t tag) const {
    if (tag < 0) return -1;
    if (tag < dense_limit_) {
      return tag < static_cast<std::int64_t>(dense_.size()) ? dense_[tag] : -1;
    }
    const auto it = sparse_.find(tag);
    return it == sparse_.end() ? -1 : it->second;
  }

 private:
  std::int64_t dense_limit_;
  std::vector<std::int64_t> dense_;
  absl::flat_hash_map<std::int64_t, std::int64_t> sparse_;
};

}  // namespace getme::formats
