#include "su2_test_util.h"

#include <sstream>

#include "absl/strings/match.h"
#include "absl/strings/numbers.h"
#include "absl/strings/str_split.h"
#include "absl/strings/strip.h"
#include "formats/grid_mesh.h"
#include "getme/elements/element_quality.h"

namespace getme::formats::testing {

std::string SharedSu2(const std::string& name) {
  return std::string(GETME_SHARED_MESHES) + "/su2/" + name;
}

std::string Su2FixturePath(const std::string& name) {
  return std::string(SU2_FIXTURES) + "/" + name;
}

std::vector<std::vector<std::string>> SectionRows(const std::string& text,
                                                  const std::string& keyword) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line)) {
    if (absl::StartsWith(line, keyword)) break;
  }
  // A marker's rows follow its MARKER_ELEMS= line; a section's its own header.
  std::string header = line;
  if (absl::StartsWith(keyword, "MARKER_TAG=")) std::getline(lines, header);
  const std::size_t equals = header.find('=');
  std::int64_t count = 0;
  if (equals == std::string::npos ||
      !absl::SimpleAtoi(absl::StripAsciiWhitespace(header.substr(equals + 1)), &count)) {
    return rows;
  }
  for (std::int64_t k = 0; k < count && std::getline(lines, line); ++k) {
    rows.push_back(absl::StrSplit(line, absl::ByAnyChar(" \t\r"), absl::SkipEmpty()));
  }
  return rows;
}

absl::StatusOr<std::vector<std::int64_t>> InvalidVolumeCellIndices(const UnstructuredGrid& grid) {
  absl::StatusOr<GridMesh> mesh = GridToMesh(grid);
  if (!mesh.ok()) return mesh.status();
  std::vector<std::int64_t> invalid;
  for (ElementId element = 0; element < mesh->mesh.element_count(); ++element) {
    DispatchElementType(mesh->mesh.type(element), [&]<ElementType kType>() {
      const auto nodes = GatherNodes<kType>(mesh->mesh, mesh->mesh.element_nodes(element).data());
      if (!IsValid<kType>(nodes)) invalid.push_back(mesh->element_cells[element]);
    });
  }
  return invalid;
}

std::int64_t InvalidVolumeCells(const UnstructuredGrid& grid) {
  const absl::StatusOr<std::vector<std::int64_t>> invalid = InvalidVolumeCellIndices(grid);
  return invalid.ok() ? static_cast<std::int64_t>(invalid->size()) : -1;
}

}  // namespace getme::formats::testing
