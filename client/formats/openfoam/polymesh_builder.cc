#include "formats/openfoam/polymesh_builder.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <map>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "absl/container/flat_hash_map.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_join.h"
#include "formats/vtk_cell_type.h"

namespace getme::formats {
namespace {

using FaceKey = std::array<std::int64_t, 4>;  // sorted point labels, -1 padded

struct LocalFace {
  int size;
  std::array<int, 4> nodes;
};

// The faces of each VTK cell, their points ordered so that the right-hand normal points out of
// the cell (checked against a regular element of each type in docs/node-orders.md's orientation).
std::span<const LocalFace> OutwardFaces(int vtk_type) {
  static constexpr LocalFace kTetra[] = {
      {3, {0, 2, 1}}, {3, {0, 1, 3}}, {3, {1, 2, 3}}, {3, {0, 3, 2}}};
  static constexpr LocalFace kHexahedron[] = {{4, {0, 3, 2, 1}}, {4, {4, 5, 6, 7}},
                                              {4, {0, 1, 5, 4}}, {4, {1, 2, 6, 5}},
                                              {4, {2, 3, 7, 6}}, {4, {3, 0, 4, 7}}};
  // VTK's wedge: triangle 0, 1, 2 already faces away from 3, 4, 5.
  static constexpr LocalFace kWedge[] = {
      {3, {0, 1, 2}}, {3, {3, 5, 4}}, {4, {0, 2, 5, 3}}, {4, {2, 1, 4, 5}}, {4, {1, 0, 3, 4}}};
  static constexpr LocalFace kPyramid[] = {
      {4, {0, 3, 2, 1}}, {3, {0, 1, 4}}, {3, {1, 2, 4}}, {3, {2, 3, 4}}, {3, {3, 0, 4}}};
  switch (vtk_type) {
    case kVtkTetra:
      return kTetra;
    case kVtkHexahedron:
      return kHexahedron;
    case kVtkWedge:
      return kWedge;
    case kVtkPyramid:
      return kPyramid;
    default:
      return {};
  }
}

FaceKey KeyOf(std::span<const std::int64_t> points) {
  FaceKey key{-1, -1, -1, -1};
  const std::size_t size = std::min<std::size_t>(points.size(), key.size());
  std::copy_n(points.begin(), size, key.begin());
  std::sort(key.begin(), key.begin() + static_cast<std::ptrdiff_t>(size));
  return key;
}

struct Face {
  std::array<std::int64_t, 4> points;
  int size = 0;
  std::int64_t owner = -1;
  std::int64_t neighbour = -1;
  std::int64_t patch = -1;  // boundary: its group, or -1 for defaultFaces
};

std::string Header(const char* class_name, const char* object, Encoding encoding,
                   const std::string& note = {}) {
  const bool binary = encoding == Encoding::kBinary;
  return absl::StrCat("FoamFile\n{\n    version     2.0;\n    format      ",
                      binary ? "binary" : "ascii", ";\n    class       ", class_name, ";\n",
                      binary ? "    arch        \"LSB;label=32;scalar=64\";\n" : "",
                      note.empty() ? "" : absl::StrCat("    note        \"", note, "\";\n"),
                      "    location    \"constant/polyMesh\";\n    object      ", object,
                      ";\n}\n// Written by getme\n\n");
}

std::string LabelList(const std::vector<std::int64_t>& labels, Encoding encoding) {
  std::string out = absl::StrCat(labels.size(), "\n(");
  if (encoding == Encoding::kBinary) {
    const std::size_t first = out.size();
    out.resize(first + 4 * labels.size());
    for (std::size_t i = 0; i < labels.size(); ++i) {
      const std::int32_t label = static_cast<std::int32_t>(labels[i]);
      std::memcpy(out.data() + first + 4 * i, &label, 4);
    }
  } else {
    out += '\n';
    for (const std::int64_t label : labels) absl::StrAppend(&out, label, "\n");
  }
  out += ")\n";
  return out;
}

// The surface group of each tagged triangle and quad, by its sorted points.
absl::flat_hash_map<FaceKey, std::int64_t> SurfaceGroups(const UnstructuredGrid& grid) {
  absl::flat_hash_map<FaceKey, std::int64_t> groups;
  for (const char* name : {"gmsh:physical", "medit:ref", "su2:tag", "cgns:bc"}) {
    const DataArray* tags = FindArray(grid.cell_data, name);
    if (tags == nullptr || tags->components != 1 || tags->tuple_count() != grid.cells.size()) {
      continue;
    }
    for (std::int64_t cell = 0; cell < grid.cells.size(); ++cell) {
      const int type = grid.cells.types[cell];
      const std::int64_t size = grid.cells.node_count(cell);
      if (!((type == kVtkTriangle && size == 3) || (type == kVtkQuad && size == 4))) continue;
      const std::int64_t tag = static_cast<std::int64_t>(tags->AsDouble(cell));
      if (tag == 0) continue;
      groups[KeyOf({grid.cells.nodes(cell), static_cast<std::size_t>(size)})] = tag;
    }
    break;
  }
  return groups;
}

// A Gmsh physical surface's name where the file gives one and it is a valid OpenFOAM word (no
// white space, quote, bracket, brace, ';' or '/'), else "group<N>".
std::string PatchName(const MeshDocument& document, std::int64_t tag) {
  if (document.gmsh.has_value()) {
    for (const GmshPhysicalName& physical : document.gmsh->physical_names) {
      if (physical.dim != 2 || physical.tag != tag || physical.name.empty()) continue;
      if (physical.name.find_first_of(" \t\n\"'(){};/") == std::string::npos) return physical.name;
    }
  }
  return absl::StrCat("group", tag);
}

}  // namespace

absl::StatusOr<OpenFoamExtras> BuildPolyMesh(const MeshDocument& document, Encoding encoding) {
  const UnstructuredGrid& grid = document.grid;
  const std::int64_t point_count = grid.point_count();
  std::vector<Face> faces;
  absl::flat_hash_map<FaceKey, std::int64_t> face_of_key;
  std::int64_t cell_count = 0;
  for (std::int64_t cell = 0; cell < grid.cells.size(); ++cell) {
    const int type = grid.cells.types[cell];
    const std::optional<VtkCellTypeInfo> info = CellTypeInfo(type);
    if (info.has_value() && info->role == VtkCellRole::kPassthrough) continue;
    const std::span<const LocalFace> local = OutwardFaces(type);
    if (local.empty() || grid.cells.node_count(cell) != info->node_count) {
      return absl::InvalidArgumentError(absl::StrCat(
          "cell ", cell, " (VTK type ", type, info ? absl::StrCat(" ", info->name) : "",
          ") cannot be written to an OpenFOAM polyMesh: only tetrahedra, pyramids, wedges and "
          "hexahedra are"));
    }
    const std::int64_t* nodes = grid.cells.nodes(cell);
    for (int k = 0; k < info->node_count; ++k) {
      if (nodes[k] < 0 || nodes[k] >= point_count) {
        return absl::InvalidArgumentError(absl::StrCat("cell ", cell, " refers to point ", nodes[k],
                                                       ", but there are ", point_count, " points"));
      }
    }
    for (int k = 1; k < info->node_count; ++k) {
      if (std::find(nodes, nodes + k, nodes[k]) != nodes + k) {
        return absl::InvalidArgumentError(
            absl::StrCat("cell ", cell, " (", info->name, ") lists point ", nodes[k],
                         " twice: a degenerate cell cannot be written to an OpenFOAM polyMesh"));
      }
    }
    const std::int64_t foam_cell = cell_count++;
    for (const LocalFace& face : local) {
      Face built;
      built.size = face.size;
      for (int k = 0; k < face.size; ++k) built.points[k] = nodes[face.nodes[k]];
      const FaceKey key = KeyOf({built.points.data(), static_cast<std::size_t>(face.size)});
      const auto [found, inserted] =
          face_of_key.try_emplace(key, static_cast<std::int64_t>(faces.size()));
      if (inserted) {
        built.owner = foam_cell;
        faces.push_back(built);
        continue;
      }
      Face& shared = faces[found->second];
      if (shared.neighbour >= 0 || shared.owner == foam_cell) {
        return absl::InvalidArgumentError(absl::StrCat(
            "cell ", cell, ": a face with the points ", absl::StrJoin(key, " "),
            " is shared by more than two cells (or twice by one): not a valid polyMesh"));
      }
      // The neighbour must see the face the other way round (its outward normal is the owner's
      // inward one); otherwise one of the two cells is inverted, which no face order can express.
      bool reversed = false;
      for (int start = 0; start < face.size && !reversed; ++start) {
        reversed = true;
        for (int k = 0; k < face.size && reversed; ++k) {
          reversed = built.points[k] == shared.points[(start - k + face.size) % face.size];
        }
      }
      if (!reversed) {
        return absl::InvalidArgumentError(absl::StrCat(
            "cell ", cell, " and the cell before it sharing the face with the points ",
            absl::StrJoin(key.begin(), key.begin() + face.size, " "),
            " are oriented against each other (one is inverted): an OpenFOAM polyMesh cannot hold "
            "that; smooth (untangle) the mesh first"));
      }
      shared.neighbour = foam_cell;
    }
  }
  if (cell_count == 0) {
    return absl::InvalidArgumentError(
        "no volume cells to write as an OpenFOAM polyMesh (tetrahedra, pyramids, wedges, "
        "hexahedra)");
  }

  // Internal faces in upper-triangular order, then the boundary faces by patch.
  const absl::flat_hash_map<FaceKey, std::int64_t> groups = SurfaceGroups(grid);
  std::vector<std::int64_t> patch_tags;
  for (Face& face : faces) {
    if (face.neighbour >= 0) continue;
    const auto group =
        groups.find(KeyOf({face.points.data(), static_cast<std::size_t>(face.size)}));
    if (group != groups.end()) {
      face.patch = group->second;
      patch_tags.push_back(group->second);
    }
  }
  std::sort(patch_tags.begin(), patch_tags.end());
  patch_tags.erase(std::unique(patch_tags.begin(), patch_tags.end()), patch_tags.end());
  const auto rank = [&](const Face& face) -> std::int64_t {
    if (face.neighbour >= 0) return -1;
    if (face.patch < 0) return static_cast<std::int64_t>(patch_tags.size());
    return std::lower_bound(patch_tags.begin(), patch_tags.end(), face.patch) - patch_tags.begin();
  };
  std::stable_sort(faces.begin(), faces.end(), [&](const Face& a, const Face& b) {
    const std::int64_t ra = rank(a);
    const std::int64_t rb = rank(b);
    if (ra != rb) return ra < rb;
    if (ra >= 0) return false;  // boundary faces keep their order within a patch
    return a.owner != b.owner ? a.owner < b.owner : a.neighbour < b.neighbour;
  });

  std::vector<std::int64_t> offsets{0};
  std::vector<std::int64_t> labels;
  std::vector<std::int64_t> owner;
  std::vector<std::int64_t> neighbour;
  for (const Face& face : faces) {
    labels.insert(labels.end(), face.points.begin(), face.points.begin() + face.size);
    offsets.push_back(static_cast<std::int64_t>(labels.size()));
    owner.push_back(face.owner);
    if (face.neighbour >= 0) neighbour.push_back(face.neighbour);
  }
  const std::int64_t internal = static_cast<std::int64_t>(neighbour.size());

  OpenFoamExtras extras;
  std::int64_t start = internal;
  for (std::size_t p = 0; p <= patch_tags.size(); ++p) {
    const std::int64_t count =
        std::count_if(faces.begin() + internal, faces.end(),
                      [&](const Face& f) { return rank(f) == static_cast<std::int64_t>(p); });
    if (p == patch_tags.size() && count == 0) break;
    extras.patches.push_back(
        {p < patch_tags.size() ? PatchName(document, patch_tags[p]) : std::string("defaultFaces"),
         "patch", start, count});
    start += count;
  }
  const std::string note = absl::StrCat("nPoints:", point_count, "  nCells:", cell_count,
                                        "  nFaces:", faces.size(), "  nInternalFaces:", internal);
  std::string faces_text;
  if (encoding == Encoding::kBinary) {
    faces_text = absl::StrCat(Header("faceCompactList", "faces", encoding),
                              LabelList(offsets, encoding), "\n", LabelList(labels, encoding));
  } else {
    faces_text = absl::StrCat(Header("faceList", "faces", encoding), faces.size(), "\n(\n");
    for (const Face& face : faces) {
      absl::StrAppend(&faces_text, face.size, "(",
                      absl::StrJoin(face.points.begin(), face.points.begin() + face.size, " "),
                      ")\n");
    }
    faces_text += ")\n";
  }
  std::string boundary = absl::StrCat(Header("polyBoundaryMesh", "boundary", Encoding::kAscii),
                                      extras.patches.size(), "\n(\n");
  for (const OpenFoamPatch& patch : extras.patches) {
    absl::StrAppend(&boundary, "    ", patch.name, "\n    {\n        type            ", patch.type,
                    ";\n        nFaces          ", patch.face_count, ";\n        startFace       ",
                    patch.start_face, ";\n    }\n");
  }
  boundary += ")\n";
  extras.files = {
      {"faces", std::move(faces_text)},
      {"owner", Header("labelList", "owner", encoding, note) + LabelList(owner, encoding)},
      {"neighbour",
       Header("labelList", "neighbour", encoding, note) + LabelList(neighbour, encoding)},
      {"boundary", std::move(boundary)}};
  extras.points_name = "points";
  extras.points_before = Header("vectorField", "points", encoding);
  extras.points_after = "\n";
  extras.points_binary = encoding == Encoding::kBinary;
  extras.scalar_bytes = 8;
  extras.point_count = point_count;
  extras.cell_count = cell_count;
  return extras;
}

}  // namespace getme::formats
