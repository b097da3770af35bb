#include "formats/medit/medit_writer.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "absl/status/status.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_join.h"
#include "absl/strings/str_split.h"
#include "formats/medit/medit_keywords.h"
#include "formats/medit/medit_layout.h"
#include "formats/vtk_values.h"
#include "spdlog/spdlog.h"

namespace getme::formats {
namespace {

using medit::CellLayout;
using medit::ElementSection;
using medit::Entity;
using medit::EntityCounts;
using medit::Keyword;
using medit::KeywordRole;

constexpr absl::string_view kRefName = "medit:ref";
constexpr absl::string_view kFixedName = "fixed";

// GMF solution types (libmeshb7.h: GmfSca, GmfVec, GmfSymMat, GmfMat).
constexpr int kGmfScalar = 1;
constexpr int kGmfVector = 2;
constexpr int kGmfMatrix = 4;

std::int64_t& Count(EntityCounts& counts, Entity entity) {
  return counts[static_cast<int>(entity)];
}

absl::Status CheckPoints(const UnstructuredGrid& grid) {
  const DataArray& points = grid.points;
  if (points.components != 3 || IsIntegerType(points.type) || !points.integers.empty() ||
      points.value_count() % 3 != 0) {
    return absl::InvalidArgumentError(
        "points: expected 3 real components per point, stored in `reals`");
  }
  return absl::OkStatus();
}

// Refs of the points: the point array "medit:ref", or 0.
absl::StatusOr<std::vector<std::int64_t>> PointRefs(const UnstructuredGrid& grid) {
  std::vector<std::int64_t> refs(grid.point_count(), 0);
  const DataArray* array = FindArray(grid.point_data, kRefName);
  if (array == nullptr) return refs;
  if (array->components != 1 || array->tuple_count() != grid.point_count()) {
    return absl::InvalidArgumentError(absl::StrCat(
        "point data 'medit:ref' has ", array->tuple_count(), " tuples of ", array->components,
        " components; expected ", grid.point_count(), " single values, one per point"));
  }
  for (std::int64_t point = 0; point < grid.point_count(); ++point) {
    const double value = array->AsDouble(point);
    if (!(value >= std::numeric_limits<std::int32_t>::min() &&
          value <= std::numeric_limits<std::int32_t>::max() && std::trunc(value) == value)) {
      return absl::InvalidArgumentError(absl::StrCat("point data 'medit:ref' at point ", point,
                                                     " is ", value,
                                                     "; a MEDIT ref is a 32-bit integer"));
    }
    refs[point] = static_cast<std::int64_t>(value);
  }
  return refs;
}

// The RequiredVertices list (1-based), or nullopt when there is no section to write.
absl::StatusOr<std::optional<std::vector<std::int64_t>>> RequiredVertices(
    const UnstructuredGrid& grid, const MeditExtras* extras) {
  const DataArray* fixed = FindArray(grid.point_data, kFixedName);
  if (fixed == nullptr) return std::nullopt;
  if (fixed->components < 1 || fixed->tuple_count() != grid.point_count()) {
    return absl::InvalidArgumentError(absl::StrCat("point data 'fixed' has ", fixed->tuple_count(),
                                                   " tuples for ", grid.point_count(), " points"));
  }
  std::vector<std::int64_t> marked;
  for (std::int64_t point = 0; point < grid.point_count(); ++point) {
    for (int c = 0; c < fixed->components; ++c) {
      if (fixed->AsDouble(point * fixed->components + c) != 0.0) {
        marked.push_back(point + 1);
        break;
      }
    }
  }
  if (extras != nullptr && extras->required_vertices) {
    std::vector<std::int64_t> listed = *extras->required_vertices;
    std::sort(listed.begin(), listed.end());
    listed.erase(std::unique(listed.begin(), listed.end()), listed.end());
    if (listed == marked) return extras->required_vertices;
  }
  if (marked.empty()) return std::nullopt;
  return marked;
}

class MeshWriter {
 public:
  explicit MeshWriter(const MeshDocument& document) : document_(document), grid_(document.grid) {}

