// Malformed polyMesh input gives InvalidArgument naming the file, the line (ASCII) or byte
// (binary), the list and the face or cell; a small hand-written mesh of two hexahedra is the
// valid baseline each case breaks in one place.

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_replace.h"
#include "formats/openfoam/foam_file.h"
#include "formats/openfoam/openfoam_reader.h"
#include "formats/openfoam/openfoam_writer.h"
#include "formats/vtk_cell_type.h"
#include "openfoam_test_util.h"

namespace getme::formats {
namespace {

std::string Header(const std::string& object, const std::string& class_name,
                   const std::string& format = "ascii") {
  return absl::StrCat("FoamFile\n{\n    version 2.0;\n    format ", format, ";\n    class ",
                      class_name, ";\n    object ", object, ";\n}\n");
}

// Two unit cubes side by side along x: point i + 3j + 6k at (i, j, k). Face 0 is the internal
// face x = 1 (owner 0, neighbour 1, normal +x); faces 1..10 are the boundary, each ordered so
// that its normal points out of its owner.
constexpr char kPoints[] =
    "12\n(\n(0 0 0)\n(1 0 0)\n(2 0 0)\n(0 1 0)\n(1 1 0)\n(2 1 0)\n(0 0 1)\n(1 0 1)\n(2 0 1)\n"
    "(0 1 1)\n(1 1 1)\n(2 1 1)\n)\n";
constexpr char kFaces[] =
    "11\n(\n4(1 4 10 7)\n4(0 6 9 3)\n4(2 5 11 8)\n4(0 1 7 6)\n4(1 2 8 7)\n4(3 9 10 4)\n"
    "4(4 10 11 5)\n4(0 3 4 1)\n4(1 4 5 2)\n4(6 7 10 9)\n4(7 8 11 10)\n)\n";
constexpr char kOwner[] = "11\n(\n0\n0\n1\n0\n1\n0\n1\n0\n1\n0\n1\n)\n";
constexpr char kNeighbour[] = "1\n(\n1\n)\n";
constexpr char kBoundary[] =
    "2\n(\n    walls\n    {\n        type wall;\n        inGroups 1(wall);\n        nFaces 8;\n"
    "        startFace 1;\n    }\n    top\n    {\n        type patch;\n        nFaces 2;\n"
    "        startFace 9;\n    }\n)\n";

PolyMeshFiles Valid() {
  PolyMeshFiles files;
  files.points = {"points", Header("points", "vectorField") + kPoints};
  files.faces = {"faces", Header("faces", "faceList") + kFaces};
  files.owner = {"owner", Header("owner", "labelList") + kOwner};
  files.neighbour = {"neighbour", Header("neighbour", "labelList") + kNeighbour};
  files.boundary = {"boundary", Header("boundary", "polyBoundaryMesh") + kBoundary};
  return files;
}

// Replaces the one occurrence of `from` in `text`.
std::string Replaced(const std::string& text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  EXPECT_EQ(text.find(from, at + 1), std::string::npos) << from << " is not unique";
  return text.substr(0, at) + to + text.substr(at + from.size());
}

std::string Message(const PolyMeshFiles& files) {
  const absl::StatusOr<MeshDocument> document = ParseOpenFoam(files);
  EXPECT_FALSE(document.ok());
  EXPECT_EQ(document.status().code(), absl::StatusCode::kInvalidArgument);
  return std::string(document.status().message());
}

std::string Binary(const void* data, std::size_t size) {
  return std::string(static_cast<const char*>(data), size);
}

TEST(OpenFoamMalformed, BaselineReadsAsTwoValidHexahedra) {
  absl::StatusOr<MeshDocument> document = ParseOpenFoam(Valid());
  ASSERT_TRUE(document.ok()) << document.status();
  const GridCells& cells = document->grid.cells;
  ASSERT_EQ(cells.size(), 2 + 10);
  EXPECT_EQ(cells.types[0], kVtkHexahedron);
  EXPECT_EQ(cells.types[1], kVtkHexahedron);
  // Cell 0's first face is the internal face (1 4 10 7), which it owns: reversed, it is the
  // bottom (1 7 10 4), counter-clockwise seen from the top (-x side); the top is x = 0.
  EXPECT_EQ(std::vector<std::int64_t>(cells.nodes(0), cells.nodes(0) + 8),
            (std::vector<std::int64_t>{1, 7, 10, 4, 0, 6, 9, 3}));
  EXPECT_EQ(testing::IntegerArray(document->grid.cell_data, "openfoam:patch"),
            (std::vector<std::int64_t>{0, 0, 1, 1, 1, 1, 1, 1, 1, 1, 2, 2}));
}

TEST(OpenFoamMalformed, FilesWithoutHeaderOrInCompactFormReadTheSame) {
  PolyMeshFiles bare{{"points", kPoints},       {"faces", kFaces},       {"owner", kOwner},
                     {"neighbour", kNeighbour}, {"boundary", kBoundary}, {}};
  absl::StatusOr<MeshDocument> document = ParseOpenFoam(bare);
  ASSERT_TRUE(document.ok()) << document.status();
  PolyMeshFiles compact = Valid();
  compact.faces.bytes = Header("faces", "faceCompactList") +
                        "12(0 4 8 12 16 20 24 28 32 36 40 44)\n"
                        "44(1 4 10 7 0 6 9 3 2 5 11 8 0 1 7 6 1 2 8 7 3 9 10 4 4 10 11 5 "
                        "0 3 4 1 1 4 5 2 6 7 10 9 7 8 11 10)\n";
  absl::StatusOr<MeshDocument> from_compact = ParseOpenFoam(compact);
  ASSERT_TRUE(from_compact.ok()) << from_compact.status();
  EXPECT_EQ(from_compact->grid.cells.connectivity, document->grid.cells.connectivity);
  // A uniform owner list ("N{label}") and a list without a size are ASCII forms too.
  PolyMeshFiles forms = Valid();
  forms.neighbour.bytes = Header("neighbour", "labelList") + "(1)";
  // A patch may hold a sub-dictionary (no ';' after its brace) and lists in its entries.
  forms.boundary.bytes = Replaced(forms.boundary.bytes, "type wall;",
                                  "type wall;\n        transform { type none; offset (0 0 0); }");
  absl::StatusOr<MeshDocument> from_forms = ParseOpenFoam(forms);
  ASSERT_TRUE(from_forms.ok()) << from_forms.status();
  EXPECT_EQ(from_forms->openfoam->patches[0].face_count, 8);
  EXPECT_EQ(from_forms->openfoam->patches[0].type, "wall");
}

TEST(OpenFoamMalformed, BinaryFilesReadTheSame) {
  PolyMeshFiles files = Valid();
  std::vector<double> xyz;
  for (int k = 0; k < 2; ++k) {
    for (int j = 0; j < 2; ++j) {
      for (int i = 0; i < 3; ++i) xyz.insert(xyz.end(), {double(i), double(j), double(k)});
    }
  }
  files.points.bytes = Header("points", "vectorField", "binary") + "12\n(" +
                       Binary(xyz.data(), xyz.size() * 8) + ")\n";
  const std::vector<std::int32_t> owner = {0, 0, 1, 0, 1, 0, 1, 0, 1, 0, 1};
  files.owner.bytes =
      Header("owner", "labelList", "binary") + "11\n(" + Binary(owner.data(), 44) + ")\n";
  absl::StatusOr<MeshDocument> binary = ParseOpenFoam(files);
  ASSERT_TRUE(binary.ok()) << binary.status();
  EXPECT_EQ(binary->grid.points.reals, xyz);
  EXPECT_EQ(binary->as_read.encoding, Encoding::kBinary);
  EXPECT_EQ(binary->grid.cells.connectivity, ParseOpenFoam(Valid())->grid.cells.connectivity);

  // arch "LSB;label=64;scalar=32": 64-bit labels, float coordinates; written back as floats.
  {
    PolyMeshFiles wide = Valid();
    const std::string arch = "    arch \"LSB;label=64;scalar=32\";\n}";
    const std::vector<float> narrow(xyz.begin(), xyz.end());
    wide.points.bytes = Replaced(Header("points", "vectorField", "binary"), "\n}", "\n" + arch) +
                        "12\n(" + Binary(narrow.data(), narrow.size() * 4) + ")\n";
    const std::vector<std::int64_t> owner64(owner.begin(), owner.end());
    wide.owner.bytes = Replaced(Header("owner", "labelList", "binary"), "\n}", "\n" + arch) +
                       "11\n(" + Binary(owner64.data(), 88) + ")\n";
    absl::StatusOr<MeshDocument> read = ParseOpenFoam(wide);
    ASSERT_TRUE(read.ok()) << read.status();
    EXPECT_EQ(read->grid.points.reals, xyz);  // small integers: exact as floats
    EXPECT_EQ(read->grid.cells.connectivity, ParseOpenFoam(Valid())->grid.cells.connectivity);
    absl::StatusOr<std::vector<PolyMeshFile>> written = SerializeOpenFoam(*read, read->as_read);
    ASSERT_TRUE(written.ok()) << written.status();
    EXPECT_EQ((*written)[0].bytes, wide.points.bytes);
  }

  // A binary faceList (what OpenFOAM before v1806 writes): each face "4(" raw labels ")".
  const std::vector<std::vector<std::int32_t>> face_points = {
      {1, 4, 10, 7},  {0, 6, 9, 3}, {2, 5, 11, 8}, {0, 1, 7, 6},  {1, 2, 8, 7},  {3, 9, 10, 4},
      {4, 10, 11, 5}, {0, 3, 4, 1}, {1, 4, 5, 2},  {6, 7, 10, 9}, {7, 8, 11, 10}};
  PolyMeshFiles face_list = Valid();
  face_list.faces.bytes = Header("faces", "faceList", "binary") + "11\n(\n";
  for (const std::vector<std::int32_t>& face : face_points) {
    face_list.faces.bytes += "4(" + Binary(face.data(), 16) + ")\n";
  }
  face_list.faces.bytes += ")\n";
  absl::StatusOr<MeshDocument> from_face_list = ParseOpenFoam(face_list);
  ASSERT_TRUE(from_face_list.ok()) << from_face_list.status();
  EXPECT_EQ(from_face_list->grid.cells.connectivity,
            ParseOpenFoam(Valid())->grid.cells.connectivity);

  // Truncated binary block: the byte offset of where the block begins.
  files.points.bytes =
      Header("points", "vectorField", "binary") + "12\n(" + Binary(xyz.data(), 11 * 24) + ")\n";
  EXPECT_EQ(Message(files),
            "points: byte 95: the point list: 36 values of 8 bytes need more than the 266 bytes "
            "left in the file");
  // A label outside the points, reported at its byte.
  files = Valid();
  const std::vector<std::int32_t> offsets = {0, 3, 6};
  const std::vector<std::int32_t> labels = {0, 1, 2, 3, 99, 5};
  files.faces.bytes = Header("faces", "faceCompactList", "binary") + "3\n(" +
                      Binary(offsets.data(), 12) + ")\n6\n(" + Binary(labels.data(), 24) + ")\n";
  // The bad label is the 5th (index 4) of the second list, after the header, "3\n(", the 12
  // offset bytes, ")\n6\n(".
  const std::size_t at = Header("faces", "faceCompactList", "binary").size() + 3 + 12 + 5 + 4 * 4;
  EXPECT_EQ(Message(files), absl::StrCat("faces: byte ", at,
                                         ": face 1 refers to point 99, but the points file has 12 "
                                         "points"));
}

struct MalformedCase {
  const char* name;
  int file = 0;  // 0 points, 1 faces, 2 owner, 3 neighbour, 4 boundary
  std::string from;
  std::string to;
  std::string message;
};

PolyMeshFile& FileOf(PolyMeshFiles& files, int file) {
  PolyMeshFile* all[] = {&files.points, &files.faces, &files.owner, &files.neighbour,
                         &files.boundary};
  return *all[file];
}

TEST(OpenFoamMalformed, EachBrokenPlaceIsNamed) {
  const std::vector<MalformedCase> cases = {
      {"PointCountTooLarge", 0, "12\n(", "13\n(",
       "points: line 22: the point list: ')' after 12 of 13 entries"},
      {"PointComponentNotANumber", 0, "(2 1 1)", "(2 1 x)",
       "points: line 21: expected the point list entry 11 component 2 (a number), found 'x'"},
      {"PointListUnclosed", 0, "(2 1 1)\n)", "(2 1 1)\n",
       "points: line 23: expected ')' to close the point list, found the end of the file"},
      {"FormatUnknown", 0, "format ascii", "format text",
       "points: line 7: FoamFile format 'text' is neither ascii nor binary"},
      {"BigEndian", 0, "format ascii;", "format ascii; arch \"MSB;label=32\";",
       "points: line 7: arch \"MSB\": big-endian binary files are not supported"},
      {"Label16", 0, "format ascii;", "format ascii; arch \"LSB;label=16\";",
       "points: line 7: arch \"LSB;label=16\": label=16 is not supported (32 or 64 bits)"},
      {"FaceMissingPoint", 1, "4(0 1 7 6)", "4(0 1 7 12)",
       "faces: line 13: face 3 refers to point 12, but the points file has 12 points"},
      {"FaceNegativePoint", 1, "4(0 1 7 6)", "4(0 1 7 -1)",
       "faces: line 13: face 3 refers to point -1, but the points file has 12 points"},
      {"FaceTooSmall", 1, "4(0 1 7 6)", "2(0 1)",
       "faces: line 13: face 3 has 2 points; a face has at least 3"},
      {"FaceRepeatsPoint", 1, "4(0 1 7 6)", "4(0 1 7 0)",
       "faces: line 13: face 3 lists point 0 twice"},
      {"FaceCountTooSmall", 1, "11\n(", "12\n(",
       "faces: line 21: the face list: ')' after 11 of 12 entries"},
      {"OwnerTooShort", 2, "11\n(\n0\n0\n", "10\n(\n0\n",
       "owner: line 8: the owner list has 10 entries, but the faces file has 11 faces (one "
       "owner cell per face)"},
      {"OwnerNegative", 2, "11\n(\n0\n0\n", "11\n(\n0\n-3\n",
       "owner: line 11: face 1 has the negative owner cell -3"},
      {"NeighbourIsOwner", 3, "(\n1\n)", "(\n0\n)",
       "neighbour: line 10: face 0 has cell 0 as both owner and neighbour"},
      {"NeighbourTooLong", 3, "1\n(\n1\n)", "12\n(\n5\n5\n5\n5\n5\n5\n5\n5\n5\n5\n5\n5\n)",
       "neighbour: line 8: the neighbour list has 12 entries, but the faces file has only 11 "
       "faces"},
      {"PatchGap", 4, "nFaces 8;", "nFaces 7;",
       "boundary: boundary face 8 is in no patch (the patches must cover the faces 1..10, those "
       "after the 1 internal faces)"},
      {"PatchOverlap", 4, "startFace 9;", "startFace 8;",
       "boundary: face 8 is in both patch 'walls' and 'top'"},
      {"PatchOutside", 4, "startFace 9;", "startFace 10;",
       "boundary: patch 'top' has 2 faces from face 10, not within the boundary faces 1..10"},
      {"PatchHuge", 4, "nFaces 2;", "nFaces 9223372036854775807;",
       "boundary: patch 'top' has 9223372036854775807 faces from face 9, not within the "
       "boundary faces 1..10"},
      {"UniformListTooLarge", 2, "11\n(\n0\n0\n1\n0\n1\n0\n1\n0\n1\n0\n1\n)", "2000000{0}",
       "owner: line 8: the owner list: uniform list of 2000000 entries exceeds the limit of "
       "1048576"},
      {"PatchWithoutStart", 4, "        startFace 1;\n", "",
       "boundary: line 10: patch 'walls' has no startFace entry"},
      {"PatchCount", 4, "2\n(\n    walls", "3\n(\n    walls",
       "boundary: line 23: the patch list: its size says 3 patches, but it has 2"},
      {"CellOpen", 2, "11\n(\n0\n0\n", "11\n(\n0\n1\n",
       "owner/neighbour/faces: cell 0: the cell is not closed: the edge 0->3 of face 7 is on no "
       "other face of the cell"},
      {"FaceFlipped", 1, "4(0 1 7 6)", "4(0 6 7 1)",
       "owner/neighbour/faces: cell 0: faces 1 and 3 both run along the edge 0->6 seen from the "
       "cell: one of them is oriented against the others (owner and neighbour swapped, or its "
       "points reversed)"},
      {"CellWithoutFaces", 3, "(\n1\n)", "(\n2\n)",
       "owner/neighbour: cell 2 has 1 face; a cell is bounded by at least 4"},
      {"TrailingContent", 2, "1\n)\n", "1\n)\nextra\n",
       "owner: line 22: unexpected content after the data"},
      {"CommentUnclosed", 3, "1\n)\n", "1\n)\n/* note\n",
       "neighbour: line 12: comment '/*' is never closed"},
  };
  for (const MalformedCase& c : cases) {
    SCOPED_TRACE(c.name);
    PolyMeshFiles files = Valid();
    PolyMeshFile& file = FileOf(files, c.file);
    file.bytes = Replaced(file.bytes, c.from, c.to);
    EXPECT_EQ(Message(files), c.message);
  }
}

TEST(OpenFoamMalformed, PolyhedraAreKeptFixedAndOnlyPolyhedraIsRefused) {
  // Split cell 0's top (6 7 10 9) into two triangles: it has 7 faces, a polyhedron.
  PolyMeshFiles files = Valid();
  files.faces.bytes = Replaced(files.faces.bytes, "11\n(", "12\n(");
  files.faces.bytes = Replaced(files.faces.bytes, "4(6 7 10 9)", "3(6 7 10)\n3(6 10 9)");
  files.owner.bytes = Header("owner", "labelList") + "12(0 0 1 0 1 0 1 0 1 0 0 1)";
  files.boundary.bytes = Replaced(files.boundary.bytes, "nFaces 2;", "nFaces 3;");
  absl::StatusOr<MeshDocument> document = ParseOpenFoam(files);
  ASSERT_TRUE(document.ok()) << document.status();
  EXPECT_EQ(document->openfoam->polyhedron_count, 1);
  EXPECT_EQ(document->grid.cells.types[0], kVtkHexahedron);  // cell 1
  EXPECT_EQ(testing::IntegerArray(document->grid.point_data, "fixed"),
            (std::vector<std::int64_t>{1, 1, 0, 1, 1, 0, 1, 1, 0, 1, 1, 0}));
  // The triangles of the split face are surface cells of patch 'top' (2).
  const GridCells& cells = document->grid.cells;
  EXPECT_EQ(cells.types[cells.size() - 3], kVtkTriangle);
  EXPECT_EQ(cells.types[cells.size() - 2], kVtkTriangle);

  // The same split on cell 1 leaves nothing to smooth.
  files.faces.bytes = Replaced(files.faces.bytes, "12\n(", "13\n(");
  files.faces.bytes = Replaced(files.faces.bytes, "4(7 8 11 10)", "3(7 8 11)\n3(7 11 10)");
  files.owner.bytes = Header("owner", "labelList") + "13(0 0 1 0 1 0 1 0 1 0 0 1 1)";
  files.boundary.bytes = Replaced(files.boundary.bytes, "nFaces 3;", "nFaces 4;");
  EXPECT_EQ(Message(files),
            "nothing to smooth: all 2 cells are polyhedra (not tetrahedra, pyramids, prisms or "
            "hexahedra), which getme keeps fixed");
}

TEST(OpenFoamMalformed, GzipDamageIsNamed) {
  PolyMeshFiles files = Valid();
  std::string compressed = Gzip(files.points.bytes).value();
  files.points = {"points.gz", compressed};
  ASSERT_TRUE(ParseOpenFoam(files).ok());
  files.points.bytes = compressed.substr(0, compressed.size() / 2);
  const std::string message = Message(files);
  EXPECT_EQ(message.rfind("points.gz: gzip data truncated after ", 0), 0u) << message;
}

TEST(OpenFoamMalformed, MissingFileIsNotFound) {
  namespace fs = std::filesystem;
  const fs::path directory =
      fs::path(OPENFOAM_FIXTURES) / "written" / "no_owner" / "constant" / "polyMesh";
  fs::remove_all(directory.parent_path().parent_path());
  fs::create_directories(directory);
  const PolyMeshFiles files = Valid();
  for (const PolyMeshFile* file :
       {&files.points, &files.faces, &files.neighbour, &files.boundary}) {
    testing::WriteText((directory / file->name).string(), file->bytes);
  }
  const absl::StatusOr<MeshDocument> document =
      ReadOpenFoam(directory.parent_path().parent_path().string());
  EXPECT_EQ(document.status().code(), absl::StatusCode::kNotFound);
  EXPECT_EQ(document.status().message(),
            directory.string() + ": the polyMesh has no owner file (owner or owner.gz)");
}

// Every prefix of a valid file is refused or read, never crashes.
TEST(OpenFoamMalformed, PrefixesNeverCrash) {
  for (int file = 0; file < 5; ++file) {
    const PolyMeshFiles valid = Valid();
    const std::string& bytes = FileOf(const_cast<PolyMeshFiles&>(valid), file).bytes;
    for (std::size_t size = 0; size < bytes.size(); ++size) {
      PolyMeshFiles files = Valid();
      FileOf(files, file).bytes = bytes.substr(0, size);
      (void)ParseOpenFoam(files);
    }
  }
}

}  // namespace
}  // namespace getme::formats
