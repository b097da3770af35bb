#include "vtk_test_util.h"

#include <gtest/gtest.h>

#include <bit>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>

namespace getme::formats::testing {

std::string SharedMesh(const std::string& name) {
  return std::string(GETME_SHARED_MESHES) + "/mesquite/" + name;
}

std::vector<std::string> AllSharedMeshNames() {
  std::vector<std::string> names;
  // Called while ctest lists the tests (the build's last step): a missing folder must not abort
  // the build. SharedMeshes.EveryMeshTheReadmeListsIsPresent then fails and names the folder.
  std::error_code error;
  std::filesystem::directory_iterator folder(std::string(GETME_SHARED_MESHES) + "/mesquite", error);
  if (error) return names;
  for (const auto& entry : folder) {
    if (entry.path().extension() == ".vtk") names.push_back(entry.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

std::string ReadText(const std::string& path) {
  std::ifstream stream(path, std::ios::binary);
  std::ostringstream contents;
  contents << stream.rdbuf();
  return contents.str();
}

std::vector<std::int64_t> DeclaredNumbers(const std::string& text, const std::string& keyword) {
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line)) {
    std::istringstream words(line);
    std::string word;
    if (!(words >> word) || word != keyword) continue;
    std::vector<std::int64_t> numbers;
    std::int64_t number = 0;
    while (words >> number) numbers.push_back(number);
    return numbers;
  }
  return {};
}

std::int64_t DeclaredCount(const std::string& text, const std::string& keyword) {
  const std::vector<std::int64_t> numbers = DeclaredNumbers(text, keyword);
  return numbers.empty() ? -1 : numbers.front();
}

namespace {

void ExpectSameArray(const DataArray& expected, const DataArray& actual, const std::string& where) {
  SCOPED_TRACE(where + " array '" + expected.name + "'");
  EXPECT_EQ(expected.name, actual.name);
  EXPECT_EQ(expected.components, actual.components);
  const bool promoted = expected.type == VtkDataType::kFloat && actual.type == VtkDataType::kDouble;
  EXPECT_TRUE(expected.type == actual.type || promoted)
      << DataTypeInfo(expected.type).name << " became " << DataTypeInfo(actual.type).name;
  ASSERT_EQ(expected.value_count(), actual.value_count());
  EXPECT_EQ(expected.integers, actual.integers);
  for (std::size_t i = 0; i < expected.reals.size(); ++i) {
    ASSERT_EQ(std::bit_cast<std::uint64_t>(expected.reals[i]),
              std::bit_cast<std::uint64_t>(actual.reals[i]))
        << "value " << i << ": " << expected.reals[i] << " vs " << actual.reals[i];
  }
}

void ExpectSameAttributes(const std::vector<VtkAttribute>& expected,
                          const std::vector<VtkAttribute>& actual, const std::string& where) {
  ASSERT_EQ(expected.size(), actual.size()) << where;
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ(expected[i].kind, actual[i].kind) << where << " section " << i;
    EXPECT_EQ(expected[i].name, actual[i].name) << where << " section " << i;
    EXPECT_EQ(expected[i].lookup_table, actual[i].lookup_table) << where << " section " << i;
    ASSERT_EQ(expected[i].arrays.size(), actual[i].arrays.size()) << where << " section " << i;
    for (std::size_t a = 0; a < expected[i].arrays.size(); ++a) {
      ExpectSameArray(expected[i].arrays[a], actual[i].arrays[a], where);
    }
  }
}

}  // namespace

void ExpectSameContent(const UnstructuredGrid& expected, const UnstructuredGrid& actual) {
  EXPECT_EQ(expected.title, actual.title);
  EXPECT_EQ(expected.version_major, actual.version_major);
  EXPECT_EQ(expected.version_minor, actual.version_minor);
  ExpectSameArray(expected.points, actual.points, "POINTS");
  EXPECT_EQ(expected.cells.offsets, actual.cells.offsets);
  EXPECT_EQ(expected.cells.connectivity, actual.cells.connectivity);
  EXPECT_EQ(expected.cells.types, actual.cells.types);
  ExpectSameAttributes(expected.field_data, actual.field_data, "FIELD");
  ExpectSameAttributes(expected.point_data, actual.point_data, "POINT_DATA");
  ExpectSameAttributes(expected.cell_data, actual.cell_data, "CELL_DATA");
}

}  // namespace getme::formats::testing