  absl::StatusOr<std::string> Write() {
    if (absl::Status status = CheckPoints(grid_); !status.ok()) return status;
    absl::StatusOr<CellLayout> layout = medit::PlanCells(grid_);
    if (!layout.ok()) return layout.status();
    std::string ref_source;
    absl::StatusOr<std::vector<std::int64_t>> cell_refs = medit::CellRefs(grid_, &ref_source);
    if (!cell_refs.ok()) return cell_refs.status();
    absl::StatusOr<std::vector<std::int64_t>> point_refs = PointRefs(grid_);
    if (!point_refs.ok()) return point_refs.status();
    const MeditExtras* extras = document_.medit ? &*document_.medit : nullptr;
    if (extras != nullptr && (extras->version < 1 || extras->version > 4)) {
      return absl::InvalidArgumentError(
          absl::StrCat("MEDIT extras: version ", extras->version, "; expected 1 to 4"));
    }
    absl::StatusOr<std::optional<std::vector<std::int64_t>>> required =
        RequiredVertices(grid_, extras);
    if (!required.ok()) return required.status();

    absl::StrAppend(&out_, "MeshVersionFormatted ", Version(extras), "\n\nDimension 3\n");
    WriteVertices(*point_refs);
    for (const ElementSection& section : layout->sections) WriteElements(section, *cell_refs);
    if (*required) {
      absl::StrAppend(&out_, "\nRequiredVertices\n", (*required)->size(), "\n");
      for (const std::int64_t vertex : **required) absl::StrAppend(&out_, vertex, "\n");
    }
    if (extras != nullptr) {
      if (absl::Status status = WriteExtras(*extras, *layout); !status.ok()) return status;
    }
    out_.append("\nEnd\n");
    Warn(*layout, ref_source);
    return std::move(out_);
  }

 private:
  int Version(const MeditExtras* extras) const {
    const int version = extras != nullptr ? extras->version : 2;
    if (version != 1) return version;
    for (const double value : grid_.points.reals) {
      if (!std::isnan(value) && static_cast<double>(static_cast<float>(value)) != value) return 2;
    }
    return 1;
  }

  void WriteVertices(const std::vector<std::int64_t>& refs) {
    absl::StrAppend(&out_, "\nVertices\n", grid_.point_count(), "\n");
    const std::vector<double>& xyz = grid_.points.reals;
    for (std::int64_t point = 0; point < grid_.point_count(); ++point) {
      for (int c = 0; c < 3; ++c) {
        AppendReal(out_, xyz[3 * point + c]);
        out_.push_back(' ');
      }
      absl::StrAppend(&out_, refs[point], "\n");
    }
  }

  void WriteElements(const ElementSection& section, const std::vector<std::int64_t>& refs) {
    const medit::ElementKind& kind = *section.kind;
    absl::StrAppend(&out_, "\n", kind.keyword, "\n", section.cells.size(), "\n");
    for (const std::int64_t cell : section.cells) {
      const std::int64_t* nodes = grid_.cells.nodes(cell);
      for (int k = 0; k < kind.node_count; ++k) {
        // The prism permutation is its own inverse: MEDIT node k is VTK node order[k].
        absl::StrAppend(&out_, nodes[medit::MeditToVtkNode(kind, k)] + 1, " ");
      }
      absl::StrAppend(&out_, refs[cell], "\n");
    }
  }

