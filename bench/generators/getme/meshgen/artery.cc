#include "getme/meshgen/artery.h"

#include <gmsh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>

#include "absl/strings/str_cat.h"
#include "getme/meshgen/gmsh_tet_vessel.h"
#include "getme/meshgen/mesh_draft.h"
#include "getme/meshgen/prism_layer_extrusion.h"

namespace getme::meshgen {
namespace {

const char* const kWho = "Artery";
constexpr int kGmshDelaunay3d = 1;
// Cross-sections of the main vessel handed to OpenCASCADE's loft (ThruSections).
constexpr int kSections = 25;
constexpr double kStenosisWidth = 0.08;
constexpr double kBranchInclination = std::numbers::pi / 6.0;  // towards downstream, from normal
// Radians about the centre line from the direction away from the helix axis, per branch.
constexpr std::array<double, 3> kBranchAzimuth = {0.5, -1.0, 2.0};
constexpr double kBranchTaper = 0.85;

Vec3 Centreline(const ArteryOptions& o, double t) {
  const double a = o.helix_radius, phi = o.turn_angle * t;
  return Vec3(a * std::cos(phi) - a, a * std::sin(phi), o.length * t);
}

Vec3 Tangent(const ArteryOptions& o, double t) {
  const double a = o.helix_radius, phi = o.turn_angle * t;
  const Vec3 d(-a * o.turn_angle * std::sin(phi), a * o.turn_angle * std::cos(phi), o.length);
  return d / d.norm();
}

double Radius(const ArteryOptions& o, double t) {
  const double s = (t - 0.5) / kStenosisWidth;
  return o.radius * (1.0 - o.taper * t) * (1.0 - o.stenosis * std::exp(-s * s));
}

// Unit normal to the centre line pointing away from the helix axis (the x axis when straight).
Vec3 Inward(const ArteryOptions& o, double t);

// `v` turned by `angle` about the unit `axis` (Rodrigues).
Vec3 Rotated(const Vec3& v, const Vec3& axis, double angle) {
  return std::cos(angle) * v + std::sin(angle) * axis.cross(v) +
         (1.0 - std::cos(angle)) * axis.dot(v) * axis;
}

Vec3 Inward(const ArteryOptions& o, double t) {
  const Vec3 tangent = Tangent(o, t);
  const double phi = o.turn_angle * t;
  const Vec3 away = o.helix_radius > 0.0 ? Vec3(std::cos(phi), std::sin(phi), 0.0) : Vec3(1, 0, 0);
  return -(away - away.dot(tangent) * tangent).normalized();
}

std::vector<double> BranchPositions(int branches) {
  switch (branches) {
    case 1:
      return {0.3};
    case 2:
      return {0.3, 0.72};
    case 3:
      return {0.18, 0.38, 0.72};
    default:
      return {};
  }
}

struct Branch {
  Vec3 start;  // on the main centre line
  Vec3 direction;
  double start_radius = 0.0;
  double end_radius = 0.0;
};

std::vector<Branch> Branches(const ArteryOptions& o) {
  std::vector<Branch> branches;
  const std::vector<double> positions = BranchPositions(o.branches);
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const double t = positions[i];
    const Vec3 tangent = Tangent(o, t);
    // A frame normal to the tangent: n1 points away from the helix axis (the x axis for a
    // straight centre line), so that branches leave the coil instead of crossing it.
    const Vec3 n1 = -Inward(o, t);
    const Vec3 n2 = tangent.cross(n1);
    const double psi = kBranchAzimuth[i];
    const Vec3 radial = std::cos(psi) * n1 + std::sin(psi) * n2;
    Branch branch;
    branch.start = Centreline(o, t);
    branch.direction =
        (std::cos(kBranchInclination) * radial + std::sin(kBranchInclination) * tangent)
            .normalized();
    branch.start_radius = o.branch_radius_ratio * Radius(o, t);
    branch.end_radius = kBranchTaper * branch.start_radius;
    branches.push_back(branch);
  }
  return branches;
}

absl::Status ValidateOptions(const ArteryOptions& o) {
  const auto positive = [](double v) { return std::isfinite(v) && v > 0.0; };
  if (!positive(o.radius) || !positive(o.length) || !positive(o.mesh_size) ||
      !positive(o.branch_length) || !positive(o.first_layer_ratio) || !positive(o.growth_ratio)) {
    return absl::InvalidArgumentError(
        "Artery: radius, length, mesh_size, branch_length, first_layer_ratio and growth_ratio must "
        "be finite and > 0");
  }
  if (!(o.helix_radius >= 0.0) || !std::isfinite(o.turn_angle) || o.turn_angle < 0.0 ||
      o.turn_angle >= 2.0 * std::numbers::pi) {
    return absl::InvalidArgumentError(
        "Artery: helix_radius must be >= 0 and turn_angle in [0, 2π)");
  }
  // The helix's curvature radius (a² + c²)/a with c = length/turn_angle must exceed the radius.
  if (o.helix_radius > 0.0 && o.turn_angle > 0.0) {
    const double c = o.length / o.turn_angle;
    const double curvature_radius = (o.helix_radius * o.helix_radius + c * c) / o.helix_radius;
    if (curvature_radius <= 1.5 * o.radius) {
      return absl::InvalidArgumentError(absl::StrCat(
          "Artery: the centre line's radius of curvature ", curvature_radius,
          " must exceed 1.5 × the vessel radius; lengthen the vessel or flatten the helix"));
    }
  }
  if (!(o.taper >= 0.0 && o.taper < 0.8) || !(o.stenosis >= 0.0 && o.stenosis < 0.8)) {
    return absl::InvalidArgumentError("Artery: taper and stenosis must be in [0, 0.8)");
  }
  if (o.branches < 0 || o.branches > 3) {
    return absl::InvalidArgumentError(
        absl::StrCat("Artery: branches must be 0 to 3, got ", o.branches));
  }
  if (!(o.branch_radius_ratio > 0.0 && o.branch_radius_ratio < 0.8)) {
    return absl::InvalidArgumentError("Artery: branch_radius_ratio must be in (0, 0.8)");
  }
  if (!(o.junction_fillet >= 0.0 && o.junction_fillet < 1.0)) {
    return absl::InvalidArgumentError("Artery: junction_fillet must be in [0, 1)");
  }
  if (o.inward_layers < 0 || o.outward_layers < 0) {
    return absl::InvalidArgumentError("Artery: layer counts must be >= 0");
  }
  return absl::OkStatus();
}

// The surfaces to read back: group 0 the wall, group 1 + c cap c.
void GenerateWithGmsh(const ArteryOptions& o, const std::vector<CapPlane>& caps, RawGmshMesh& raw) {
  gmsh::option::setNumber("General.Terminal", 0);
  gmsh::option::setNumber("General.NumThreads", 1);
  gmsh::option::setNumber("Mesh.Algorithm3D", kGmshDelaunay3d);
  gmsh::option::setNumber("Mesh.RandomSeed", static_cast<double>(o.seed % (1u << 30)));
  gmsh::option::setNumber("Mesh.MeshSizeMin", o.mesh_size);
  gmsh::option::setNumber("Mesh.MeshSizeMax", o.mesh_size);
  gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
  gmsh::model::add("artery");

  // Main vessel: a loft through circles normal to the centre line. Each circle is made in the xy
  // plane, turned by the smallest rotation taking z to the tangent (the tangent always rises, so
  // the circles' start points stay aligned along the vessel), and moved onto the centre line.
  std::vector<int> wires;
  for (int k = 0; k < kSections; ++k) {
    const double t = static_cast<double>(k) / (kSections - 1);
    const int circle = gmsh::model::occ::addCircle(0, 0, 0, Radius(o, t));
    const Vec3 tangent = Tangent(o, t);
    const Vec3 axis = Vec3(0, 0, 1).cross(tangent);
    const double angle = std::atan2(axis.norm(), tangent.z());
    // The circle's start point (its seam, where OpenCASCADE may split a junction curve into
    // tiny pieces) goes to the helix's inner side, which the branches avoid: turn it about z
    // first so that the rotation below takes it there.
    const Vec3 seam = axis.norm() > 1e-12 ? Rotated(-Inward(o, t), axis.normalized(), -angle)
                                          : Vec3(-Inward(o, t));
    gmsh::model::occ::rotate({{1, circle}}, 0, 0, 0, 0, 0, 1, std::atan2(-seam.y(), -seam.x()));
    if (axis.norm() > 1e-12) {
      gmsh::model::occ::rotate({{1, circle}}, 0, 0, 0, axis.x(), axis.y(), axis.z(), angle);
    }
    const Vec3 centre = Centreline(o, t);
    gmsh::model::occ::translate({{1, circle}}, centre.x(), centre.y(), centre.z());
    wires.push_back(gmsh::model::occ::addWire({circle}));
  }
  gmsh::vectorpair loft;
  gmsh::model::occ::addThruSections(wires, loft, -1, /*makeSolid=*/true, /*makeRuled=*/false);
  gmsh::vectorpair main_volume;
  for (const auto& dim_tag : loft) {
    if (dim_tag.first == 3) main_volume.push_back(dim_tag);
  }
  gmsh::vectorpair branch_volumes;
  for (const Branch& b : Branches(o)) {
    const Vec3 axis = o.branch_length * b.direction;
    const int cone = gmsh::model::occ::addCone(b.start.x(), b.start.y(), b.start.z(), axis.x(),
                                               axis.y(), axis.z(), b.start_radius, b.end_radius);
    branch_volumes.emplace_back(3, cone);
  }
  if (!branch_volumes.empty()) {
    gmsh::vectorpair fused;
    std::vector<gmsh::vectorpair> map;
    gmsh::model::occ::fuse(main_volume, branch_volumes, fused, map);
  }
  gmsh::model::occ::synchronize();
  if (o.junction_fillet > 0.0 && !branch_volumes.empty()) {
    // The junction curves are the curves between two different wall surfaces (a cap's rim
    // borders a cap, the loft's seam borders its own surface twice).
    gmsh::vectorpair volumes;
    gmsh::model::getEntities(volumes, 3);
    std::vector<int> volume_tags, junction;
    for (const auto& [dim, tag] : volumes) volume_tags.push_back(tag);
    gmsh::vectorpair curves;
    gmsh::model::getEntities(curves, 1);
    for (const auto& [dim, tag] : curves) {
      std::vector<int> up, down;
      gmsh::model::getAdjacencies(dim, tag, up, down);
      std::sort(up.begin(), up.end());
      up.erase(std::unique(up.begin(), up.end()), up.end());
      if (up.size() != 2) continue;
      const bool on_cap = std::any_of(up.begin(), up.end(), [&](int surface) {
        double x, y, z;
        gmsh::model::occ::getCenterOfMass(2, surface, x, y, z);
        return std::any_of(caps.begin(), caps.end(), [&](const CapPlane& cap) {
          return (Vec3(x, y, z) - cap.centre).norm() < 1e-3 * o.radius;
        });
      });
      if (!on_cap) junction.push_back(tag);
    }
    gmsh::vectorpair filleted;
    gmsh::model::occ::fillet(volume_tags, junction, {o.junction_fillet * o.radius}, filleted,
                             /*removeVolume=*/true);
    gmsh::model::occ::synchronize();
  }

  // Caps: the planar surfaces whose centre of mass is a cap centre; everything else is wall.
  gmsh::vectorpair surfaces;
  gmsh::model::getEntities(surfaces, 2);
  std::vector<std::vector<int>> groups(1 + caps.size());
  for (const auto& [dim, tag] : surfaces) {
    double x, y, z;
    gmsh::model::occ::getCenterOfMass(dim, tag, x, y, z);
    int group = 0;
    for (std::size_t c = 0; c < caps.size(); ++c) {
      if ((Vec3(x, y, z) - caps[c].centre).norm() < 1e-3 * o.radius) {
        group = static_cast<int>(c) + 1;
      }
    }
    groups[group].push_back(tag);
  }
  for (std::size_t g = 1; g < groups.size(); ++g) {
    if (groups[g].size() != 1) {
      throw std::runtime_error(
          absl::StrCat("cap ", g - 1, " matched ", groups[g].size(), " surfaces"));
    }
  }
  gmsh::model::mesh::generate(3);
  ReadGmshMesh(groups, raw);
}

}  // namespace

