#pragma once

#include <cstdint>
#include <span>

#include "getme/mesh/mesh.h"

namespace getme {

// Calls run(type, begin, end) for each longest stretch [begin, end) of `elements` whose elements
// all have one type, in order. A node's element row and a pick's neighbour list are in canonical
// order, so grouped by type: each stretch goes to one type's element-list pass
// (smoothing/element_passes.h), several elements side by side.
template <typename Run>
void ForEachTypeRun(const Mesh& mesh, std::span<const ElementId> elements, Run&& run) {
  const auto count = static_cast<std::int64_t>(elements.size());
  for (std::int64_t begin = 0; begin < count;) {
    const ElementType type = mesh.type(elements[begin]);
    std::int64_t end = begin + 1;
    while (end < count && mesh.type(elements[end]) == type) ++end;
    run(type, begin, end);
    begin = end;
  }
}

}  // namespace getme