  absl::Status WriteExtras(const MeditExtras& extras, const CellLayout& layout) {
    EntityCounts counts{};
    Count(counts, Entity::kVertex) = grid_.point_count();
    for (const ElementSection& section : layout.sections) {
      if (section.kind->entity != Entity::kNone) {
        Count(counts, section.kind->entity) = static_cast<std::int64_t>(section.cells.size());
      }
    }
    for (const MeditSection& section : extras.sections) {
      const auto size = static_cast<std::int64_t>(section.entries.size());
      if (section.keyword == "Normals") Count(counts, Entity::kNormal) = size;
      if (section.keyword == "Tangents") Count(counts, Entity::kTangent) = size;
    }
    for (const MeditSection& section : extras.sections) {
      const Keyword* keyword = medit::FindKeyword(section.keyword);
      if (keyword == nullptr || keyword->role != KeywordRole::kKept) {
        return absl::InvalidArgumentError(absl::StrCat("MEDIT extras: '", section.keyword,
                                                       "' is not a section getme keeps verbatim"));
      }
      if (!keyword->has_count && section.entries.size() != 1) {
        return absl::InvalidArgumentError(absl::StrCat("MEDIT extras: ", keyword->name,
                                                       " holds exactly one entry, not ",
                                                       section.entries.size()));
      }
      absl::StrAppend(&out_, "\n", keyword->name, "\n");
      if (keyword->has_count) absl::StrAppend(&out_, section.entries.size(), "\n");
      for (std::size_t index = 0; index < section.entries.size(); ++index) {
        const std::vector<absl::string_view> tokens =
            absl::StrSplit(section.entries[index], absl::ByAnyChar(" \t"), absl::SkipEmpty());
        const std::string where =
            absl::StrCat("MEDIT extras: ", keyword->name, " entry ", index + 1);
        if (tokens.size() != keyword->fields.size()) {
          return absl::InvalidArgumentError(absl::StrCat(
              where, " has ", tokens.size(), " numbers; expected ", keyword->fields.size()));
        }
        for (std::size_t field = 0; field < tokens.size(); ++field) {
          if (std::optional<std::string> problem =
                  medit::FieldError(keyword->fields[field], tokens[field])) {
            return absl::InvalidArgumentError(
                absl::StrCat(where, ", field ", field + 1, ": ", *problem));
          }
          const Entity entity = medit::EntityOf(keyword->refers[field]);
          if (entity == Entity::kNone) continue;
          if (std::optional<std::string> problem =
                  medit::IndexError(entity, *medit::ParseInteger(tokens[field]), counts)) {
            return absl::InvalidArgumentError(absl::StrCat(where, ": ", *problem));
          }
        }
        absl::StrAppend(&out_, absl::StrJoin(tokens, " "), "\n");
      }
    }
    return absl::OkStatus();
  }

  void Warn(const CellLayout& layout, const std::string& ref_source) const {
    if (layout.vertex_cells > 0) {
      spdlog::warn("MEDIT .mesh: {} vertex cells not written: MEDIT has no vertex elements",
                   layout.vertex_cells);
    }
    if (layout.regrouped) {
      spdlog::warn(
          "MEDIT .mesh: elements are grouped by kind, so the file's element order differs from "
          "the input's cell order");
    }
    if (ref_source == "gmsh:physical") {
      spdlog::warn("MEDIT .mesh: element refs taken from cell data 'gmsh:physical'");
    }
    std::vector<std::string> dropped;
    for (const VtkAttribute& attribute : grid_.point_data) {
      for (const DataArray& array : attribute.arrays) {
        if (array.name != kRefName && array.name != kFixedName) {
          dropped.push_back(absl::StrCat("point data '", array.name, "'"));
        }
      }
    }
    for (const VtkAttribute& attribute : grid_.field_data) {
      for (const DataArray& array : attribute.arrays) {
        dropped.push_back(absl::StrCat("field data '", array.name, "'"));
      }
    }
    if (!dropped.empty()) {
      spdlog::warn("MEDIT .mesh cannot hold {}; not written", absl::StrJoin(dropped, ", "));
    }
  }

