// Round trips: VTK meshes through every MSH variant keep their points bit for bit, their cells
// and arrays; Gmsh-written files parsed and written in their own variant give the same content
// (4.1 binary: the same bytes); conversions between variants keep the grid and the physical groups;
// grids without Gmsh extras get entities from their cell data. GmshOutputs writes the files
// that check_gmsh_reads_outputs.py has Gmsh itself read.

#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <memory>

#include "formats/gmsh/gmsh_element_type.h"
#include "formats/gmsh/gmsh_groups.h"
#include "formats/gmsh/gmsh_reader.h"
#include "formats/gmsh/gmsh_writer.h"
#include "formats/vtk_reader.h"
#include "gmsh_test_util.h"
#include "spdlog/sinks/ringbuffer_sink.h"
#include "spdlog/spdlog.h"
#include "vtk_test_util.h"

namespace getme::formats {
namespace {

using testing::AllGmshVariants;
using testing::ExpectSameDocument;
using testing::GmshInput;
using testing::GmshOutput;
using testing::GmshVariant;
using testing::ParseGmshFile;
using testing::ReadBytes;
using testing::SameBits;

MeshDocument FromVtk(const UnstructuredGrid& file) {
  MeshDocument document;
  document.grid = file;
  return document;
}

absl::StatusOr<MeshDocument> WriteAndParse(const MeshDocument& document,
                                           const WriteOptions& options) {
  absl::StatusOr<std::string> bytes = SerializeGmsh(document, options);
  if (!bytes.ok()) return bytes.status();
  return ParseGmsh(*bytes);
}

// Every array of `expected` is in `actual` under its name, with the same values as doubles.
void ExpectSameArraysByName(const std::vector<VtkAttribute>& expected,
                            const std::vector<VtkAttribute>& actual) {
  for (const VtkAttribute& attribute : expected) {
    for (const DataArray& array : attribute.arrays) {
      const DataArray* read = FindArray(actual, array.name);
      ASSERT_NE(read, nullptr) << array.name;
      ASSERT_EQ(read->components, array.components) << array.name;
      ASSERT_EQ(read->value_count(), array.value_count()) << array.name;
      for (std::int64_t k = 0; k < array.value_count(); ++k) {
        ASSERT_TRUE(SameBits(read->AsDouble(k), array.AsDouble(k))) << array.name << " " << k;
      }
    }
  }
}

// ---- VTK meshes through every variant ----

std::vector<std::string> VtkSources() {
  std::vector<std::string> paths;
  for (const std::string& name : testing::AllSharedMeshNames()) {
    paths.push_back(testing::SharedMesh(name));
  }
  paths.push_back(std::string(GETME_TEST_DATA) + "/hybrid-example.vtk");
  return paths;
}

TEST(GmshRoundTrip, VtkMeshesKeepPointsCellsAndArraysInEveryVariant) {
  const std::vector<std::string> sources = VtkSources();
  ASSERT_GE(sources.size(), 18u);
  for (const std::string& path : sources) {
    const absl::StatusOr<UnstructuredGrid> file = ReadVtkFile(path);
    ASSERT_TRUE(file.ok()) << file.status();
    const MeshDocument document = FromVtk(*file);
    for (const GmshVariant& variant : AllGmshVariants()) {
      SCOPED_TRACE(path + " as " + variant.suffix);
      const absl::StatusOr<std::string> bytes = SerializeGmsh(document, variant.options);
      ASSERT_TRUE(bytes.ok()) << bytes.status();
      const absl::StatusOr<MeshDocument> read = ParseGmsh(*bytes);
      ASSERT_TRUE(read.ok()) << read.status();
      ASSERT_EQ(read->grid.point_count(), file->point_count());
      for (std::int64_t k = 0; k < 3 * file->point_count(); ++k) {
        ASSERT_TRUE(SameBits(read->grid.points.AsDouble(k), file->points.AsDouble(k))) << k;
      }
      EXPECT_EQ(read->grid.cells.types, file->cells.types);
      EXPECT_EQ(read->grid.cells.offsets, file->cells.offsets);
      EXPECT_EQ(read->grid.cells.connectivity, file->cells.connectivity);
      ExpectSameArraysByName(file->point_data, read->grid.point_data);
      ExpectSameArraysByName(file->cell_data, read->grid.cell_data);
      // Written again in the same variant: the same bytes.
      const absl::StatusOr<std::string> again = SerializeGmsh(*read, variant.options);
      ASSERT_TRUE(again.ok()) << again.status();
      EXPECT_TRUE(*again == *bytes);
    }
  }
}

// ---- Gmsh- and meshio-written files in their own variant ----

class GmshFileRoundTrip : public ::testing::TestWithParam<std::string> {};

TEST_P(GmshFileRoundTrip, SameVariantKeepsTheContent) {
  const std::string path = GmshInput(GetParam() + ".msh");
  const std::string original = ReadBytes(path);
  const absl::StatusOr<MeshDocument> document = ParseGmsh(original);
  ASSERT_TRUE(document.ok()) << document.status();
  const absl::StatusOr<std::string> bytes = SerializeGmsh(*document, document->as_read);
  ASSERT_TRUE(bytes.ok()) << bytes.status();
  const absl::StatusOr<MeshDocument> read = ParseGmsh(*bytes);
  ASSERT_TRUE(read.ok()) << read.status();
  ExpectSameDocument(*document, *read, /*with_extras=*/true);
  // Gmsh's 4.1 binary layout leaves no choice, so its files come back byte for byte. (Its 2.2
  // binary writer gives every element its own block header, where ours heads runs of one type.)
  if (!GetParam().starts_with("meshio") && GetParam().ends_with("41_binary")) {
    EXPECT_TRUE(*bytes == original)
        << "written " << bytes->size() << " bytes, read " << original.size();
  }
}

std::vector<std::string> GmshFileStems() {
  std::vector<std::string> stems;
  for (const std::string stem : {"hybrid", "views", "regular", "meshio"}) {
    for (const GmshVariant& variant : AllGmshVariants())
      stems.push_back(stem + "_" + variant.suffix);
  }
  stems.push_back("multi_41_ascii");
  stems.push_back("multi_41_binary");
  return stems;
}

INSTANTIATE_TEST_SUITE_P(WrittenByGmshAndMeshio, GmshFileRoundTrip,
                         ::testing::ValuesIn(GmshFileStems()),
                         [](const auto& info) { return info.param; });

// ---- Between variants ----

class GmshConversion : public ::testing::TestWithParam<std::string> {};

TEST_P(GmshConversion, EveryVariantKeepsGridTagsAndGroups) {
  const absl::StatusOr<MeshDocument> document = ParseGmshFile(GmshInput(GetParam() + ".msh"));
  ASSERT_TRUE(document.ok()) << document.status();
  for (const GmshVariant& variant : AllGmshVariants()) {
    SCOPED_TRACE(variant.suffix);
    const absl::StatusOr<MeshDocument> read = WriteAndParse(*document, variant.options);
    ASSERT_TRUE(read.ok()) << read.status();
    ExpectSameDocument(*document, *read, /*with_extras=*/false);
    EXPECT_EQ(read->gmsh->node_tags, document->gmsh->node_tags);
    EXPECT_EQ(read->gmsh->element_tags, document->gmsh->element_tags);
    for (const GmshPhysicalName& group : document->gmsh->physical_names) {
      const auto before = GmshGroupCells(*document, group.name);
      const auto after = GmshGroupCells(*read, group.name);
      ASSERT_TRUE(before.ok() && after.ok()) << group.name;
      EXPECT_EQ(*before, *after) << group.name;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(GmshWritten, GmshConversion,
                         ::testing::Values("hybrid_41_binary", "hybrid_22_ascii", "views_41_ascii",
                                           "views_22_binary"));

// ---- Grids without Gmsh extras ----

UnstructuredGrid TwoTetsAndATriangle() {
  UnstructuredGrid file;
  file.points.type = VtkDataType::kDouble;
  file.points.components = 3;
  file.points.reals = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1};
  file.cells.Add(10, {0, 1, 2, 3});
  file.cells.Add(10, {1, 2, 3, 4});
  file.cells.Add(5, {0, 1, 2});
  return file;
}

VtkAttribute IntScalars(const std::string& name, std::vector<std::int64_t> values) {
  DataArray array{name, VtkDataType::kInt32, 1, {}, std::move(values)};
  return VtkAttribute{VtkAttributeKind::kScalars, name, "default", {std::move(array)}};
}

TEST(GmshWithoutExtras, PhysicalCellDataBecomesEntitiesAndGroups) {
  MeshDocument document = FromVtk(TwoTetsAndATriangle());
  document.grid.cell_data.push_back(IntScalars("gmsh:physical", {5, 5, 7}));
  for (const GmshVariant& variant : AllGmshVariants()) {
    SCOPED_TRACE(variant.suffix);
    const absl::StatusOr<MeshDocument> read = WriteAndParse(document, variant.options);
    ASSERT_TRUE(read.ok()) << read.status();
    EXPECT_EQ(read->gmsh->node_tags, (std::vector<std::int64_t>{1, 2, 3, 4, 5}));
    EXPECT_EQ(read->gmsh->element_tags, (std::vector<std::int64_t>{1, 2, 3}));
    EXPECT_EQ(*GmshGroupCells(*read, "5"), (std::vector<std::int64_t>{0, 1}));
    EXPECT_EQ(*GmshGroupCells(*read, "2:7"), (std::vector<std::int64_t>{2}));
    EXPECT_EQ(GmshGroupCells(*read, "3:7").status().code(), absl::StatusCode::kNotFound);
    EXPECT_EQ(FindArray(read->grid.cell_data, "gmsh:physical")->integers,
              (std::vector<std::int64_t>{5, 5, 7}));
    if (variant.options.gmsh_version == GmshVersion::k41) {
      // One volume and one surface entity, boxes around their nodes.
      ASSERT_EQ(read->gmsh->entities.size(), 2u);
      const GmshEntity& volume = read->gmsh->entities[1];
      EXPECT_EQ(volume.dim, 3);
      EXPECT_EQ(volume.physical_tags, (std::vector<int>{5}));
      EXPECT_EQ(volume.min, (std::array<double, 3>{0, 0, 0}));
      EXPECT_EQ(volume.max, (std::array<double, 3>{1, 1, 1}));
      const GmshEntity& surface = read->gmsh->entities[0];
      EXPECT_EQ(surface.dim, 2);
      EXPECT_EQ(surface.max, (std::array<double, 3>{1, 1, 0}));
    }
  }
}

TEST(GmshWithoutExtras, MeditRefsBecomeEntitiesAndGroups) {
  MeshDocument document = FromVtk(TwoTetsAndATriangle());
  document.grid.cell_data.push_back(IntScalars("medit:ref", {3, 4, 3}));
  const absl::StatusOr<MeshDocument> read = WriteAndParse(document, WriteOptions{});
  ASSERT_TRUE(read.ok()) << read.status();
  EXPECT_EQ(FindArray(read->grid.cell_data, "gmsh:geometrical")->integers,
            (std::vector<std::int64_t>{3, 4, 3}));
  EXPECT_EQ(*GmshGroupCells(*read, "3:4"), (std::vector<std::int64_t>{1}));
  EXPECT_EQ(*GmshGroupCells(*read, "3"), (std::vector<std::int64_t>{0, 2}));
  // medit:ref is carried by the entities, not written as a view.
  EXPECT_EQ(FindArray(read->grid.cell_data, "medit:ref"), nullptr);
}

TEST(GmshWithoutExtras, NoTagsGiveOneEntityPerDimension) {
  const MeshDocument document = FromVtk(TwoTetsAndATriangle());
  const absl::StatusOr<MeshDocument> read = WriteAndParse(document, WriteOptions{});
  ASSERT_TRUE(read.ok()) << read.status();
  ASSERT_EQ(read->gmsh->entities.size(), 2u);
  EXPECT_EQ(read->gmsh->element_entities, (std::vector<GmshDimTag>{{3, 1}, {3, 1}, {2, 1}}));
  EXPECT_EQ(GmshGroupCells(*read, "1").status().code(), absl::StatusCode::kNotFound);
}

TEST(GmshWithoutExtras, ArraysOfOtherComponentCountsAreSplit) {
  MeshDocument document = FromVtk(TwoTetsAndATriangle());
  DataArray pair{"pair", VtkDataType::kDouble, 2, {1, 2, 3, 4, 5, 6}, {}};
  document.grid.cell_data.push_back(
      VtkAttribute{VtkAttributeKind::kField, "f", "", {std::move(pair)}});
  const absl::StatusOr<MeshDocument> read = WriteAndParse(document, WriteOptions{});
  ASSERT_TRUE(read.ok()) << read.status();
  EXPECT_EQ(FindArray(read->grid.cell_data, "pair[0]")->reals, (std::vector<double>{1, 3, 5}));
  EXPECT_EQ(FindArray(read->grid.cell_data, "pair[1]")->reals, (std::vector<double>{2, 4, 6}));
}

TEST(GmshWithoutExtras, CellsMshCannotHoldAreRefused) {
  MeshDocument document = FromVtk(TwoTetsAndATriangle());
  document.grid.cells.Add(24, {0, 1, 2, 3, 4, 0, 1, 2, 3, 4});
  const absl::StatusOr<std::string> bytes = SerializeGmsh(document, WriteOptions{});
  ASSERT_FALSE(bytes.ok());
  EXPECT_EQ(bytes.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_EQ(bytes.status().message(),
            "cell 3 has VTK type 24 (quadratic_tetra), which the Gmsh writer cannot store; it "
            "writes vertex, line, triangle, quad, tetra, hexahedron, wedge and pyramid cells");
}

TEST(GmshWithoutExtras, AsciiNumbersAreShortestRoundTripDecimals) {
  MeshDocument document = FromVtk(TwoTetsAndATriangle());
  document.grid.points.reals[0] = 0.1 + 0.2;
  document.grid.points.reals[1] = 1.0 / 3.0;
  document.grid.points.reals[2] = 0.1;
  WriteOptions options;
  options.gmsh_version = GmshVersion::k22;
  const absl::StatusOr<std::string> text = SerializeGmsh(document, options);
  ASSERT_TRUE(text.ok()) << text.status();
  EXPECT_NE(text->find("\n1 0.30000000000000004 0.3333333333333333 0.1\n2 1 0 0\n"),
            std::string::npos)
      << *text;
  EXPECT_NE(text->find("\n1 4 2 0 1 1 2 3 4\n"), std::string::npos) << *text;
}

TEST(GmshWithoutExtras, InconsistentModelsAreRefused) {
  MeshDocument document = FromVtk(TwoTetsAndATriangle());
  document.grid.cells.connectivity[4] = 9;
  EXPECT_EQ(SerializeGmsh(document, WriteOptions{}).status().message(),
            "a cell refers to point 9, but there are 5 points");
  document = FromVtk(TwoTetsAndATriangle());
  document.grid.cell_data.push_back(IntScalars("short", {1, 2}));
  EXPECT_EQ(SerializeGmsh(document, WriteOptions{}).status().message(),
            "cell data array 'short' holds 2 values, expected 3 × 1");
  // Extras made by hand are checked before use.
  absl::StatusOr<MeshDocument> read = WriteAndParse(FromVtk(TwoTetsAndATriangle()), WriteOptions{});
  ASSERT_TRUE(read.ok()) << read.status();
  read->gmsh->physical_names.push_back({3, 1, "a \"quoted\" name"});
  EXPECT_EQ(SerializeGmsh(*read, WriteOptions{}).status().message(),
            "inconsistent Gmsh extras: physical name 'a \"quoted\" name'");
  read->gmsh->physical_names.clear();
  read->gmsh->node_blocks[0].parametric = true;
  EXPECT_EQ(SerializeGmsh(*read, WriteOptions{}).status().message(),
            "inconsistent Gmsh extras: node block (3, 1)");
}

// ---- What cannot be carried over is named ----

class WarningCapture {
 public:
  WarningCapture() : sink_(std::make_shared<spdlog::sinks::ringbuffer_sink_mt>(64)) {
    spdlog::default_logger()->sinks().push_back(sink_);
  }
  ~WarningCapture() { spdlog::default_logger()->sinks().pop_back(); }
  std::string Text() const {
    std::string text;
    for (const std::string& line : sink_->last_formatted()) text += line;
    return text;
  }

 private:
  std::shared_ptr<spdlog::sinks::ringbuffer_sink_mt> sink_;
};

TEST(GmshWarnings, RawSectionsOfAnotherVariantAreNamed) {
  // A $Periodic section (4.1: one link, surface 4 to 3, no affine transform, one node pair).
  constexpr char kPeriodic[] = "$Periodic\n1\n2 4 3\n0\n1\n1000 1007\n$EndPeriodic\n";
  const absl::StatusOr<MeshDocument> document =
      ParseGmsh(ReadBytes(GmshInput("hybrid_41_ascii.msh")) + kPeriodic);
  ASSERT_TRUE(document.ok()) << document.status();
  ASSERT_EQ(document->gmsh->raw_sections.size(), 1u);
  EXPECT_EQ(document->gmsh->raw_sections[0].name, "Periodic");
  EXPECT_EQ(document->gmsh->raw_sections[0].body, "1\n2 4 3\n0\n1\n1000 1007\n");
  {
    WarningCapture capture;
    const absl::StatusOr<std::string> bytes = SerializeGmsh(*document, document->as_read);
    ASSERT_TRUE(bytes.ok());
    EXPECT_EQ(capture.Text(), "");
    EXPECT_TRUE(bytes->ends_with(kPeriodic));
  }
  WarningCapture capture;
  WriteOptions options = document->as_read;
  options.encoding = Encoding::kBinary;
  const absl::StatusOr<std::string> bytes = SerializeGmsh(*document, options);
  ASSERT_TRUE(bytes.ok());
  EXPECT_NE(capture.Text().find("section $Periodic of the input (MSH 4.1 ASCII) cannot be "
                                "carried over to MSH 4.1 binary; it is left out"),
            std::string::npos)
      << capture.Text();
  EXPECT_EQ(bytes->find("$Periodic"), std::string::npos);
}

TEST(GmshWarnings, InterpolationSchemesGoWithTheirViews) {
  // $ElementData names its scheme; the scheme section is text, so it is kept in any variant.
  const absl::StatusOr<MeshDocument> document = ParseGmshFile(GmshInput("views_41_ascii.msh"));
  ASSERT_TRUE(document.ok()) << document.status();
  // One per view Gmsh appended.
  const std::vector<GmshRawSection>& raw = document->gmsh->raw_sections;
  ASSERT_EQ(raw.size(), 2u);
  EXPECT_EQ(raw[0].name, "InterpolationScheme");
  WarningCapture capture;
  for (const GmshVariant& variant : AllGmshVariants()) {
    const absl::StatusOr<MeshDocument> read = WriteAndParse(*document, variant.options);
    ASSERT_TRUE(read.ok()) << read.status();
    ASSERT_EQ(read->gmsh->raw_sections.size(), raw.size());
    for (std::size_t i = 0; i < raw.size(); ++i) {
      EXPECT_EQ(read->gmsh->raw_sections[i].name, raw[i].name);
      EXPECT_EQ(read->gmsh->raw_sections[i].body, raw[i].body);
    }
  }
  EXPECT_EQ(capture.Text(), "");
}

TEST(GmshWarnings, SeveralGroupsOfAnEntityIn22AreNamed) {
  const absl::StatusOr<MeshDocument> document = ParseGmshFile(GmshInput("multi_41_ascii.msh"));
  ASSERT_TRUE(document.ok()) << document.status();
  WarningCapture capture;
  WriteOptions options;
  options.gmsh_version = GmshVersion::k22;
  ASSERT_TRUE(SerializeGmsh(*document, options).ok());
  EXPECT_NE(capture.Text().find("entities (2, 4) in groups 21, 22 keep only their first group"),
            std::string::npos)
      << capture.Text();
}

// ---- Files for check_gmsh_reads_outputs.py ----

// What Gmsh must find in a file we wrote (`document`: as we read it back): node count,
// elements by Gmsh type, physical groups with their element counts, views with their time step
// and entry count.
// MSH 2.2 cell arrays of a mesh with several runs of element types go to $ElementNodeData, which
// meshio skips (its 2.2 $ElementData split is wrong, gmsh_writer.h), and read back as the same
// cell arrays; single-run 2.2 and 4.1 keep $ElementData.
TEST(GmshCellArrays, MultiRunMsh22WritesElementNodeDataAndReadsItBack) {
  MeshDocument document;
  UnstructuredGrid& grid = document.grid;
  grid.points.components = 3;
  grid.points.reals = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1};
  grid.cells.Add(10, {0, 1, 2, 3});
  grid.cells.Add(5, {1, 2, 4});
  DataArray quality;
  quality.name = "mean_ratio";
  quality.components = 3;
  quality.reals = {0.25, 0.5, -1, 1e-300, 7.5, -2};
  grid.cell_data.push_back({VtkAttributeKind::kScalars, quality.name, "default", {quality}});
  for (const GmshVersion version : {GmshVersion::k22, GmshVersion::k41}) {
    for (const Encoding encoding : {Encoding::kAscii, Encoding::kBinary}) {
      WriteOptions options;
      options.gmsh_version = version;
      options.encoding = encoding;
      const absl::StatusOr<std::string> bytes = SerializeGmsh(document, options);
      ASSERT_TRUE(bytes.ok()) << bytes.status();
      const bool on_nodes = version == GmshVersion::k22;
      EXPECT_EQ(bytes->find("$ElementNodeData\n") != std::string::npos, on_nodes);
      EXPECT_EQ(bytes->find("$ElementData\n") != std::string::npos, !on_nodes);
      const absl::StatusOr<MeshDocument> read = ParseGmsh(*bytes);
      ASSERT_TRUE(read.ok()) << read.status();
      ExpectSameArraysByName(grid.cell_data, read->grid.cell_data);
      ASSERT_EQ(read->gmsh->data_views.size(), 1u);
      EXPECT_EQ(read->gmsh->data_views[0].element_nodes, on_nodes);
      EXPECT_TRUE(read->gmsh->raw_sections.empty());
    }
  }
  // One run (the tetrahedron alone): meshio reads 2.2 $ElementData then.
  document.grid.cells = GridCells{};
  document.grid.cells.Add(10, {0, 1, 2, 3});
  document.grid.cell_data[0].arrays[0].reals = {0.25, 0.5, -1};
  WriteOptions v22;
  v22.gmsh_version = GmshVersion::k22;
  const absl::StatusOr<std::string> single = SerializeGmsh(document, v22);
  ASSERT_TRUE(single.ok()) << single.status();
  EXPECT_NE(single->find("$ElementData\n"), std::string::npos);
  EXPECT_EQ(single->find("$ElementNodeData\n"), std::string::npos);
}

// An $ElementNodeData view that varies within an element is another tool's: kept verbatim.
TEST(GmshCellArrays, VaryingElementNodeDataStaysVerbatim) {
  const std::string body = "1\n\"u\"\n1\n0\n3\n0\n1\n1\n1 4 0 1 2 3\n";
  const std::string text =
      "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 0 1 0\n"
      "4 0 0 1\n$EndNodes\n$Elements\n1\n1 4 2 0 1 1 2 3 4\n$EndElements\n"
      "$ElementNodeData\n" +
      body + "$EndElementNodeData\n";
  const absl::StatusOr<MeshDocument> read = ParseGmsh(text);
  ASSERT_TRUE(read.ok()) << read.status();
  EXPECT_TRUE(read->gmsh->data_views.empty());
  ASSERT_EQ(read->gmsh->raw_sections.size(), 1u);
  EXPECT_EQ(read->gmsh->raw_sections[0].name, "ElementNodeData");
  EXPECT_EQ(read->gmsh->raw_sections[0].body, body);
  EXPECT_EQ(FindArray(read->grid.cell_data, "u"), nullptr);
}

std::string Summary(const MeshDocument& document) {
  std::string text = "nodes " + std::to_string(document.grid.point_count()) + "\n";
  std::map<int, int> by_type;
  for (const std::uint8_t type : document.grid.cells.types) {
    ++by_type[GmshElementTypeOfVtk(type)->code];
  }
  for (const auto& [type, count] : by_type) {
    text += "elements " + std::to_string(type) + " " + std::to_string(count) + "\n";
  }
  {
    for (const GmshPhysicalName& group : document.gmsh->physical_names) {
      const auto cells = GmshGroupCells(document, group.name);
      text += "group " + std::to_string(group.dim) + " " + std::to_string(group.tag) + " " +
              std::to_string(cells.ok() ? cells->size() : 0) + " " + group.name + "\n";
    }
  }
  for (const bool on_nodes : {true, false}) {
    for (const VtkAttribute& attribute :
         on_nodes ? document.grid.point_data : document.grid.cell_data) {
      for (const DataArray& array : attribute.arrays) {
        if (array.name.starts_with("gmsh:")) continue;
        // Entries: all points / cells, or those the view read from the file listed.
        std::int64_t entries = array.tuple_count();
        int step = 0;
        std::string name = array.name;
        std::string kind = on_nodes ? "NodeData " : "ElementData ";
        for (const GmshDataView& view : document.gmsh->data_views) {
          if (view.on_nodes != on_nodes || view.array_name != array.name) continue;
          if (!view.listed.empty()) entries = static_cast<std::int64_t>(view.listed.size());
          step = static_cast<int>(view.integer_tags[0]);
          name = view.string_tags.front();
          if (view.element_nodes) kind = "ElementNodeData ";
        }
        text += std::string("view ") + kind + std::to_string(step) + " " + std::to_string(entries) +
                " " + name + "\n";
      }
    }
  }
  return text;
}

TEST(GmshOutputs, WriteFilesForGmshToRead) {
  std::filesystem::create_directories(testing::GmshOutputDirectory());
  const absl::StatusOr<UnstructuredGrid> vtk =
      ReadVtkFile(std::string(GETME_TEST_DATA) + "/hybrid-example.vtk");
  ASSERT_TRUE(vtk.ok()) << vtk.status();
  MeshDocument from_vtk = FromVtk(*vtk);
  // A "fixed" array on every third point, as the CLI's users mark fixed nodes.
  DataArray fixed{"fixed", VtkDataType::kInt32, 1, {}, {}};
  for (std::int64_t i = 0; i < vtk->point_count(); ++i) fixed.integers.push_back(i % 3 == 0);
  from_vtk.grid.point_data.push_back(
      VtkAttribute{VtkAttributeKind::kScalars, "fixed", "default", {fixed}});
  const absl::StatusOr<MeshDocument> hybrid = ParseGmshFile(GmshInput("hybrid_41_ascii.msh"));
  ASSERT_TRUE(hybrid.ok()) << hybrid.status();
  const absl::StatusOr<MeshDocument> views = ParseGmshFile(GmshInput("views_22_binary.msh"));
  ASSERT_TRUE(views.ok()) << views.status();
  const std::vector<std::pair<std::string, const MeshDocument*>> sources = {
      {"vtk", &from_vtk}, {"hybrid", &*hybrid}, {"views", &*views}};
  for (const auto& [name, document] : sources) {
    for (const GmshVariant& variant : AllGmshVariants()) {
      const std::string stem = name + "_" + variant.suffix;
      const absl::StatusOr<std::string> bytes = SerializeGmsh(*document, variant.options);
      ASSERT_TRUE(bytes.ok()) << bytes.status();
      testing::WriteBytes(GmshOutput(stem + ".msh"), *bytes);
      // The summary of what we wrote, as we read it back.
      const absl::StatusOr<MeshDocument> read = ParseGmsh(*bytes);
      ASSERT_TRUE(read.ok()) << read.status();
      testing::WriteBytes(GmshOutput(stem + ".summary"), Summary(*read));
    }
  }
}

}  // namespace
}  // namespace getme::formats
