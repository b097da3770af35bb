#pragma once

#include <algorithm>
#include <cstdint>

#include "getme/element_tables.h"
#include "getme/mesh.h"
#include "getme/thread_pool.h"

namespace getme {

// Elements per ParallelFor chunk: large enough to amortise scheduling, small enough to balance.
inline constexpr std::int64_t kElementGrain = 2048;

// Runs body.template operator()<kType>(block, begin, end) over every type block, in parallel
// chunks of block entries. The element type is a compile-time constant inside the body.
template <typename Body>
void ParallelForEachBlock(const Mesh& mesh, ThreadPool& pool, Body&& body) {
  for (ElementType type : kAllElementTypes) {
    const ElementBlock& block = mesh.block(type);
    const auto count = static_cast<std::int64_t>(block.elements.size());
    if (count == 0) continue;
    DispatchElementType(type, [&]<ElementType kType>() {
      pool.ParallelFor(count, kElementGrain, [&](std::int64_t begin, std::int64_t end) {
        body.template operator()<kType>(block, begin, end);
      });
    });
  }
}

// Runs body.template operator()<kType>(block, begin, end) for the block entries at canonical
// positions [first, last) (Mesh::canonical_order), in that order: the blocks follow one another
// in the canonical order, so a range covers the tail of one block and the heads of the next.
template <typename Body>
void ForEachCanonicalRange(const Mesh& mesh, std::int64_t first, std::int64_t last, Body&& body) {
  std::int64_t block_first = 0;  // canonical position of the block's first entry
  for (ElementType type : kAllElementTypes) {
    const ElementBlock& block = mesh.block(type);
    const auto count = static_cast<std::int64_t>(block.elements.size());
    const std::int64_t begin = std::max(first, block_first);
    const std::int64_t end = std::min(last, block_first + count);
    if (begin < end) {
      DispatchElementType(type, [&]<ElementType kType>() {
        body.template operator()<kType>(block, begin - block_first, end - block_first);
      });
    }
    block_first += count;
  }
}

}  // namespace getme
