#include "getme/meshgen/gmsh_tet_vessel.h"

#include <gmsh.h>

#include <algorithm>
#include <cstddef>
#include <functional>
#include <mutex>
#include <stdexcept>
#include <string>
#include <utility>

#include "absl/container/flat_hash_map.h"
#include "absl/strings/str_cat.h"

#if defined(__SANITIZE_ADDRESS__)
// gmsh 4.8 leaks a few kB of surface-meshing scratch per run (allocated under meshGFace and never
// freed, also after gmsh::finalize), which LeakSanitizer would report at the exit of every program
// that builds a vessel. The leak is inside libgmsh, so only its frames are suppressed. ASan calls
// this hook once at start-up; a program defining its own must add this line to it.
extern "C" const char* __lsan_default_suppressions() { return "leak:libgmsh.so\n"; }
#endif

namespace getme::meshgen {
namespace {

constexpr int kGmshTriangle = 2;
constexpr int kGmshTetrahedron = 4;
constexpr int kGmshDelaunay3d = 1;

// gmsh keeps one global model; concurrent callers would mesh into each other's geometry.
std::mutex& GmshMutex() {
  static std::mutex mutex;
  return mutex;
}

// Initialises gmsh for one meshing run and always finalises it, also when gmsh throws.
class GmshSession {
 public:
  GmshSession() {
    // No config files: a user's ~/.gmshrc must not change the mesh.
    gmsh::initialize(0, nullptr, /*readConfigFiles=*/false);
  }
  ~GmshSession() { gmsh::finalize(); }
  GmshSession(const GmshSession&) = delete;
  GmshSession& operator=(const GmshSession&) = delete;
};

void GenerateWithGmsh(const ThinPrismVesselOptions& options, RawGmshMesh& raw) {
  gmsh::option::setNumber("General.Terminal", 0);
  gmsh::option::setNumber("General.NumThreads", 1);
  gmsh::option::setNumber("Mesh.Algorithm3D", kGmshDelaunay3d);
  gmsh::option::setNumber("Mesh.RandomSeed", static_cast<double>(options.seed % (1u << 30)));
  gmsh::option::setNumber("Mesh.MeshSizeMin", options.mesh_size);
  gmsh::option::setNumber("Mesh.MeshSizeMax", options.mesh_size);
  gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
  gmsh::model::add("vessel");
  const double segment_length = SegmentLength(options);
  if (options.bend_angle > 0.0) {
    // A torus section around the z axis: its centreline is an arc of the given length.
    gmsh::model::occ::addTorus(0, 0, 0, options.length / options.bend_angle, options.radius, -1,
                               options.bend_angle);
  } else {
    gmsh::model::occ::addCylinder(0, 0, 0, 0, 0, segment_length, options.radius);
  }
  gmsh::model::occ::synchronize();
  if (options.segments > 1) {
    // Copies of the segment are stacked along z (vessel_segments.h): the top cap's mesh must be
    // the bottom cap's, moved up by the segment length.
    gmsh::vectorpair surfaces;
    gmsh::model::getEntities(surfaces, 2);
    int bottom = -1, top = -1;
    for (const auto& [dim, tag] : surfaces) {
      std::string type;
      gmsh::model::getType(dim, tag, type);
      if (type != "Plane") continue;
      double x, y, z;
      gmsh::model::occ::getCenterOfMass(dim, tag, x, y, z);
      (z < 0.5 * segment_length ? bottom : top) = tag;
    }
    const std::vector<double> translation = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, segment_length,
                                             0, 0, 0, 1};
    gmsh::model::mesh::setPeriodic(2, {top}, {bottom}, translation);
  }
  gmsh::model::mesh::generate(3);

  // The end caps are the planar surfaces; everything else (cylinder or torus) is the wall.
  gmsh::vectorpair surfaces;
  gmsh::model::getEntities(surfaces, 2);
  std::vector<int> wall;
  for (const auto& [dim, tag] : surfaces) {
    std::string type;
    gmsh::model::getType(dim, tag, type);
    if (type != "Plane") wall.push_back(tag);
  }
  ReadGmshMesh({wall}, raw);
}

std::array<NodeId, 3> SortedTriangle(NodeId a, NodeId b, NodeId c) {
  std::array<NodeId, 3> key = {a, b, c};
  std::sort(key.begin(), key.end());
  return key;
}

}  // namespace

