// Malformed Exodus files (written by write_fixtures.py with netCDF directly) get InvalidArgument
// naming the block, set, entry and what is wrong; a missing file is NotFound.

#include <gtest/gtest.h>

#include <cstdint>
#include <string>

#include "exodus_test_util.h"
#include "formats/exodus/exodus_reader.h"
#include "formats/file_io.h"
#include "formats/mesh_file.h"

namespace getme::formats {
namespace {

using testing::ExodusFixture;

std::string ReadFileBytesOrEmpty(const std::string& path) {
  absl::StatusOr<std::string> bytes = ReadFileBytes(path);
  EXPECT_TRUE(bytes.ok()) << bytes.status();
  return bytes.ok() ? *bytes : std::string();
}

struct MalformedCase {
  const char* file;  // fixture name without "bad_" and ".exo"
  const char* message;
};

void PrintTo(const MalformedCase& param, std::ostream* out) { *out << param.file; }

class ExodusMalformedTest : public ::testing::TestWithParam<MalformedCase> {};

TEST_P(ExodusMalformedTest, IsRefusedWithExactMessage) {
  const std::string path = ExodusFixture(std::string("bad_") + GetParam().file + ".exo");
  const absl::StatusOr<MeshDocument> document = ReadExodus(path);
  ASSERT_FALSE(document.ok());
  EXPECT_EQ(document.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_EQ(document.status().message(), GetParam().message);
  // Through the dispatcher, the same message after the path.
  const absl::StatusOr<MeshDocument> dispatched = ReadMeshDocument(path);
  ASSERT_FALSE(dispatched.ok());
  EXPECT_EQ(dispatched.status().message(), path + ": " + GetParam().message);
}

INSTANTIATE_TEST_SUITE_P(
    WrittenWithNetcdf, ExodusMalformedTest,
    ::testing::Values(
        MalformedCase{"tet4_with_5_nodes",
                      "element block 1 ('solid'): element type 'TET4' names 4 nodes but the "
                      "block has 5 per element"},
        MalformedCase{"hex20",
                      "element block 4 ('quadratic'): element type 'HEX20' with 20 nodes per "
                      "element is not supported: getme smooths linear elements (HEX has 8 "
                      "nodes)"},
        MalformedCase{"node_out_of_range",
                      "element block 2 ('solid'): element 1: node 7 out of range 1..4"},
        MalformedCase{"no_blocks", "no element blocks: the file holds no elements"},
        MalformedCase{"duplicate_block_ids", "element block id 3 is used twice"},
        MalformedCase{"two_dimensional",
                      "num_dim = 2: getme smooths 3D volume meshes; this file is 2-dimensional"},
        MalformedCase{"side_out_of_range",
                      "side set 9 ('wall'): entry 2: side 5 out of range 1..4 of element 1"},
        MalformedCase{"side_element_out_of_range",
                      "side set 9 ('wall'): entry 1: element 2 out of range 1..1"},
        MalformedCase{"side_of_shell",
                      "side set 9 ('wall'): entry 1: element 2 (block 2) is not a volume "
                      "element; getme keeps sides of volume elements only"},
        MalformedCase{"node_set_out_of_range",
                      "node set 4 ('clamp'): entry 2: node 5 out of range 1..4"},
        MalformedCase{"connect_over_other_dimensions",
                      "variable 'connect1' has dimensions (num_el_in_blk1, len_string); Exodus "
                      "II defines it over (num_el_in_blk1, num_nod_per_el1)"},
        MalformedCase{"polyhedron",
                      "element block 1 ('poly'): element type 'NFACED' is not supported: getme "
                      "reads linear TETRA, PYRAMID, WEDGE and HEX blocks and passes SHELL/QUAD, "
                      "TRI, BAR/BEAM/TRUSS and SPHERE blocks through"}),
    [](const ::testing::TestParamInfo<MalformedCase>& info) {
      return std::string(info.param.file);
    });

TEST(ExodusMalformed, NotNetcdfCarriesTheLibrarysReason) {
  const std::string path = ExodusFixture("bad_not_netcdf.exo");
  const absl::StatusOr<MeshDocument> document = ReadExodus(path);
  ASSERT_FALSE(document.ok());
  EXPECT_EQ(document.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_EQ(document.status().message(), "not an Exodus II file: Error: failed to open " + path +
                                             " read only (NetCDF: Unknown file format)");
}

TEST(ExodusMalformed, BytesThatAreNoExodusFileNameNoTemporaryPath) {
  const absl::StatusOr<MeshDocument> document = ParseExodus("this is not an Exodus file\n");
  ASSERT_FALSE(document.ok());
  EXPECT_EQ(document.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_EQ(document.status().message(),
            "not an Exodus II file: Error: failed to open the data read only (NetCDF: Unknown "
            "file format)");
}

// netCDF would allocate what a header declares before reading it (exodus_netcdf_header.h).
TEST(ExodusMalformed, NetcdfHeaderCountsBeyondTheFileAreRefusedFirst) {
  // CDF-1, numrecs 0, a dimension list claiming 10^6 dimensions in 16 bytes.
  const std::string bytes("CDF\x01\0\0\0\0\0\0\0\x0A\0\x0F\x42\x40", 16);
  const absl::StatusOr<MeshDocument> document = ParseExodus(bytes);
  EXPECT_EQ(document.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_EQ(document.status().message(),
            "netCDF header, byte 16: dimension list does not fit the file");
  // A global attribute the Exodus library reads into one number, given as 1,000 (found by the
  // corruption test: the library overflowed its stack).
  EXPECT_EQ(ParseExodus(ReadFileBytesOrEmpty(ExodusFixture("bad_file_size_array.exo")))
                .status()
                .message(),
            "global attribute 'file_size' has 1000 values; Exodus II stores one number there");
}

// netCDF copies a header's names whole into NC_MAX_NAME + 1 bytes (exodus_netcdf_header.h); the
// exodus fuzz target's find was a global attribute name 517 bytes long.
TEST(ExodusMalformed, NetcdfNamesLongerThanNcMaxNameAreRefusedFirst) {
  // CDF-1, numrecs 0, no dimensions, one global attribute whose name is `name_length` bytes, of
  // one character; no variables.
  auto header = [](std::uint32_t name_length) {
    auto big_endian = [](std::uint32_t value) {
      return std::string{static_cast<char>(value >> 24), static_cast<char>(value >> 16),
                         static_cast<char>(value >> 8), static_cast<char>(value)};
    };
    std::string bytes("CDF\x01", 4);
    bytes += big_endian(0) + big_endian(0) + big_endian(0);  // numrecs; the dimensions ABSENT
    bytes += big_endian(0x0C) + big_endian(1) + big_endian(name_length);
    bytes += std::string((name_length + 3) / 4 * 4, 'a');
    bytes += big_endian(2) + big_endian(1) + std::string("x\0\0\0", 4);  // NC_CHAR "x"
    bytes += big_endian(0) + big_endian(0);                              // no variables
    return bytes;
  };
  const absl::StatusOr<MeshDocument> long_name = ParseExodus(header(517));
  EXPECT_EQ(long_name.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_EQ(long_name.status().message(),
            "netCDF header, byte 28: global attribute 0 name is 517 bytes long; netCDF names "
            "have at most 256 (NC_MAX_NAME)");
  // The longest name netCDF allows passes this check: the file then fails as no Exodus file.
  const absl::StatusOr<MeshDocument> longest = ParseExodus(header(256));
  EXPECT_EQ(longest.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_EQ(longest.status().message().find("netCDF header"), std::string::npos)
      << longest.status();
}

TEST(ExodusMalformed, MissingFileIsNotFound) {
  const absl::StatusOr<MeshDocument> document = ReadExodus("/nonexistent/mesh.exo");
  EXPECT_EQ(document.status().code(), absl::StatusCode::kNotFound);
  EXPECT_EQ(document.status().message(),
            "cannot open '/nonexistent/mesh.exo': No such file or directory");
  EXPECT_EQ(ReadMeshDocument("/nonexistent/mesh.exo").status(), document.status());
}

}  // namespace
}  // namespace getme::formats
