#include "getme_wire/mesh_fields.h"

namespace getme::wire {

int WireGroupOf(ElementType type) {
  for (int group = 0; group < kWireElementGroupCount; ++group) {
    if (kWireElementGroups[group].type == type) return group;
  }
  return 0;  // unreachable: every engine type has a group
}

const Indices& Connectivity(const v1::Mesh& mesh, int group) {
  switch (group) {
    case 0:
      return mesh.tetrahedra();
    case 1:
      return mesh.hexahedra();
    case 2:
      return mesh.wedges();
    default:
      return mesh.pyramids();
  }
}

Indices* MutableConnectivity(v1::Mesh& mesh, int group) {
  switch (group) {
    case 0:
      return mesh.mutable_tetrahedra();
    case 1:
      return mesh.mutable_hexahedra();
    case 2:
      return mesh.mutable_wedges();
    default:
      return mesh.mutable_pyramids();
  }
}

std::int64_t WireElementCount(const v1::Mesh& mesh) {
  std::int64_t count = 0;
  for (int group = 0; group < kWireElementGroupCount; ++group) {
    count += Connectivity(mesh, group).size() / NodeCount(kWireElementGroups[group].type);
  }
  return count;
}

v1::MeshSize SizeOf(const v1::Mesh& mesh) {
  v1::MeshSize size;
  size.set_nodes(mesh.coordinates_size() / 3);
  size.set_tetrahedra(mesh.tetrahedra_size() / 4);
  size.set_hexahedra(mesh.hexahedra_size() / 8);
  size.set_wedges(mesh.wedges_size() / 6);
  size.set_pyramids(mesh.pyramids_size() / 5);
  return size;
}

}  // namespace getme::wire
