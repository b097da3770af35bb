// Files the CGNS reader refuses, each with its exact message: not CGNS at all (meshio's h5py
// file, random bytes), no 3D base, structured and multiple zones, unsupported element types, a
// boundary condition naming no element.

#include <cgnslib.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "absl/status/status.h"
#include "absl/strings/match.h"
#include "absl/strings/str_cat.h"
#include "cgns_test_files.h"
#include "formats/cgns/cgns_reader.h"
#include "formats/mesh_file.h"

namespace getme::formats {
namespace {

using testing::FixturePath;
using testing::LibraryFileOptions;
using testing::WriteLibraryFile;

absl::Status ReadStatus(const LibraryFileOptions& options) {
  return ReadCgnsFile(WriteLibraryFile(options)).status();
}

std::string ReadFileOrEmpty(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

LibraryFileOptions Options(const std::string& name) {
  LibraryFileOptions options;
  options.path = ::testing::TempDir() + "/" + name + ".cgns";
  return options;
}

TEST(CgnsMalformed, MeshioH5pyFileIsNotCgnsForTheLibrary) {
  EXPECT_EQ(ReadCgnsFile(FixturePath("meshio_written.cgns")).status(),
            absl::InvalidArgumentError("not a file the CGNS library opens (cg_open): "
                                       "cgio_get_label:Node attribute doesn't exist"));
}

TEST(CgnsMalformed, BytesThatAreNoCgnsFile) {
  // Checked before the library sees them: its ADF core aborts on some headers (below).
  EXPECT_EQ(
      ParseCgns("not a CGNS file at all").status(),
      absl::InvalidArgumentError(
          "not a CGNS file: it opens with neither the HDF5 signature nor an ADF file header"));
  // The 23 bytes with which fuzz/cgns_fuzzer.cc made the CGNS library's ADF core abort
  // (ADFI_read_file_header: assertion `ADF_file[file_index].format != UNDEFINED_FORMAT').
  const std::string adf_abort("\x89H\0\0\0\0\0\0\0$\0\xff\0\0\0a\xf9\0&\0\0\0\0", 23);
  EXPECT_EQ(
      ParseCgns(adf_abort).status(),
      absl::InvalidArgumentError(
          "not a CGNS file: it opens with neither the HDF5 signature nor an ADF file header"));
  // An ADF file cut inside its header.
  LibraryFileOptions options = Options("adf_for_truncation");
  options.file_type = CG_FILE_ADF;
  const std::string adf = ReadFileOrEmpty(WriteLibraryFile(options));
  ASSERT_GT(adf.size(), 186u);
  EXPECT_EQ(ParseCgns(adf.substr(0, 120)).status(),
            absl::InvalidArgumentError("not a CGNS file: its ADF file header is truncated or "
                                       "damaged (a tag AdF0..AdF5, the numeric format or the OS "
                                       "size is missing)"));
  // A truncated HDF5 file: HDF5 refuses it, through the library.
  const absl::Status truncated = ParseCgns(std::string("\x89HDF\r\n\x1a\n", 8)).status();
  EXPECT_EQ(truncated.code(), absl::StatusCode::kInvalidArgument);
  EXPECT_TRUE(
      absl::StartsWith(truncated.message(), "not a file the CGNS library opens (cg_open): "))
      << truncated;
}

TEST(CgnsMalformed, MissingFileIsNotFound) {
  const absl::Status status = ReadCgnsFile("/nonexistent/mesh.cgns").status();
  EXPECT_EQ(status,
            absl::NotFoundError("cannot open '/nonexistent/mesh.cgns': No such file or directory"));
  EXPECT_EQ(ReadMeshDocument("/nonexistent/mesh.cgns").status(), status);
}

TEST(CgnsMalformed, NoVolumeBase) {
  LibraryFileOptions options = Options("surface_base");
  options.cell_dimension = 2;
  options.element_type = TRI_3;
  options.with_family_and_vertex_bc = false;
  EXPECT_EQ(ReadStatus(options),
            absl::InvalidArgumentError("no base of cell and physical dimension 3 (bases: 'Base' "
                                       "(cell dimension 2)); getme smooths volume meshes"));
}

TEST(CgnsMalformed, StructuredZone) {
  LibraryFileOptions options = Options("structured");
  options.structured = true;
  EXPECT_EQ(ReadStatus(options),
            absl::InvalidArgumentError(
                "zone 'Zone1' is Structured; getme reads unstructured zones only"));
}

TEST(CgnsMalformed, SeveralZonesAreNotMerged) {
  LibraryFileOptions options = Options("two_zones");
  options.zones = 2;
  EXPECT_EQ(ReadStatus(options),
            absl::InvalidArgumentError(
                "base 'Base' has 2 zones ('Zone1', 'Zone2'); getme reads a single unstructured "
                "zone and does not merge zones (their shared nodes would need the zone "
                "connectivity); merge them first"));
}

TEST(CgnsMalformed, QuadraticAndPolyhedralSectionsAreRefused) {
  for (const auto& [type, name] : {std::pair{TETRA_10, "TETRA_10"}, std::pair{HEXA_20, "HEXA_20"},
                                   std::pair{PENTA_15, "PENTA_15"}}) {
    LibraryFileOptions options = Options(name);
    options.element_type = type;
    EXPECT_EQ(ReadStatus(options),
              absl::InvalidArgumentError(absl::StrCat(
                  "zone 'Zone1' section 'Cells': ", name,
                  " elements are not supported; getme reads TETRA_4, PYRA_5, PENTA_6, HEXA_8, "
                  "TRI_3, QUAD_4, BAR_2, NODE and MIXED sections of these")));
  }
}

TEST(CgnsMalformed, ZoneWithoutVolumeElements) {
  LibraryFileOptions options = Options("surface_zone");
  options.element_type = TRI_3;
  EXPECT_EQ(ReadStatus(options),
            absl::InvalidArgumentError(
                "zone 'Zone1': no volume elements (TETRA_4, PYRA_5, PENTA_6, HEXA_8); getme "
                "smooths volume meshes"));
}

TEST(CgnsMalformed, BoundaryConditionOnAMissingElement) {
  LibraryFileOptions options = Options("bc_missing_element");
  options.bc_element = 7;
  EXPECT_EQ(ReadStatus(options),
            absl::InvalidArgumentError(
                "zone 'Zone1' boundary condition 'inlet': element 7 is in no section"));
}

TEST(CgnsMalformed, CountsBeyondWhatTheFileHoldsAreRefusedBeforeAllocating) {
  // write_fixtures.py: a section declaring 10^8 tetrahedra whose connectivity dataset is all
  // unwritten chunks, in a file of some kilobytes.
  const std::string path = FixturePath("oversized_section.cgns");
  const auto bytes = std::filesystem::file_size(path);
  ASSERT_LT(bytes, 100000u);
  EXPECT_EQ(ReadCgnsFile(path).status(),
            absl::InvalidArgumentError(absl::StrCat(
                "zone 'Zone' section 'TetElements': 500000000 connectivity entries are more than "
                "a file of ",
                bytes, " bytes can hold")));
}

TEST(CgnsMalformed, ErrorsThroughReadMeshDocumentNameThePath) {
  const std::string path = FixturePath("meshio_written.cgns");
  EXPECT_EQ(ReadMeshDocument(path).status(),
            absl::InvalidArgumentError(
                absl::StrCat(path,
                             ": not a file the CGNS library opens (cg_open): cgio_get_label:Node "
                             "attribute doesn't exist")));
}

}  // namespace
}  // namespace getme::formats