void ReadGmshMesh(const std::vector<std::vector<int>>& surface_groups, RawGmshMesh& raw) {
  std::vector<double> parametric;
  gmsh::model::mesh::getNodes(raw.node_tags, raw.node_coords, parametric, -1, -1,
                              /*includeBoundary=*/false, /*returnParametricCoord=*/false);
  // Fresh output vectors for every call: gmsh 4.8 returned no triangles into a vector that still
  // held the tetrahedra's tags (it takes non-empty vectors as preallocated storage).
  std::vector<std::size_t> tet_tags;
  gmsh::model::mesh::getElementsByType(kGmshTetrahedron, tet_tags, raw.tet_nodes);
  raw.surface_nodes.assign(surface_groups.size(), {});
  for (std::size_t group = 0; group < surface_groups.size(); ++group) {
    for (const int tag : surface_groups[group]) {
      std::vector<std::size_t> triangle_tags, triangle_nodes;
      gmsh::model::mesh::getElementsByType(kGmshTriangle, triangle_tags, triangle_nodes, tag);
      raw.surface_nodes[group].insert(raw.surface_nodes[group].end(), triangle_nodes.begin(),
                                      triangle_nodes.end());
    }
  }
}

absl::Status RunGmsh(const std::function<void(RawGmshMesh&)>& generate, RawGmshMesh& raw,
                     const std::string& who) {
  std::lock_guard<std::mutex> lock(GmshMutex());
  try {
    GmshSession session;
    try {
      generate(raw);
    } catch (const std::exception& e) {
      return absl::InternalError(absl::StrCat(who, ": ", e.what()));
    } catch (...) {
      // gmsh's API throws without a message of its own; its logger keeps the last error, and
      // must be read before the session finalises gmsh.
      std::string error;
      gmsh::logger::getLastError(error);
      return absl::InternalError(absl::StrCat(
          who, ": gmsh failed to mesh the vessel: ", error.empty() ? "no message" : error));
    }
  } catch (...) {
    return absl::InternalError(absl::StrCat(who, ": gmsh failed to start or to shut down"));
  }
  return absl::OkStatus();
}

double SegmentLength(const ThinPrismVesselOptions& options) {
  return options.length / std::max(1, options.segments);
}

