// .vtu files written by other tools (meshio's VTU writer; files assembled by the fixture script
// with Python's struct / base64 / zlib) read back with the content their writers put in, as
// found independently in the fixture's sidecar files.

#include <gtest/gtest.h>

#include "absl/strings/match.h"
#include "formats/grid_mesh.h"
#include "formats/vtk_reader.h"
#include "formats/vtk_writer.h"
#include "formats/vtu/vtu_reader.h"
#include "formats/vtu/vtu_writer.h"
#include "getme/elements/element_quality.h"
#include "vtk_test_util.h"
#include "vtu_expected.h"

namespace getme::formats {
namespace {

using testing::ExpectContent;
using testing::ExpectSameContent;
using testing::FixturePath;
using testing::ReadExpected;
using testing::ReadText;

struct ExternalFile {
  const char* name;
  Encoding encoding;
  VtuLayout layout;
  bool compressed;
};

void PrintTo(const ExternalFile& file, std::ostream* out) { *out << file.name; }

class VtuExternalFileTest : public ::testing::TestWithParam<ExternalFile> {};

TEST_P(VtuExternalFileTest, ReadsWhatItsWriterWrote) {
  const std::string path = FixturePath(GetParam().name);
  const absl::StatusOr<MeshDocument> document = ParseVtu(ReadText(path));
  ASSERT_TRUE(document.ok()) << document.status();
  EXPECT_EQ(document->format, FileFormat::kVtkXml);
  EXPECT_EQ(document->as_read.encoding, GetParam().encoding);
  EXPECT_EQ(document->grid.encoding, GetParam().encoding);
  if (GetParam().encoding == Encoding::kBinary) {
    EXPECT_EQ(document->as_read.vtu_layout, GetParam().layout);
    EXPECT_EQ(document->as_read.vtu_compress, GetParam().compressed);
  }
  ExpectContent(ReadExpected(path), document->grid);

  // Written back as .vtu with the options it was read with, and as a BINARY legacy file, it
  // reads back the same. (Not as ASCII: a float written as its shortest decimal reads back as the
  // double of that decimal, by the model's convention for ASCII input, unstructured_grid.h.)
  const absl::StatusOr<std::string> vtu = SerializeVtu(*document, document->as_read);
  ASSERT_TRUE(vtu.ok()) << vtu.status();
  const absl::StatusOr<MeshDocument> vtu_again = ParseVtu(*vtu);
  ASSERT_TRUE(vtu_again.ok()) << vtu_again.status();
  ExpectSameContent(document->grid, vtu_again->grid);
  {
    const absl::StatusOr<std::string> legacy = SerializeVtk(document->grid, Encoding::kBinary);
    ASSERT_TRUE(legacy.ok()) << legacy.status();
    const absl::StatusOr<UnstructuredGrid> legacy_again = ParseVtk(*legacy);
    ASSERT_TRUE(legacy_again.ok()) << legacy_again.status();
    ExpectSameContent(document->grid, *legacy_again);
  }
}

std::string StemOf(const ::testing::TestParamInfo<ExternalFile>& info) {
  const std::string name = info.param.name;
  return name.substr(0, name.find('.'));
}

constexpr Encoding kAscii = Encoding::kAscii;
constexpr Encoding kBinary = Encoding::kBinary;
constexpr VtuLayout kInline = VtuLayout::kInline;
constexpr VtuLayout kAppended = VtuLayout::kAppended;

INSTANTIATE_TEST_SUITE_P(
    Meshio, VtuExternalFileTest,
    ::testing::Values(ExternalFile{"meshio_ascii.vtu", kAscii, kInline, false},
                      ExternalFile{"meshio_binary.vtu", kBinary, kInline, false},
                      ExternalFile{"meshio_binary_uint64.vtu", kBinary, kInline, false},
                      ExternalFile{"meshio_zlib.vtu", kBinary, kInline, true},
                      ExternalFile{"meshio_zlib_uint64.vtu", kBinary, kInline, true}),
    StemOf);

// BigEndian, UInt32 and UInt64 headers, several zlib blocks, appended raw and base64 data,
// two pieces merged into one grid, field data and attribute roles.
INSTANTIATE_TEST_SUITE_P(
    Assembled, VtuExternalFileTest,
    ::testing::Values(ExternalFile{"hand_big_endian_uint32.vtu", kBinary, kInline, false},
                      ExternalFile{"hand_big_endian_zlib_uint64.vtu", kBinary, kInline, true},
                      ExternalFile{"hand_appended_raw_two_pieces.vtu", kBinary, kAppended, false},
                      ExternalFile{"hand_appended_raw_zlib.vtu", kBinary, kAppended, true},
                      ExternalFile{"hand_appended_base64.vtu", kBinary, kAppended, false},
                      ExternalFile{"hand_appended_base64_zlib.vtu", kBinary, kAppended, true}),
    StemOf);

TEST(VtuExternalFiles, MeshioLzmaIsRefusedByName) {
  const std::string path = FixturePath("meshio_lzma.vtu");
  const absl::StatusOr<MeshDocument> document = ParseVtu(ReadText(path));
  ASSERT_FALSE(document.ok());
  EXPECT_EQ(document.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_NE(document.status().message().find("'vtkLZMADataCompressor'"), std::string::npos)
      << document.status();
  EXPECT_NE(document.status().message().find("is not supported"), std::string::npos)
      << document.status();
  // It names the first binary array and its line.
  EXPECT_TRUE(absl::StartsWith(document.status().message(), "line ")) << document.status();
  EXPECT_NE(document.status().message().find("DataArray"), std::string::npos) << document.status();
}

// One regular element per type, handed to meshio in meshio's own (Gmsh's) node order: meshio
// writes VTK's order itself, so through ParseVtu and GridToMesh each must come out valid with mean
// ratio 1. This pins the node-order mapping: none for tetra, hexahedron and pyramid, VTK's
// mirrored wedge for the prism.
class VtuRegularElementTest : public ::testing::TestWithParam<std::string> {};

TEST_P(VtuRegularElementTest, ReadsBackValidWithMeanRatioOne) {
  for (const char* encoding : {"ascii", "binary"}) {
    SCOPED_TRACE(encoding);
    const std::string path = FixturePath("regular_" + GetParam() + "_" + encoding + ".vtu");
    const absl::StatusOr<MeshDocument> document = ParseVtu(ReadText(path));
    ASSERT_TRUE(document.ok()) << document.status();
    absl::StatusOr<GridMesh> mesh = GridToMesh(document->grid);
    ASSERT_TRUE(mesh.ok()) << mesh.status();
    ASSERT_EQ(mesh->mesh.element_count(), 1);
    DispatchElementType(mesh->mesh.type(0), [&]<ElementType kType>() {
      const auto nodes = GatherNodes<kType>(mesh->mesh, mesh->mesh.element_nodes(0).data());
      EXPECT_TRUE(IsValid<kType>(nodes));
      EXPECT_NEAR(MeanRatio<kType>(nodes), 1.0, 1e-12);
    });
    if (GetParam() == "wedge") {
      // meshio permuted its (Gmsh) prism to VTK's wedge on writing.
      const GridCells& cells = document->grid.cells;
      EXPECT_EQ(std::vector<std::int64_t>(cells.nodes(0), cells.nodes(0) + 6),
                (std::vector<std::int64_t>{0, 2, 1, 3, 5, 4}));
    }
  }
}

INSTANTIATE_TEST_SUITE_P(AllTypes, VtuRegularElementTest,
                         ::testing::Values("tetra", "hexahedron", "pyramid", "wedge"));

}  // namespace
}  // namespace getme::formats
