#include "mesh_checks.h"

#include <algorithm>

#include "getme/elements/element_quality.h"
#include "getme/elements/element_tables.h"

namespace getme::testing {

FaceCensus CensusFaces(const Mesh& mesh) {
  FaceCensus census;
  for (ElementId e = 0; e < mesh.element_count(); ++e) {
    const std::span<const NodeId> nodes = mesh.element_nodes(e);
    DispatchElementType(mesh.type(e), [&]<ElementType kType>() {
      for (const FaceIndices& face : ElementTable<kType>::kFaces) {
        std::vector<NodeId> face_nodes;
        for (int k = 0; k < face.size; ++k) face_nodes.push_back(nodes[face.nodes[k]]);
        std::vector<NodeId> key = face_nodes;
        std::sort(key.begin(), key.end());
        FaceUse& use = census[key];
        if (use.elements.empty()) use.nodes = face_nodes;
        use.elements.push_back(e);
      }
    });
  }
  return census;
}

std::vector<ElementId> InvalidElements(const Mesh& mesh) {
  std::vector<ElementId> invalid;
  for (ElementId e = 0; e < mesh.element_count(); ++e) {
    const NodeId* ids = mesh.element_nodes(e).data();
    const bool valid = DispatchElementType(mesh.type(e), [&]<ElementType kType>() {
      return IsValid<kType>(GatherNodes<kType>(mesh, ids));
    });
    if (!valid) invalid.push_back(e);
  }
  return invalid;
}

std::vector<double> MeanRatios(const Mesh& mesh) {
  std::vector<double> quality(mesh.element_count());
  for (ElementId e = 0; e < mesh.element_count(); ++e) {
    const NodeId* ids = mesh.element_nodes(e).data();
    quality[e] = DispatchElementType(mesh.type(e), [&]<ElementType kType>() {
      return MeanRatio<kType>(GatherNodes<kType>(mesh, ids));
    });
  }
  return quality;
}

double FaceArea(const Mesh& mesh, const std::vector<NodeId>& nodes) {
  const Vec3 a = NodePosition(mesh, nodes[0]);
  double area = 0.0;
  for (std::size_t k = 1; k + 1 < nodes.size(); ++k) {
    const Vec3 b = NodePosition(mesh, nodes[k]);
    const Vec3 c = NodePosition(mesh, nodes[k + 1]);
    area += 0.5 * (b - a).cross(c - a).norm();
  }
  return area;
}

Vec3 ElementCentroid(const Mesh& mesh, ElementId element) {
  Vec3 sum = Vec3::Zero();
  const std::span<const NodeId> nodes = mesh.element_nodes(element);
  for (const NodeId node : nodes) sum += NodePosition(mesh, node);
  return sum / static_cast<double>(nodes.size());
}

double EnclosedVolume(const Mesh& mesh) {
  double volume = 0.0;
  for (const auto& [key, use] : CensusFaces(mesh)) {
    if (use.elements.size() != 1) continue;
    const Vec3 a = NodePosition(mesh, use.nodes[0]);
    Vec3 face_centre = Vec3::Zero();
    Vec3 area_normal = Vec3::Zero();
    double signed_volume = 0.0;
    for (std::size_t k = 0; k < use.nodes.size(); ++k) {
      face_centre += NodePosition(mesh, use.nodes[k]) / static_cast<double>(use.nodes.size());
    }
    for (std::size_t k = 1; k + 1 < use.nodes.size(); ++k) {
      const Vec3 b = NodePosition(mesh, use.nodes[k]);
      const Vec3 c = NodePosition(mesh, use.nodes[k + 1]);
      area_normal += (b - a).cross(c - a);
      signed_volume += a.dot(b.cross(c)) / 6.0;
    }
    const bool outward = area_normal.dot(face_centre - ElementCentroid(mesh, use.elements[0])) > 0;
    volume += outward ? signed_volume : -signed_volume;
  }
  return volume;
}

BlockFaceReport CheckBlockFaces(const Mesh& mesh, int nx, int ny, int nz) {
  const std::array<double, 3> extent = {double(nx), double(ny), double(nz)};
  BlockFaceReport report;
  for (const auto& [key, use] : CensusFaces(mesh)) {
    const std::size_t count = use.elements.size();
    if (count == 2) ++report.shared_faces;
    if (count > 2) ++report.overused_faces;
    if (count != 1) continue;
    ++report.boundary_faces;
    report.boundary_area += FaceArea(mesh, use.nodes);
    bool on_surface = false;
    for (int axis = 0; axis < 3; ++axis) {
      for (const double plane : {0.0, extent[axis]}) {
        on_surface |= std::all_of(use.nodes.begin(), use.nodes.end(), [&](NodeId node) {
          return NodePosition(mesh, node)[axis] == plane;
        });
      }
    }
    if (!on_surface) ++report.inner_boundary_faces;
  }
  return report;
}

}  // namespace getme::testing
