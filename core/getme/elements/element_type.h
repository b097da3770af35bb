#pragma once

#include <array>
#include <cstdint>
#include <string_view>

namespace getme {

// The four volume element kinds of the paper (Fig. 1). The numeric values index per-type arrays.
enum class ElementType : std::uint8_t {
  kTetrahedron = 0,
  kHexahedron = 1,
  kPyramid = 2,
  kPrism = 3
};

inline constexpr int kElementTypeCount = 4;
inline constexpr std::array<ElementType, kElementTypeCount> kAllElementTypes = {
    ElementType::kTetrahedron, ElementType::kHexahedron, ElementType::kPyramid,
    ElementType::kPrism};

constexpr int TypeIndex(ElementType type) { return static_cast<int>(type); }

constexpr int NodeCount(ElementType type) {
  constexpr std::array<int, kElementTypeCount> kCounts = {4, 8, 5, 6};
  return kCounts[TypeIndex(type)];
}

// const char* rather than std::string_view: Debian's Abseil is built with its own
// absl::string_view, which does not convert from std::string_view (so StrCat would not accept it).
constexpr const char* TypeName(ElementType type) {
  constexpr std::array<const char*, kElementTypeCount> kNames = {"tetrahedron", "hexahedron",
                                                                 "pyramid", "prism"};
  return kNames[TypeIndex(type)];
}

// The largest element (hexahedron) has 8 nodes; fixed-size scratch buffers use this bound.
inline constexpr int kMaxElementNodes = 8;

}  // namespace getme
