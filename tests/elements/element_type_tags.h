#pragma once

// Typed-test plumbing: every element-level behaviour is checked for all four element types.

#include <gtest/gtest.h>

#include <string>

#include "getme/elements/element_type.h"

namespace getme::test {

template <ElementType kElementType>
struct TypeTag {
  static constexpr ElementType kType = kElementType;
};

using TetTag = TypeTag<ElementType::kTetrahedron>;
using HexTag = TypeTag<ElementType::kHexahedron>;
using PyramidTag = TypeTag<ElementType::kPyramid>;
using PrismTag = TypeTag<ElementType::kPrism>;

using AllElementTypes = ::testing::Types<TetTag, HexTag, PyramidTag, PrismTag>;

struct ElementTypeName {
  template <typename Tag>
  static std::string GetName(int) {
    return std::string(TypeName(Tag::kType));
  }
};

}  // namespace getme::test
