// The OpenFOAM writer: an unchanged polyMesh is written back with the same files (binary:
// byte for byte; ASCII: all but points byte for byte, the points to the same doubles), moved
// points are all that changes, checkMesh accepts what is written, and what cannot be written
// is refused with a message.

#include "formats/openfoam/openfoam_writer.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iterator>
#include <set>
#include <sstream>

#include "formats/openfoam/foam_file.h"
#include "formats/openfoam/openfoam_reader.h"
#include "formats/vtk_reader.h"
#include "openfoam_test_util.h"

namespace getme::formats {
namespace {

namespace fs = std::filesystem;
using testing::CasePath;
using testing::ReadText;

MeshDocument ReadWrittenCase(const std::string& name) {
  absl::StatusOr<MeshDocument> document = ReadOpenFoam(CasePath(name));
  EXPECT_TRUE(document.ok()) << document.status();
  return document.ok() ? *std::move(document) : MeshDocument{};
}

std::string Decompressed(const std::string& bytes) {
  if (bytes.size() < 2 || static_cast<unsigned char>(bytes[0]) != 0x1f) return bytes;
  return Gunzip(bytes, "test").value();
}

// A fresh directory under the test's build directory.
std::string ScratchDirectory(const std::string& name) {
  const fs::path path = fs::path(OPENFOAM_FIXTURES) / "written" / name;
  fs::remove_all(path);
  fs::create_directories(path.parent_path());
  return path.string();
}

// checkMesh's output on `case_directory` (after giving it the fixture's system dictionaries).
std::string RunCheckMesh(const std::string& case_directory) {
  fs::copy(CasePath("box_ascii") + "/system", case_directory + "/system",
           fs::copy_options::recursive | fs::copy_options::overwrite_existing);
  const std::string log = case_directory + "/log.checkMesh";
  const std::string command = "WM_PROJECT_DIR=/usr/share/openfoam checkMesh -case '" +
                              case_directory + "' > '" + log + "' 2>&1";
  EXPECT_EQ(std::system(command.c_str()), 0) << ReadText(log);
  return ReadText(log);
}

TEST(OpenFoamWriter, UnchangedMeshIsWrittenBackAsRead) {
  for (const char* name :
       {"box_ascii", "box_binary", "box_binary_gz", "mixed_ascii", "mixed_binary", "poly_ascii"}) {
    SCOPED_TRACE(name);
    const MeshDocument document = ReadWrittenCase(name);
    absl::StatusOr<std::vector<PolyMeshFile>> files = SerializeOpenFoam(document, document.as_read);
    ASSERT_TRUE(files.ok()) << files.status();
    const std::string directory = CasePath(name) + "/constant/polyMesh/";
    std::set<std::string> names;
    for (const PolyMeshFile& file : *files) {
      names.insert(file.name);
      const std::string original = ReadText(directory + file.name);
      if (file.name.rfind("points", 0) == 0 && !document.openfoam->points_binary) {
        // OpenFOAM writes 17 significant digits, getme the shortest exact decimals: compare
        // the values read back.
        absl::StatusOr<FoamFile> parsed = ParseFoamFile(file.name, file.bytes);
        ASSERT_TRUE(parsed.ok()) << parsed.status();
        FoamCursor cursor(parsed->name, parsed->text);
        cursor.set_position(parsed->data_begin);
        absl::StatusOr<std::vector<double>> values =
            ReadVectorList(cursor, parsed->header, "points");
        ASSERT_TRUE(values.ok()) << values.status();
        EXPECT_EQ(*values, document.grid.points.reals);
        continue;
      }
      EXPECT_EQ(Decompressed(file.bytes), Decompressed(original)) << file.name;
    }
    for (const char* required : {"points", "faces", "owner", "neighbour", "boundary"}) {
      EXPECT_TRUE(names.count(required) || names.count(std::string(required) + ".gz")) << required;
    }
    if (std::string(name) == "poly_ascii") {
      EXPECT_TRUE(names.count("cellZones") && names.count("faceZones") &&
                  names.count("pointZones"));
    }
  }
}

TEST(OpenFoamWriter, MovedPointsAreAllThatChangesAndCheckMeshAcceptsThem) {
  for (const char* name : {"mixed_ascii", "box_binary_gz"}) {
    SCOPED_TRACE(name);
    MeshDocument document = ReadWrittenCase(name);
    // Scale by 2 and shift by (1, 0, 0): every cell stays valid, the bounding box is known.
    std::vector<double>& xyz = document.grid.points.reals;
    for (std::size_t i = 0; i < xyz.size(); ++i) xyz[i] = 2 * xyz[i] + (i % 3 == 0 ? 1.0 : 0.0);
    const std::string out = ScratchDirectory(name);
    ASSERT_TRUE(WriteOpenFoam(out, document, document.as_read).ok());
    absl::StatusOr<MeshDocument> again = ReadOpenFoam(out);
    ASSERT_TRUE(again.ok()) << again.status();
    EXPECT_EQ(again->grid.points.reals, xyz);
    EXPECT_EQ(again->grid.cells.connectivity, document.grid.cells.connectivity);
    EXPECT_EQ(again->openfoam->files, document.openfoam->files);
    EXPECT_EQ(again->openfoam->points_gzipped, document.openfoam->points_gzipped);
    const std::string log = RunCheckMesh(out);
    EXPECT_NE(log.find("Mesh OK."), std::string::npos) << log;
    EXPECT_EQ(log.find("***"), std::string::npos) << log;
    // "Overall domain bounding box (1 0 0) (7 6 4)", the coordinates to rounding.
    const std::size_t at = log.find("Overall domain bounding box");
    ASSERT_NE(at, std::string::npos) << log;
    std::string numbers = log.substr(at + 27, log.find('\n', at) - at - 27);
    for (char& c : numbers) {
      if (c == '(' || c == ')') c = ' ';
    }
    std::istringstream values(numbers);
    std::vector<double> box((std::istream_iterator<double>(values)),
                            std::istream_iterator<double>());
    const std::vector<double> expected = std::string(name) == "mixed_ascii"
                                             ? std::vector<double>{1, 0, 0, 7, 6, 4}
                                             : std::vector<double>{1, 0, 0, 5, 3, 2};
    ASSERT_EQ(box.size(), 6u) << numbers;
    for (int k = 0; k < 6; ++k) EXPECT_NEAR(box[k], expected[k], 1e-12) << k;
  }
}

// A mesh of another format (foamToVTK's .vtk of the hybrid case): faces, owners and patches are
// built from its cells; reading the result back gives the same cells, and the same faces as
// gmshToFoam's polyMesh of that mesh, as sets.
TEST(OpenFoamWriter, BuildsThePolyMeshOfAnotherFormat) {
  absl::StatusOr<UnstructuredGrid> vtk = ParseVtk(ReadText(testing::FixturePath("mixed.vtk")));
  ASSERT_TRUE(vtk.ok()) << vtk.status();
  MeshDocument document;
  document.grid = *std::move(vtk);
  for (const Encoding encoding : {Encoding::kAscii, Encoding::kBinary}) {
    WriteOptions options;
    options.encoding = encoding;
    absl::StatusOr<std::vector<PolyMeshFile>> files = SerializeOpenFoam(document, options);
    ASSERT_TRUE(files.ok()) << files.status();
    ASSERT_EQ(files->size(), 5u);
    PolyMeshFiles polymesh{(*files)[0], (*files)[1], (*files)[2], (*files)[3], (*files)[4], {}};
    absl::StatusOr<MeshDocument> again = ParseOpenFoam(polymesh);
    ASSERT_TRUE(again.ok()) << again.status();
    EXPECT_EQ(again->as_read.encoding, encoding);
    const std::int64_t cells = document.grid.cells.size();
    ASSERT_EQ(again->openfoam->cell_count, cells);
    for (std::int64_t cell = 0; cell < cells; ++cell) {
      ASSERT_EQ(again->grid.cells.types[cell], document.grid.cells.types[cell]) << cell;
      const std::int64_t* a = again->grid.cells.nodes(cell);
      const std::int64_t* b = document.grid.cells.nodes(cell);
      const int n = static_cast<int>(document.grid.cells.node_count(cell));
      EXPECT_EQ(std::set<std::int64_t>(a, a + n), std::set<std::int64_t>(b, b + n)) << cell;
    }
    // No surface groups in a foamToVTK volume file: one patch of all boundary faces, as many
    // as gmshToFoam's six patches hold.
    ASSERT_EQ(again->openfoam->patches.size(), 1u);
    EXPECT_EQ(again->openfoam->patches[0].name, "defaultFaces");
    const MeshDocument gmsh_to_foam = ReadWrittenCase("mixed_ascii");
    std::int64_t boundary_faces = 0;
    for (const OpenFoamPatch& patch : gmsh_to_foam.openfoam->patches) {
      boundary_faces += patch.face_count;
    }
    EXPECT_EQ(again->openfoam->patches[0].face_count, boundary_faces);
  }
}

TEST(OpenFoamWriter, OutputPathNamesACaseOrAPolyMeshDirectory) {
  EXPECT_EQ(PolyMeshDirectoryFor("out"), "out/constant/polyMesh");
  EXPECT_EQ(PolyMeshDirectoryFor("out/"), "out/constant/polyMesh");
  EXPECT_EQ(PolyMeshDirectoryFor("a/constant/polyMesh"), "a/constant/polyMesh");
  EXPECT_EQ(PolyMeshDirectoryFor("a/constant/polyMesh/"), "a/constant/polyMesh");
}

TEST(OpenFoamWriter, RefusesWhatItCannotWrite) {
  MeshDocument document = ReadWrittenCase("box_ascii");
  // Cells a polyMesh built from another format cannot take as one of the four shapes.
  MeshDocument foreign;
  foreign.grid = document.grid;
  foreign.grid.cells.types[0] = 11;  // a voxel
  EXPECT_EQ(SerializeOpenFoam(foreign, foreign.as_read).status().message(),
            "cell 0 (VTK type 11 voxel) cannot be written to an OpenFOAM polyMesh: only "
            "tetrahedra, pyramids, wedges and hexahedra are");
  WriteOptions binary;
  binary.encoding = Encoding::kBinary;
  EXPECT_EQ(SerializeOpenFoam(document, binary).status().message(),
            "an OpenFOAM polyMesh is written back in the encoding it was read in (ascii): only "
            "its points change, and its other files are copied as they are");
  MeshDocument fewer = document;
  fewer.grid.points.reals.resize(fewer.grid.points.reals.size() - 3);
  EXPECT_EQ(SerializeOpenFoam(fewer, fewer.as_read).status().message(),
            "the grid has 79 points (3 components), but the polyMesh it was read from has 80");
  // A faces.gz beside the faces to be written would make the directory ambiguous.
  const std::string out = ScratchDirectory("stale");
  fs::create_directories(out + "/constant/polyMesh");
  testing::WriteText(out + "/constant/polyMesh/faces.gz", "x");
  const absl::Status stale = WriteOpenFoam(out, document, document.as_read);
  EXPECT_EQ(stale.code(), absl::StatusCode::kInvalidArgument);
  EXPECT_EQ(stale.message(), out +
                                 "/constant/polyMesh/faces.gz exists, and faces is to be "
                                 "written beside it: OpenFOAM would read either; remove it "
                                 "first");
}

}  // namespace
}  // namespace getme::formats
