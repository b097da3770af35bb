#include "formats/openfoam/openfoam_reader.h"

#include <algorithm>
#include <array>
#include <filesystem>
#include <system_error>
#include <utility>

#include "absl/strings/str_cat.h"
#include "formats/file_io.h"
#include "formats/openfoam/foam_cell_shape.h"
#include "formats/openfoam/foam_file.h"
#include "formats/vtk_cell_type.h"
#include "spdlog/spdlog.h"

namespace getme::formats {
namespace {

constexpr int kVtkPolygon = 7;
constexpr const char* kZoneFiles[] = {"cellZones", "faceZones", "pointZones"};

// A parsed file and a cursor on its data, positions reported as lines or bytes as it says.
struct OpenedFile {
  FoamFile file;
  FoamCursor cursor;
};

absl::StatusOr<std::unique_ptr<OpenedFile>> Open(const PolyMeshFile& raw) {
  absl::StatusOr<FoamFile> file = ParseFoamFile(raw.name, raw.bytes);
  if (!file.ok()) return file.status();
  auto opened = std::make_unique<OpenedFile>(OpenedFile{*std::move(file), FoamCursor("", "")});
  opened->cursor = FoamCursor(opened->file.name, opened->file.text);
  opened->cursor.set_position(opened->file.data_begin);
  opened->cursor.set_binary(opened->file.header.binary);
  return opened;
}

DataArray IntArray(std::string name, std::vector<std::int64_t> values) {
  DataArray array;
  array.name = std::move(name);
  array.type = VtkDataType::kInt;
  array.components = 1;
  array.integers = std::move(values);
  return array;
}

void AddScalars(std::vector<VtkAttribute>& attributes, DataArray array) {
  VtkAttribute attribute{VtkAttributeKind::kScalars, array.name, "default", {}};
  attribute.arrays.push_back(std::move(array));
  attributes.push_back(std::move(attribute));
}

// The polyMesh's cells from owner and neighbour: for each cell its faces in increasing face
// order (OpenFOAM's own cell-face order, primitiveMesh::cells()).
struct CellFaces {
  std::vector<std::int64_t> offsets;
  std::vector<std::int64_t> faces;
};

CellFaces BuildCellFaces(std::int64_t cell_count, const std::vector<std::int64_t>& owner,
                         const std::vector<std::int64_t>& neighbour) {
  CellFaces cells;
  cells.offsets.assign(static_cast<std::size_t>(cell_count) + 1, 0);
  for (const std::int64_t cell : owner) ++cells.offsets[cell + 1];
  for (const std::int64_t cell : neighbour) ++cells.offsets[cell + 1];
  for (std::int64_t cell = 0; cell < cell_count; ++cell) {
    cells.offsets[cell + 1] += cells.offsets[cell];
  }
  cells.faces.resize(static_cast<std::size_t>(cells.offsets.back()));
  std::vector<std::int64_t> next(cells.offsets.begin(), cells.offsets.end() - 1);
  for (std::int64_t face = 0; face < static_cast<std::int64_t>(owner.size()); ++face) {
    cells.faces[next[owner[face]]++] = face;
    if (face < static_cast<std::int64_t>(neighbour.size())) {
      cells.faces[next[neighbour[face]]++] = face;
    }
  }
  return cells;
}

// Where the points list starts and ends in the points file, for writing it back.
struct PointsLayout {
  std::size_t list_begin = 0;
  std::size_t list_end = 0;
};

}  // namespace

absl::StatusOr<MeshDocument> ParseOpenFoam(const PolyMeshFiles& files) {
  // points
  absl::StatusOr<std::unique_ptr<OpenedFile>> points_file = Open(files.points);
  if (!points_file.ok()) return points_file.status();
  FoamCursor& points_cursor = (*points_file)->cursor;
  if (absl::Status status = points_cursor.SkipSpace(); !status.ok()) return status;
  PointsLayout layout;
  layout.list_begin = points_cursor.position();
  absl::StatusOr<std::vector<double>> points =
      ReadVectorList(points_cursor, (*points_file)->file.header, "the point list");
  if (!points.ok()) return points.status();
  layout.list_end = points_cursor.position();
  if (absl::Status status = ExpectEndOfFile(points_cursor); !status.ok()) return status;
  const std::int64_t point_count = static_cast<std::int64_t>(points->size() / 3);

  // faces
  absl::StatusOr<std::unique_ptr<OpenedFile>> faces_file = Open(files.faces);
  if (!faces_file.ok()) return faces_file.status();
  absl::StatusOr<CompactFaces> faces =
      ReadFaces((*faces_file)->cursor, (*faces_file)->file.header, point_count);
  if (!faces.ok()) return faces.status();
  if (absl::Status status = ExpectEndOfFile((*faces_file)->cursor); !status.ok()) return status;
  const std::int64_t face_count = faces->size();

  // owner: one cell per face.
  absl::StatusOr<std::unique_ptr<OpenedFile>> owner_file = Open(files.owner);
  if (!owner_file.ok()) return owner_file.status();
  FoamCursor& owner_cursor = (*owner_file)->cursor;
  if (absl::Status status = owner_cursor.SkipSpace(); !status.ok()) return status;
  const std::size_t owner_at = owner_cursor.position();
  absl::StatusOr<std::vector<std::int64_t>> owner =
      ReadLabelList(owner_cursor, (*owner_file)->file.header, "the owner list",
                    [](std::int64_t face, std::int64_t cell) -> std::string {
                      if (cell < 0)
                        return absl::StrCat("face ", face, " has the negative owner cell ", cell);
                      return {};
                    });
  if (!owner.ok()) return owner.status();
  if (static_cast<std::int64_t>(owner->size()) != face_count) {
    return owner_cursor.ErrorAt(
        owner_at,
        absl::StrCat("the owner list has ", owner->size(), " entries, but the faces file has ",
                     face_count, " faces (one owner cell per face)"));
  }
  if (absl::Status status = ExpectEndOfFile(owner_cursor); !status.ok()) return status;

  // neighbour: one cell per internal face (the first faces).
  absl::StatusOr<std::unique_ptr<OpenedFile>> neighbour_file = Open(files.neighbour);
  if (!neighbour_file.ok()) return neighbour_file.status();
  FoamCursor& neighbour_cursor = (*neighbour_file)->cursor;
  if (absl::Status status = neighbour_cursor.SkipSpace(); !status.ok()) return status;
  const std::size_t neighbour_at = neighbour_cursor.position();
  absl::StatusOr<std::vector<std::int64_t>> neighbour = ReadLabelList(
      neighbour_cursor, (*neighbour_file)->file.header, "the neighbour list",
      [&](std::int64_t face, std::int64_t cell) -> std::string {
        if (cell < 0) return absl::StrCat("face ", face, " has the negative neighbour cell ", cell);
        if (face < face_count && cell == (*owner)[face]) {
          return absl::StrCat("face ", face, " has cell ", cell, " as both owner and neighbour");
        }
        return {};
      });
  if (!neighbour.ok()) return neighbour.status();
  if (static_cast<std::int64_t>(neighbour->size()) > face_count) {
    return neighbour_cursor.ErrorAt(
        neighbour_at, absl::StrCat("the neighbour list has ", neighbour->size(),
                                   " entries, but the faces file has only ", face_count, " faces"));
  }
  if (absl::Status status = ExpectEndOfFile(neighbour_cursor); !status.ok()) return status;
  const std::int64_t internal_faces = static_cast<std::int64_t>(neighbour->size());

  // boundary: patches covering the faces after the internal ones, in order.
  absl::StatusOr<std::unique_ptr<OpenedFile>> boundary_file = Open(files.boundary);
  if (!boundary_file.ok()) return boundary_file.status();
  FoamCursor& boundary_cursor = (*boundary_file)->cursor;
  boundary_cursor.set_binary(false);  // a dictionary: text even in a binary case
  absl::StatusOr<std::vector<FoamPatch>> patches = ReadBoundary(boundary_cursor);
  if (!patches.ok()) return patches.status();
  if (absl::Status status = ExpectEndOfFile(boundary_cursor); !status.ok()) return status;
  std::vector<std::int64_t> face_patch(static_cast<std::size_t>(face_count - internal_faces), 0);
  for (std::size_t patch = 0; patch < patches->size(); ++patch) {
    const FoamPatch& p = (*patches)[patch];
    if (p.face_count == 0) continue;
    // Compared without adding the two, which may be any non-negative integers.
    if (p.start_face < internal_faces || p.start_face > face_count ||
        p.face_count > face_count - p.start_face) {
      return absl::InvalidArgumentError(absl::StrCat(
          files.boundary.name, ": patch '", p.name, "' has ", p.face_count, " faces from face ",
          p.start_face, ", not within the boundary faces ", internal_faces, "..", face_count - 1));
    }
    for (std::int64_t face = p.start_face; face < p.start_face + p.face_count; ++face) {
      std::int64_t& slot = face_patch[face - internal_faces];
      if (slot != 0) {
        return absl::InvalidArgumentError(
            absl::StrCat(files.boundary.name, ": face ", face, " is in both patch '",
                         (*patches)[slot - 1].name, "' and '", p.name, "'"));
      }
      slot = static_cast<std::int64_t>(patch) + 1;
    }
  }
  for (std::int64_t i = 0; i < static_cast<std::int64_t>(face_patch.size()); ++i) {
    if (face_patch[i] == 0) {
      return absl::InvalidArgumentError(
          absl::StrCat(files.boundary.name, ": boundary face ", internal_faces + i,
                       " is in no patch (the patches must cover the faces ", internal_faces, "..",
                       face_count - 1, ", those after the ", internal_faces, " internal faces)"));
    }
  }

  // cells
  std::int64_t cell_count = 0;
  for (const std::int64_t cell : *owner) cell_count = std::max(cell_count, cell + 1);
  for (const std::int64_t cell : *neighbour) cell_count = std::max(cell_count, cell + 1);
  if (cell_count > face_count) {
    return absl::InvalidArgumentError(absl::StrCat("owner/neighbour: cell labels go up to ",
                                                   cell_count - 1, ", but there are only ",
                                                   face_count, " faces to bound the cells"));
  }
  const CellFaces cell_faces = BuildCellFaces(cell_count, *owner, *neighbour);

  MeshDocument document;
  document.format = FileFormat::kOpenFoam;
  document.as_read.encoding =
      (*points_file)->file.header.binary ? Encoding::kBinary : Encoding::kAscii;
  UnstructuredGrid& grid = document.grid;
  grid.title = "OpenFOAM polyMesh";
  grid.points.name = "points";
  grid.points.type = VtkDataType::kDouble;
  grid.points.components = 3;
  grid.points.reals = *std::move(points);

  std::vector<std::int64_t> fixed(static_cast<std::size_t>(point_count), 0);
  std::array<std::int64_t, 5> shape_counts{};  // tetra, pyramid, wedge, hexahedron, polyhedron
  std::vector<CellFace> oriented;
  CellShapeScratch scratch;
  CellShape shape;
  std::vector<std::int64_t> nodes;
  // Too few faces first: a gap in the cell labels shows as a cell with none or few.
  for (std::int64_t cell = 0; cell < cell_count; ++cell) {
    const std::int64_t faces_of_cell = cell_faces.offsets[cell + 1] - cell_faces.offsets[cell];
    if (faces_of_cell < 4) {
      return absl::InvalidArgumentError(absl::StrCat(
          "owner/neighbour: cell ", cell, " has ", faces_of_cell,
          faces_of_cell == 1 ? " face" : " faces", "; a cell is bounded by at least 4"));
    }
  }
  for (std::int64_t cell = 0; cell < cell_count; ++cell) {
    const std::int64_t begin = cell_faces.offsets[cell];
    const std::int64_t end = cell_faces.offsets[cell + 1];
    oriented.clear();
    for (std::int64_t i = begin; i < end; ++i) {
      const std::int64_t face = cell_faces.faces[i];
      oriented.push_back({faces->labels.data() + faces->offsets[face],
                          static_cast<int>(faces->offsets[face + 1] - faces->offsets[face]),
                          (*owner)[face] != cell});
    }
    if (std::string problem =
            MatchCellShape(oriented, cell_faces.faces.data() + begin, scratch, shape);
        !problem.empty()) {
      return absl::InvalidArgumentError(
          absl::StrCat("owner/neighbour/faces: cell ", cell, ": ", problem));
    }
    if (shape.vtk_type == 0) {
      ++shape_counts[4];
      for (const CellFace& face : oriented) {
        for (int k = 0; k < face.size; ++k) fixed[face.points[k]] = 1;
      }
      continue;
    }
    shape_counts[shape.vtk_type == kVtkTetra     ? 0
                 : shape.vtk_type == kVtkPyramid ? 1
                 : shape.vtk_type == kVtkWedge   ? 2
                                                 : 3]++;
    nodes.assign(shape.nodes.begin(), shape.nodes.begin() + shape.node_count);
    grid.cells.Add(shape.vtk_type, nodes);
  }
  const std::int64_t volume_cells = grid.cells.size();
  if (volume_cells == 0) {
    return absl::InvalidArgumentError(absl::StrCat(
        "nothing to smooth: all ", cell_count,
        " cells are polyhedra (not tetrahedra, pyramids, prisms or hexahedra), which getme "
        "keeps fixed"));
  }

  std::vector<std::int64_t> patch_of_cell(static_cast<std::size_t>(volume_cells), 0);
  for (std::int64_t face = internal_faces; face < face_count; ++face) {
    const std::int64_t size = faces->offsets[face + 1] - faces->offsets[face];
    nodes.assign(faces->labels.begin() + faces->offsets[face],
                 faces->labels.begin() + faces->offsets[face + 1]);
    grid.cells.Add(size == 3 ? kVtkTriangle : size == 4 ? kVtkQuad : kVtkPolygon, nodes);
    patch_of_cell.push_back(face_patch[face - internal_faces]);
  }
  AddScalars(grid.cell_data, IntArray("openfoam:patch", std::move(patch_of_cell)));
  if (shape_counts[4] > 0) AddScalars(grid.point_data, IntArray("fixed", std::move(fixed)));

  OpenFoamExtras extras;
  for (const FoamPatch& patch : *patches) {
    extras.patches.push_back({patch.name, patch.type, patch.start_face, patch.face_count});
  }
  extras.files = {files.faces, files.owner, files.neighbour, files.boundary};
  extras.files.insert(extras.files.end(), files.zones.begin(), files.zones.end());
  const FoamFile& points_text = (*points_file)->file;
  extras.points_name = files.points.name;
  extras.points_gzipped = points_text.gzipped;
  extras.points_before = points_text.text.substr(0, layout.list_begin);
  extras.points_after = points_text.text.substr(layout.list_end);
  extras.points_binary = points_text.header.binary;
  extras.scalar_bytes = points_text.header.scalar_bytes;
  extras.point_count = point_count;
  extras.cell_count = cell_count;
  extras.polyhedron_count = shape_counts[4];
  document.openfoam = std::move(extras);

  spdlog::info(
      "OpenFOAM polyMesh: {} points, {} cells ({} tetrahedra, {} pyramids, {} prisms, {} "
      "hexahedra, {} polyhedra kept fixed with their points), {} boundary faces in {} patches",
      point_count, cell_count, shape_counts[0], shape_counts[1], shape_counts[2], shape_counts[3],
      shape_counts[4], face_count - internal_faces, patches->size());
  return document;
}

absl::StatusOr<std::string> FindPolyMeshDirectory(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code error;
  const fs::path case_mesh = fs::path(path) / "constant" / "polyMesh";
  if (fs::is_directory(case_mesh, error)) return case_mesh.string();
  const fs::path constant_mesh = fs::path(path) / "polyMesh";  // path is CASE/constant
  if (fs::is_directory(constant_mesh, error)) return constant_mesh.string();
  const fs::path own = fs::path(path);
  if (fs::exists(own / "faces", error) || fs::exists(own / "faces.gz", error)) return path;
  return absl::NotFoundError(
      absl::StrCat(path,
                   ": not an OpenFOAM case or polyMesh directory: it has no constant/polyMesh, no "
                   "polyMesh and no faces file"));
}

absl::StatusOr<MeshDocument> ReadOpenFoam(const std::string& path) {
  namespace fs = std::filesystem;
  absl::StatusOr<std::string> directory = FindPolyMeshDirectory(path);
  if (!directory.ok()) return directory.status();
  const auto read = [&](const char* name, bool required) -> absl::StatusOr<PolyMeshFile> {
    std::error_code error;
    for (const std::string& candidate : {std::string(name), absl::StrCat(name, ".gz")}) {
      const fs::path file = fs::path(*directory) / candidate;
      if (!fs::exists(file, error)) continue;
      absl::StatusOr<std::string> bytes = ReadFileBytes(file.string());
      if (!bytes.ok()) return bytes.status();
      return PolyMeshFile{candidate, *std::move(bytes)};
    }
    if (!required) return PolyMeshFile{};
    return absl::NotFoundError(absl::StrCat(*directory, ": the polyMesh has no ", name, " file (",
                                            name, " or ", name, ".gz)"));
  };
  PolyMeshFiles files;
  std::array<std::pair<const char*, PolyMeshFile*>, 5> required = {{{"points", &files.points},
                                                                    {"faces", &files.faces},
                                                                    {"owner", &files.owner},
                                                                    {"neighbour", &files.neighbour},
                                                                    {"boundary", &files.boundary}}};
  for (auto& [name, file] : required) {
    absl::StatusOr<PolyMeshFile> found = read(name, true);
    if (!found.ok()) return found.status();
    *file = *std::move(found);
  }
  for (const char* name : kZoneFiles) {
    absl::StatusOr<PolyMeshFile> found = read(name, false);
    if (!found.ok()) return found.status();
    if (!found->name.empty()) files.zones.push_back(*std::move(found));
  }
  absl::StatusOr<MeshDocument> document = ParseOpenFoam(files);
  if (!document.ok()) {
    return absl::Status(document.status().code(),
                        absl::StrCat(*directory, ": ", document.status().message()));
  }
  return document;
}

}  // namespace getme::formats