absl::StatusOr<std::vector<std::vector<std::array<NodeId, 3>>>> ImportGmshTets(
    const RawGmshMesh& raw, MeshDraft& draft, const std::string& who) {
  // Meshing failures that gmsh only logs (it does not throw unless General.AbortOnError) show up
  // as an empty mesh.
  for (std::size_t group = 0; group < raw.surface_nodes.size(); ++group) {
    if (raw.tet_nodes.empty() || raw.surface_nodes[group].empty()) {
      return absl::InternalError(
          absl::StrCat(who, ": gmsh produced ", raw.tet_nodes.size() / 4, " tetrahedra and ",
                       raw.surface_nodes[group].size() / 3, " triangles in surface group ", group));
    }
  }

  // Keep only nodes the tetrahedra use, in ascending tag order.
  std::vector<std::size_t> used_tags = raw.tet_nodes;
  std::sort(used_tags.begin(), used_tags.end());
  used_tags.erase(std::unique(used_tags.begin(), used_tags.end()), used_tags.end());
  absl::flat_hash_map<std::size_t, std::size_t> coord_index;
  for (std::size_t n = 0; n < raw.node_tags.size(); ++n) coord_index[raw.node_tags[n]] = n;
  absl::flat_hash_map<std::size_t, NodeId> node_of_tag;
  for (const std::size_t tag : used_tags) {
    const auto it = coord_index.find(tag);
    if (it == coord_index.end()) {
      return absl::InternalError(
          absl::StrCat(who, ": gmsh tetrahedron uses unknown node tag ", tag));
    }
    const double* p = &raw.node_coords[3 * it->second];
    node_of_tag[tag] = draft.AddNode(Vec3(p[0], p[1], p[2]));
  }

  // Tetrahedra, oriented valid; remember each face's opposite node to orient the wall outward.
  absl::flat_hash_map<std::array<NodeId, 3>, NodeId> opposite_of_face;
  constexpr std::array<std::array<int, 4>, 4> kFaceAndOpposite = {
      {{0, 1, 2, 3}, {0, 1, 3, 2}, {0, 2, 3, 1}, {1, 2, 3, 0}}};
  for (std::size_t t = 0; t < raw.tet_nodes.size(); t += 4) {
    std::array<NodeId, 4> tet;
    for (int k = 0; k < 4; ++k) tet[k] = node_of_tag.at(raw.tet_nodes[t + k]);
    const Vec3 p0 = draft.node(tet[0]);
    const double det =
        (draft.node(tet[1]) - p0).dot((draft.node(tet[2]) - p0).cross(draft.node(tet[3]) - p0));
    if (det < 0.0) std::swap(tet[1], tet[2]);
    const ElementId element = draft.AddElement(ElementType::kTetrahedron, tet);
    if (!draft.IsElementValid(element)) {
      return absl::InternalError(absl::StrCat(who, ": gmsh tetrahedron ", t / 4,
                                              " is degenerate (volume ", det / 6.0, ")"));
    }
    for (const auto& f : kFaceAndOpposite) {
      opposite_of_face[SortedTriangle(tet[f[0]], tet[f[1]], tet[f[2]])] = tet[f[3]];
    }
  }

  std::vector<std::vector<std::array<NodeId, 3>>> groups(raw.surface_nodes.size());
  for (std::size_t group = 0; group < raw.surface_nodes.size(); ++group) {
    const std::vector<std::size_t>& nodes = raw.surface_nodes[group];
    groups[group].reserve(nodes.size() / 3);
    for (std::size_t w = 0; w < nodes.size(); w += 3) {
      std::array<NodeId, 3> triangle;
      for (int k = 0; k < 3; ++k) {
        const auto it = node_of_tag.find(nodes[w + k]);
        if (it == node_of_tag.end()) {
          return absl::InternalError(absl::StrCat(who, ": surface triangle ", w / 3,
                                                  " uses node tag ", nodes[w + k],
                                                  " that no tetrahedron uses"));
        }
        triangle[k] = it->second;
      }
      const auto opposite =
          opposite_of_face.find(SortedTriangle(triangle[0], triangle[1], triangle[2]));
      if (opposite == opposite_of_face.end()) {
        return absl::InternalError(
            absl::StrCat(who, ": surface triangle ", w / 3, " is not a face of any tetrahedron"));
      }
      // Counter-clockwise seen from outside: the normal points away from the tetrahedron.
      const Vec3 a = draft.node(triangle[0]);
      const Vec3 normal = (draft.node(triangle[1]) - a).cross(draft.node(triangle[2]) - a);
      if (normal.dot(draft.node(opposite->second) - a) > 0.0) std::swap(triangle[1], triangle[2]);
      groups[group].push_back(triangle);
    }
  }
  return groups;
}

absl::StatusOr<TetVessel> MeshTetVessel(const ThinPrismVesselOptions& options, MeshDraft& draft) {
  RawGmshMesh raw;
  if (absl::Status status = RunGmsh(
          [&options](RawGmshMesh& out) { GenerateWithGmsh(options, out); }, raw, "ThinPrismVessel");
      !status.ok()) {
    return status;
  }
  absl::StatusOr<std::vector<std::vector<std::array<NodeId, 3>>>> surfaces =
      ImportGmshTets(raw, draft, "ThinPrismVessel");
  if (!surfaces.ok()) return surfaces.status();
  TetVessel vessel;
  vessel.wall_triangles = std::move((*surfaces)[0]);
  return vessel;
}

}  // namespace getme::meshgen
