#include "vtu_expected.h"

#include <gtest/gtest.h>

#include <bit>
#include <cstdlib>
#include <fstream>
#include <map>

namespace getme::formats::testing {
namespace {

// The legacy types ParseVtu must report for each XML type (vtu_reader.h: the types VTK's legacy
// writer names for them).
const std::map<std::string, VtkDataType>& ExpectedTypes() {
  static const std::map<std::string, VtkDataType> types = {
      {"Int8", VtkDataType::kChar},     {"UInt8", VtkDataType::kUnsignedChar},
      {"Int16", VtkDataType::kShort},   {"UInt16", VtkDataType::kUnsignedShort},
      {"Int32", VtkDataType::kInt},     {"UInt32", VtkDataType::kUnsignedInt},
      {"Int64", VtkDataType::kLong},    {"UInt64", VtkDataType::kUnsignedLong},
      {"Float32", VtkDataType::kFloat}, {"Float64", VtkDataType::kDouble}};
  return types;
}

// The section holding array `name` in `attributes`, or null.
const VtkAttribute* SectionOf(const std::vector<VtkAttribute>& attributes, const std::string& name,
                              const DataArray** array) {
  for (const VtkAttribute& attribute : attributes) {
    for (const DataArray& candidate : attribute.arrays) {
      if (candidate.name == name) {
        *array = &candidate;
        return &attribute;
      }
    }
  }
  return nullptr;
}

}  // namespace

std::string FixturePath(const std::string& name) {
  return std::string(GETME_VTU_FIXTURES) + "/" + name;
}

ExpectedContent ReadExpected(const std::string& vtu_path) {
  ExpectedContent content;
  std::ifstream in(vtu_path + ".expected");
  EXPECT_TRUE(in.good()) << "no sidecar for " << vtu_path;
  std::string word;
  std::int64_t count = 0;
  in >> word >> count;
  EXPECT_EQ(word, "points");
  for (std::int64_t i = 0; i < 3 * count && in >> word; ++i) {
    content.points.push_back(std::strtod(word.c_str(), nullptr));  // hexadecimal floats
  }
  in >> word >> count;
  EXPECT_EQ(word, "cells");
  for (std::int64_t i = 0; i < count; ++i) {
    int type = 0;
    int nodes = 0;
    in >> type >> nodes;
    content.types.push_back(static_cast<std::uint8_t>(type));
    content.cells.emplace_back(nodes);
    for (std::int64_t& id : content.cells.back()) in >> id;
  }
  while (in >> word) {
    EXPECT_EQ(word, "array");
    ExpectedArray array;
    in >> array.where >> array.name >> array.xml_type >> array.components >> array.tuples >>
        array.keyword;
    array.values.resize(array.tuples * array.components);
    for (std::string& value : array.values) in >> value;
    content.arrays.push_back(std::move(array));
  }
  EXPECT_FALSE(content.points.empty()) << vtu_path;
  return content;
}

void ExpectContent(const ExpectedContent& expected, const UnstructuredGrid& grid) {
  ASSERT_EQ(grid.points.reals.size(), expected.points.size());
  for (std::size_t i = 0; i < expected.points.size(); ++i) {
    ASSERT_EQ(std::bit_cast<std::uint64_t>(grid.points.reals[i]),
              std::bit_cast<std::uint64_t>(expected.points[i]))
        << "coordinate " << i << ": " << grid.points.reals[i] << " vs " << expected.points[i];
  }
  ASSERT_EQ(grid.cells.size(), static_cast<std::int64_t>(expected.cells.size()));
  EXPECT_EQ(grid.cells.types, expected.types);
  for (std::int64_t cell = 0; cell < grid.cells.size(); ++cell) {
    const std::vector<std::int64_t> nodes(grid.cells.nodes(cell),
                                          grid.cells.nodes(cell) + grid.cells.node_count(cell));
    EXPECT_EQ(nodes, expected.cells[cell]) << "cell " << cell;
  }
  std::size_t arrays = 0;
  for (const auto* section : {&grid.point_data, &grid.cell_data, &grid.field_data}) {
    for (const VtkAttribute& attribute : *section) arrays += attribute.arrays.size();
  }
  EXPECT_EQ(arrays, expected.arrays.size());
  for (const ExpectedArray& want : expected.arrays) {
    SCOPED_TRACE(want.where + " array " + want.name);
    const std::vector<VtkAttribute>& attributes = want.where == "point"  ? grid.point_data
                                                  : want.where == "cell" ? grid.cell_data
                                                                         : grid.field_data;
    const DataArray* array = nullptr;
    const VtkAttribute* section = SectionOf(attributes, want.name, &array);
    ASSERT_NE(section, nullptr);
    EXPECT_EQ(AttributeKindKeyword(section->kind), want.keyword);
    ASSERT_TRUE(ExpectedTypes().contains(want.xml_type)) << want.xml_type;
    EXPECT_EQ(array->type, ExpectedTypes().at(want.xml_type))
        << DataTypeInfo(array->type).name << " for " << want.xml_type;
    EXPECT_EQ(array->components, want.components);
    ASSERT_EQ(array->value_count(), static_cast<std::int64_t>(want.values.size()));
    for (std::size_t i = 0; i < want.values.size(); ++i) {
      const char* text = want.values[i].c_str();
      if (want.xml_type.starts_with("Float")) {
        EXPECT_EQ(std::bit_cast<std::uint64_t>(array->reals[i]),
                  std::bit_cast<std::uint64_t>(std::strtod(text, nullptr)))
            << "value " << i << ": " << array->reals[i] << " vs " << text;
      } else if (want.xml_type == "UInt64") {
        // Stored bit-cast (unstructured_grid.h).
        EXPECT_EQ(array->integers[i], std::bit_cast<std::int64_t>(std::strtoull(text, nullptr, 10)))
            << "value " << i;
      } else {
        EXPECT_EQ(array->integers[i], std::strtoll(text, nullptr, 10)) << "value " << i;
      }
    }
  }
}

}  // namespace getme::formats::testing
