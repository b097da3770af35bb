#pragma once

#include <array>
#include <cstdint>

#include "getme/elements/element_type.h"
#include "getme/v1/mesh.pb.h"
#include "getme/v1/smoother.pb.h"

namespace getme::wire {

// The layout of getme.v1.Mesh (proto/getme/v1/mesh.proto): its element fields in the order of
// the wire's element numbering, and how many elements a mesh carries.

using Indices = google::protobuf::RepeatedField<std::uint32_t>;

struct WireElementGroup {
  const char* field;  // name of the Mesh field
  const char* name;   // one element of it
  ElementType type;
};
inline constexpr int kWireElementGroupCount = 4;
inline constexpr std::array<WireElementGroup, kWireElementGroupCount> kWireElementGroups = {{
    {"tetrahedra", "tetrahedron", ElementType::kTetrahedron},
    {"hexahedra", "hexahedron", ElementType::kHexahedron},
    {"wedges", "wedge", ElementType::kPrism},
    {"pyramids", "pyramid", ElementType::kPyramid},
}};
// The engine's types in the wire's element numbering (MeshBuilder::NumberElementsByType).
inline constexpr std::array<ElementType, kElementTypeCount> kWireElementOrder = {
    ElementType::kTetrahedron, ElementType::kHexahedron, ElementType::kPrism,
    ElementType::kPyramid};

// Position of an engine type in kWireElementGroups.
int WireGroupOf(ElementType type);

const Indices& Connectivity(const v1::Mesh& mesh, int group);
Indices* MutableConnectivity(v1::Mesh& mesh, int group);

// Complete elements in the mesh (a trailing partial element is not counted).
std::int64_t WireElementCount(const v1::Mesh& mesh);
// The sizes a mesh's chunks add up to (SmoothHeader.expected_size).
v1::MeshSize SizeOf(const v1::Mesh& mesh);

}  // namespace getme::wire