std::vector<CapPlane> ArteryCaps(const ArteryOptions& o) {
  std::vector<CapPlane> caps;
  caps.push_back({Centreline(o, 0.0), -Tangent(o, 0.0), Radius(o, 0.0)});
  caps.push_back({Centreline(o, 1.0), Tangent(o, 1.0), Radius(o, 1.0)});
  for (const Branch& b : Branches(o)) {
    caps.push_back({b.start + o.branch_length * b.direction, b.direction, b.end_radius});
  }
  return caps;
}

absl::StatusOr<ArteryMesh> GenerateArtery(const ArteryOptions& options) {
  if (absl::Status status = ValidateOptions(options); !status.ok()) return status;
  const std::vector<CapPlane> caps = ArteryCaps(options);
  RawGmshMesh raw;
  if (absl::Status status =
          RunGmsh([&](RawGmshMesh& out) { GenerateWithGmsh(options, caps, out); }, raw, kWho);
      !status.ok()) {
    return status;
  }
  MeshDraft draft;
  absl::StatusOr<std::vector<std::vector<std::array<NodeId, 3>>>> surfaces =
      ImportGmshTets(raw, draft, kWho);
  if (!surfaces.ok()) return surfaces.status();
  const std::vector<std::array<NodeId, 3>>& wall = (*surfaces)[0];
  const std::vector<std::vector<std::array<NodeId, 3>>> cap_triangles(surfaces->begin() + 1,
                                                                      surfaces->end());
  ArteryMesh result;
  result.caps = caps;
  result.mean_wall_edge = MeanEdgeLength(draft, wall);
  result.first_layer_height = options.first_layer_ratio * result.mean_wall_edge;
  BoundaryLayerOptions layers;
  layers.inward_layers = options.inward_layers;
  layers.outward_layers = options.outward_layers;
  layers.first_layer_height = result.first_layer_height;
  layers.growth_ratio = options.growth_ratio;
  absl::StatusOr<BoundaryLayerReport> report =
      GrowBoundaryLayers(draft, wall, cap_triangles, caps, layers);
  if (!report.ok()) return report.status();
  result.layers = *report;
  absl::StatusOr<Mesh> mesh = std::move(draft).Build();
  if (!mesh.ok()) return mesh.status();
  result.mesh = *std::move(mesh);
  return result;
}

absl::StatusOr<Mesh> Artery(const ArteryOptions& options) {
  absl::StatusOr<ArteryMesh> artery = GenerateArtery(options);
  if (!artery.ok()) return artery.status();
  return std::move(artery->mesh);
}

}  // namespace getme::meshgen
