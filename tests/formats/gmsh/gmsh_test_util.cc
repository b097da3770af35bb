#include "gmsh_test_util.h"

#include <gtest/gtest.h>

#include <bit>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "formats/gmsh/gmsh_reader.h"

namespace getme::formats::testing {

std::vector<GmshVariant> AllGmshVariants() {
  std::vector<GmshVariant> variants;
  for (const GmshVersion version : {GmshVersion::k22, GmshVersion::k41}) {
    for (const Encoding encoding : {Encoding::kAscii, Encoding::kBinary}) {
      WriteOptions options;
      options.gmsh_version = version;
      options.encoding = encoding;
      variants.push_back({std::string(version == GmshVersion::k22 ? "22" : "41") +
                              (encoding == Encoding::kAscii ? "_ascii" : "_binary"),
                          options});
    }
  }
  return variants;
}

std::string GmshInput(const std::string& name) {
  return std::string(GMSH_TEST_INPUTS) + "/" + name;
}
std::string GmshOutputDirectory() {
  // Only the ctest test formats_gmsh_write_outputs sets it, so the discovered copy of the test
  // never rewrites files while check_gmsh_reads_outputs.py reads them.
  const char* directory = std::getenv("GETME_GMSH_OUTPUTS");
  return directory != nullptr ? directory : GMSH_TEST_OUTPUTS "-unchecked";
}

std::string GmshOutput(const std::string& name) { return GmshOutputDirectory() + "/" + name; }

std::string ReadBytes(const std::string& path) {
  std::ifstream stream(path, std::ios::binary);
  EXPECT_TRUE(stream.good()) << "cannot open " << path;
  std::ostringstream contents;
  contents << stream.rdbuf();
  return contents.str();
}

void WriteBytes(const std::string& path, const std::string& bytes) {
  std::ofstream stream(path, std::ios::binary);
  stream << bytes;
  EXPECT_TRUE(stream.good()) << "cannot write " << path;
}

absl::StatusOr<MeshDocument> ParseGmshFile(const std::string& path) {
  return ParseGmsh(ReadBytes(path));
}

GmshExpected ReadGmshExpected(const std::string& path) {
  GmshExpected expected;
  std::istringstream lines(ReadBytes(path));
  std::string line;
  const auto real = [](const std::string& word) { return std::strtod(word.c_str(), nullptr); };
  while (std::getline(lines, line)) {
    std::istringstream words(line);
    std::string kind;
    words >> kind;
    if (kind == "node") {
      ExpectedNode node;
      std::string x, y, z;
      words >> node.tag >> x >> y >> z;
      node.xyz[0] = real(x);
      node.xyz[1] = real(y);
      node.xyz[2] = real(z);
      expected.nodes.push_back(node);
    } else if (kind == "element") {
      ExpectedElement element;
      words >> element.tag >> element.type >> element.dim >> element.entity;
      std::int64_t node = 0;
      while (words >> node) element.nodes.push_back(node);
      expected.elements.push_back(element);
    } else if (kind == "physical") {
      ExpectedPhysical physical;
      words >> physical.dim >> physical.tag;
      std::getline(words, physical.name);
      if (!physical.name.empty() && physical.name.front() == ' ') physical.name.erase(0, 1);
      expected.physicals.push_back(physical);
    } else if (kind == "member") {
      int dim = 0, tag = 0, entity = 0;
      words >> dim >> tag >> entity;
      for (ExpectedPhysical& physical : expected.physicals) {
        if (physical.dim == dim && physical.tag == tag) physical.entities.push_back(entity);
      }
    } else if (kind == "data") {
      ExpectedData data;
      std::string where, time, value;
      words >> where >> data.name >> data.step >> time >> data.components >> data.tag;
      data.on_nodes = where == "NODE";
      data.time = real(time);
      while (words >> value) data.values.push_back(real(value));
      expected.data.push_back(data);
    }
  }
  return expected;
}

int VtkCodeOfGmshType(int gmsh_type) {
  switch (gmsh_type) {
    case 15:
      return 1;
    case 1:
      return 3;
    case 2:
      return 5;
    case 3:
      return 9;
    case 4:
      return 10;
    case 5:
      return 12;
    case 6:
      return 13;
    case 7:
      return 14;
    default:
      return -1;
  }
}

std::vector<std::int64_t> InVtkOrder(int gmsh_type, const std::vector<std::int64_t>& g) {
  if (gmsh_type == 6 && g.size() == 6) return {g[0], g[2], g[1], g[3], g[5], g[4]};
  return g;
}

bool SameBits(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

namespace {

void ExpectSameArrays(const std::vector<VtkAttribute>& expected,
                      const std::vector<VtkAttribute>& actual, const std::string& where) {
  std::vector<const DataArray*> a, b;
  for (const VtkAttribute& attribute : expected) {
    for (const DataArray& array : attribute.arrays) a.push_back(&array);
  }
  for (const VtkAttribute& attribute : actual) {
    for (const DataArray& array : attribute.arrays) b.push_back(&array);
  }
  ASSERT_EQ(a.size(), b.size()) << where;
  for (std::size_t i = 0; i < a.size(); ++i) {
    SCOPED_TRACE(where + " array '" + a[i]->name + "'");
    EXPECT_EQ(a[i]->name, b[i]->name);
    EXPECT_EQ(a[i]->components, b[i]->components);
    ASSERT_EQ(a[i]->value_count(), b[i]->value_count());
    for (std::int64_t k = 0; k < a[i]->value_count(); ++k) {
      ASSERT_TRUE(SameBits(a[i]->AsDouble(k), b[i]->AsDouble(k)))
          << "value " << k << ": " << a[i]->AsDouble(k) << " vs " << b[i]->AsDouble(k);
    }
  }
}

}  // namespace

void ExpectSameDocument(const MeshDocument& expected, const MeshDocument& actual,
                        bool with_extras) {
  const UnstructuredGrid& a = expected.grid;
  const UnstructuredGrid& b = actual.grid;
  ASSERT_EQ(a.point_count(), b.point_count());
  for (std::int64_t k = 0; k < 3 * a.point_count(); ++k) {
    ASSERT_TRUE(SameBits(a.points.AsDouble(k), b.points.AsDouble(k)))
        << "coordinate " << k << ": " << a.points.AsDouble(k) << " vs " << b.points.AsDouble(k);
  }
  EXPECT_EQ(a.cells.types, b.cells.types);
  EXPECT_EQ(a.cells.offsets, b.cells.offsets);
  EXPECT_EQ(a.cells.connectivity, b.cells.connectivity);
  ExpectSameArrays(a.point_data, b.point_data, "point data");
  ExpectSameArrays(a.cell_data, b.cell_data, "cell data");
  if (!with_extras) return;
  ASSERT_TRUE(expected.gmsh.has_value());
  ASSERT_TRUE(actual.gmsh.has_value());
  const GmshExtras& x = *expected.gmsh;
  const GmshExtras& y = *actual.gmsh;
  EXPECT_EQ(x.version_major, y.version_major);
  EXPECT_EQ(x.binary, y.binary);
  ASSERT_EQ(x.physical_names.size(), y.physical_names.size());
  for (std::size_t i = 0; i < x.physical_names.size(); ++i) {
    EXPECT_EQ(x.physical_names[i].dim, y.physical_names[i].dim);
    EXPECT_EQ(x.physical_names[i].tag, y.physical_names[i].tag);
    EXPECT_EQ(x.physical_names[i].name, y.physical_names[i].name);
  }
  EXPECT_EQ(x.has_entities, y.has_entities);
  ASSERT_EQ(x.entities.size(), y.entities.size());
  for (std::size_t i = 0; i < x.entities.size(); ++i) {
    EXPECT_EQ(x.entities[i].dim, y.entities[i].dim);
    EXPECT_EQ(x.entities[i].tag, y.entities[i].tag);
    for (int k = 0; k < 3; ++k) {
      EXPECT_TRUE(SameBits(x.entities[i].min[k], y.entities[i].min[k]));
      EXPECT_TRUE(SameBits(x.entities[i].max[k], y.entities[i].max[k]));
    }
    EXPECT_EQ(x.entities[i].physical_tags, y.entities[i].physical_tags);
    EXPECT_EQ(x.entities[i].boundary_tags, y.entities[i].boundary_tags);
  }
  EXPECT_EQ(x.node_tags, y.node_tags);
  ASSERT_EQ(x.node_blocks.size(), y.node_blocks.size());
  for (std::size_t i = 0; i < x.node_blocks.size(); ++i) {
    EXPECT_EQ(x.node_blocks[i].dim, y.node_blocks[i].dim);
    EXPECT_EQ(x.node_blocks[i].tag, y.node_blocks[i].tag);
    EXPECT_EQ(x.node_blocks[i].parametric, y.node_blocks[i].parametric);
    EXPECT_EQ(x.node_blocks[i].count, y.node_blocks[i].count);
    EXPECT_EQ(x.node_blocks[i].parametric_coords, y.node_blocks[i].parametric_coords);
  }
  EXPECT_EQ(x.element_tags, y.element_tags);
  EXPECT_EQ(x.element_entities, y.element_entities);
  EXPECT_EQ(x.element_tag_lists.offsets, y.element_tag_lists.offsets);
  EXPECT_EQ(x.element_tag_lists.values, y.element_tag_lists.values);
  ASSERT_EQ(x.data_views.size(), y.data_views.size());
  for (std::size_t i = 0; i < x.data_views.size(); ++i) {
    EXPECT_EQ(x.data_views[i].on_nodes, y.data_views[i].on_nodes);
    EXPECT_EQ(x.data_views[i].array_name, y.data_views[i].array_name);
    EXPECT_EQ(x.data_views[i].string_tags, y.data_views[i].string_tags);
    EXPECT_EQ(x.data_views[i].real_tags, y.data_views[i].real_tags);
    EXPECT_EQ(x.data_views[i].integer_tags, y.data_views[i].integer_tags);
    EXPECT_EQ(x.data_views[i].listed, y.data_views[i].listed);
  }
  ASSERT_EQ(x.raw_sections.size(), y.raw_sections.size());
  for (std::size_t i = 0; i < x.raw_sections.size(); ++i) {
    EXPECT_EQ(x.raw_sections[i].name, y.raw_sections[i].name);
    EXPECT_EQ(x.raw_sections[i].body, y.raw_sections[i].body);
  }
  EXPECT_EQ(x.section_order, y.section_order);
}

}  // namespace getme::formats::testing
