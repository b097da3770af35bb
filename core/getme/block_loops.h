#pragma once

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

}  // namespace getme
