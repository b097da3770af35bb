#include "openfoam_test_util.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

namespace getme::formats::testing {

std::string CasePath(const std::string& name) {
  return std::string(OPENFOAM_FIXTURES) + "/" + name;
}
std::string FixturePath(const std::string& name) { return CasePath(name); }

std::map<std::string, std::int64_t> CheckMeshCounts(const std::string& name) {
  std::ifstream in(FixturePath(name + ".checkMesh"));
  EXPECT_TRUE(in.good()) << "missing " << name << ".checkMesh (write_fixtures.py)";
  std::map<std::string, std::int64_t> counts;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string key;
    words >> key;
    if (key == "patch") {
      std::string patch;
      words >> patch;
      key += " " + patch;
    }
    std::int64_t value = -1;
    words >> value;
    counts[key] = value;
  }
  return counts;
}

std::map<int, std::int64_t> CellTypeCounts(const UnstructuredGrid& grid) {
  std::map<int, std::int64_t> counts;
  for (const std::uint8_t type : grid.cells.types) ++counts[type];
  return counts;
}

std::vector<std::int64_t> IntegerArray(const std::vector<VtkAttribute>& attributes,
                                       const std::string& name) {
  const DataArray* array = FindArray(attributes, name);
  return array == nullptr ? std::vector<std::int64_t>{} : array->integers;
}

std::string ReadText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream out;
  out << in.rdbuf();
  return out.str();
}

void WriteText(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

}  // namespace getme::formats::testing