  const MeshDocument& document_;
  const UnstructuredGrid& grid_;
  std::string out_;
};

// One field of a .sol keyword: a GMF type and the values of one cell array it takes.
struct SolutionField {
  const DataArray* array;
  int type;
  int first_component;
  int components;
  std::string name;
};

absl::StatusOr<std::vector<SolutionField>> SolutionFields(const UnstructuredGrid& grid,
                                                          const std::string& ref_source) {
  std::vector<SolutionField> fields;
  for (const VtkAttribute& attribute : grid.cell_data) {
    for (const DataArray& array : attribute.arrays) {
      if (array.name == ref_source) continue;
      if (array.components < 1 || array.tuple_count() != grid.cells.size() ||
          array.value_count() != array.tuple_count() * array.components) {
        return absl::InvalidArgumentError(
            absl::StrCat("cell data '", array.name, "' has ", array.value_count(), " values of ",
                         array.components, " components for ", grid.cells.size(), " cells"));
      }
      switch (array.components) {
        case 1:
          fields.push_back({&array, kGmfScalar, 0, 1, array.name});
          break;
        case 3:
          fields.push_back({&array, kGmfVector, 0, 3, array.name});
          break;
        case 9:
          fields.push_back({&array, kGmfMatrix, 0, 9, array.name});
          break;
        default:
          spdlog::warn(
              "MEDIT .sol: cell data '{}' has {} components, which is no GMF type; "
              "written as {} scalars",
              array.name, array.components, array.components);
          for (int c = 0; c < array.components; ++c) {
            fields.push_back({&array, kGmfScalar, c, 1, absl::StrCat(array.name, "[", c, "]")});
          }
          break;
      }
    }
  }
  return fields;
}

// ReferenceStrings names are the rest of a line.
std::string LineSafe(absl::string_view name) {
  std::string safe(name.empty() ? "unnamed" : name);
  for (char& c : safe) {
    if (static_cast<unsigned char>(c) < 0x20) c = '_';
  }
  return safe;
}

}  // namespace

absl::StatusOr<std::string> SerializeMedit(const MeshDocument& document,
                                           const WriteOptions& options) {
  if (options.encoding == Encoding::kBinary) {
    return absl::InvalidArgumentError(
        "MEDIT: the binary .meshb variant needs libMeshb, which no Debian package provides; "
        "write the ASCII .mesh instead");
  }
  return MeshWriter(document).Write();
}

absl::StatusOr<std::string> SerializeMeditSolution(const MeshDocument& document) {
  const UnstructuredGrid& grid = document.grid;
  absl::StatusOr<CellLayout> layout = medit::PlanCells(grid);
  if (!layout.ok()) return layout.status();
  std::string ref_source;
  if (absl::StatusOr<std::vector<std::int64_t>> refs = medit::CellRefs(grid, &ref_source);
      !refs.ok()) {
    return refs.status();
  }
  absl::StatusOr<std::vector<SolutionField>> fields = SolutionFields(grid, ref_source);
  if (!fields.ok()) return fields.status();
  if (fields->empty() || layout->sections.empty()) return std::string();

  std::string out = "MeshVersionFormatted 2\n\nDimension 3\n";
  for (const ElementSection& section : layout->sections) {
    absl::StrAppend(&out, "\n", section.kind->solution_keyword, "\n", section.cells.size(), "\n",
                    fields->size());
    for (const SolutionField& field : *fields) absl::StrAppend(&out, " ", field.type);
    out.push_back('\n');
    for (const std::int64_t cell : section.cells) {
      bool first = true;
      for (const SolutionField& field : *fields) {
        for (int c = 0; c < field.components; ++c) {
          if (!first) out.push_back(' ');
          first = false;
          AppendReal(out, field.array->AsDouble(cell * field.array->components +
                                                field.first_component + c));
        }
      }
      out.push_back('\n');
    }
  }
  absl::StrAppend(&out, "\nReferenceStrings\n", layout->sections.size() * fields->size(), "\n");
  for (const ElementSection& section : layout->sections) {
    for (std::size_t f = 0; f < fields->size(); ++f) {
      absl::StrAppend(&out, section.kind->gmf_solution_code, " ", f + 1, " ",
                      LineSafe((*fields)[f].name), "\n");
    }
  }
  out.append("\nEnd\n");
  return out;
}

}  // namespace getme::formats
