#include "formats/medit/medit_reader.h"

#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "absl/status/status.h"
#include "absl/strings/ascii.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_split.h"
#include "formats/medit/medit_keywords.h"
#include "formats/medit/medit_scanner.h"
#include "formats/quote.h"

namespace getme::formats {
namespace {

using medit::Entity;
using medit::EntityCounts;
using medit::Keyword;
using medit::KeywordRole;
using medit::Token;

constexpr std::int64_t kMaxRef = std::numeric_limits<std::int32_t>::max();
constexpr std::int64_t kMinRef = std::numeric_limits<std::int32_t>::min();

absl::Status Error(std::int64_t line, absl::string_view message) {
  return absl::InvalidArgumentError(absl::StrCat("line ", line, ": ", message));
}

// The data of one section as read, checked against the entity counts once the whole file is read
// (GMF allows any section order, so Ridges may come before Edges).
struct Section {
  const Keyword* keyword = nullptr;
  std::int64_t line = 0;                  // the keyword's line
  std::vector<std::int64_t> entry_lines;  // where each entry starts
  std::vector<std::int64_t> integers;     // kElements, kRequiredVertices: all integer fields
  std::vector<double> reals;              // kVertices: coordinates
  std::vector<std::int64_t> refs;         // kVertices: refs
  std::vector<std::string> entries;       // kKept: each entry's tokens joined by spaces

  std::int64_t size() const { return static_cast<std::int64_t>(entry_lines.size()); }
};

class Parser {
 public:
  explicit Parser(absl::string_view bytes) : scanner_(bytes) {}

  absl::StatusOr<MeshDocument> Parse() {
    if (absl::Status status = ParseHeader(); !status.ok()) return status;
    for (;;) {
      const std::optional<Token> token = scanner_.Next();
      if (!token) {
        return Error(scanner_.line(), "the file ends without End (truncated?)");
      }
      absl::StatusOr<const Keyword*> keyword = LookUp(*token);
      if (!keyword.ok()) return keyword.status();
      if ((*keyword)->role == KeywordRole::kEnd) break;
      if (absl::Status status = ParseSection(**keyword, token->line); !status.ok()) return status;
    }
    if (const std::optional<Token> extra = scanner_.Next()) {
      return Error(extra->line, absl::StrCat(Quote(extra->text), " after End"));
    }
    if (absl::Status status = CheckIndices(); !status.ok()) return status;
    return Build();
  }

 private:
  absl::StatusOr<const Keyword*> LookUp(const Token& token) const {
    if (const Keyword* keyword = medit::FindKeyword(token.text)) return keyword;
    if (!absl::ascii_isalpha(static_cast<unsigned char>(token.text.front()))) {
      return Error(token.line,
                   absl::StrCat("expected a keyword, found ", Quote(token.text),
                                " (a section holds more entries than its count says?)"));
    }
    if (std::optional<std::string> reason = medit::UnsupportedKeywordReason(token.text)) {
      return Error(token.line,
                   absl::StrCat("keyword ", Quote(token.text), " is not supported: ", *reason));
    }
    return Error(token.line,
                 absl::StrCat("unknown keyword ", Quote(token.text),
                              ": MEDIT sections have no size or end marker, so the data of an "
                              "unknown keyword cannot be skipped"));
  }

  // MeshVersionFormatted first, Dimension right after, as every writer puts them (libMeshb,
  // gmsh, meshio, MMG); the field count of Vertices depends on the dimension.
  absl::Status ParseHeader() {
    std::optional<Token> token = scanner_.Next();
    if (!token || !absl::EqualsIgnoreCase(token->text, "MeshVersionFormatted")) {
      return Error(token ? token->line : scanner_.line(),
                   absl::StrCat("expected MeshVersionFormatted, found ",
                                token ? Quote(token->text) : "the end of the file"));
    }
    absl::StatusOr<std::int64_t> version = ReadHeaderValue("MeshVersionFormatted");
    if (!version.ok()) return version.status();
    if (*version < 1 || *version > 4) {
      return Error(last_line_, absl::StrCat("MeshVersionFormatted ", *version,
                                            ": expected 1 (single precision) to 4"));
    }
    version_ = static_cast<int>(*version);

    token = scanner_.Next();
    if (!token || !absl::EqualsIgnoreCase(token->text, "Dimension")) {
      return Error(token ? token->line : scanner_.line(),
                   absl::StrCat("expected Dimension after MeshVersionFormatted, found ",
                                token ? Quote(token->text) : "the end of the file"));
    }
    absl::StatusOr<std::int64_t> dimension = ReadHeaderValue("Dimension");
    if (!dimension.ok()) return dimension.status();
    if (*dimension == 2) {
      return Error(last_line_,
                   "Dimension 2: this is a planar mesh; getme smooths volume meshes and reads "
                   "only Dimension 3");
    }
    if (*dimension != 3) {
      return Error(last_line_, absl::StrCat("Dimension ", *dimension, ": expected 3"));
    }
    return absl::OkStatus();
  }

  absl::StatusOr<std::int64_t> ReadHeaderValue(absl::string_view keyword) {
    const std::optional<Token> token = scanner_.Next();
    if (!token) {
      return Error(scanner_.line(), absl::StrCat("the file ends after ", keyword));
    }
    last_line_ = token->line;
    const std::optional<std::int64_t> value = medit::ParseInteger(token->text);
    if (!value) {
      return Error(token->line,
                   absl::StrCat(keyword, ": expected an integer, found ", Quote(token->text)));
    }
    return *value;
  }

  absl::Status ParseSection(const Keyword& keyword, std::int64_t line) {
    if (keyword.role == KeywordRole::kVersion || keyword.role == KeywordRole::kDimension) {
      return Error(line, absl::StrCat("second ", keyword.name, ": the file starts with it"));
    }
    if (const auto [seen, inserted] = section_lines_.emplace(keyword.name, line); !inserted) {
      return Error(line, absl::StrCat("second ", keyword.name, " section (the first is at line ",
                                      seen->second, ")"));
    }
    std::int64_t count = 1;
    if (keyword.has_count) {
      const std::optional<Token> token = scanner_.Next();
      if (!token) {
        return Error(scanner_.line(),
                     absl::StrCat("the file ends before the entry count of ", keyword.name));
      }
      const std::optional<std::int64_t> value = medit::ParseInteger(token->text);
      if (!value || *value < 0) {
        return Error(token->line, absl::StrCat(keyword.name, ": expected an entry count, found ",
                                               Quote(token->text)));
      }
      count = *value;
      // Each field takes at least one character and one separator.
      const auto per_entry = static_cast<std::int64_t>(keyword.fields.size());
      const auto remaining = static_cast<std::int64_t>(scanner_.remaining());
      if (count > (remaining + 1) / (2 * per_entry)) {
        return Error(token->line, absl::StrCat(keyword.name, ": ", count, " entries of ", per_entry,
                                               " numbers cannot fit in the ", remaining,
                                               " bytes left in the file (truncated?)"));
      }
    }
    Section section;
    section.keyword = &keyword;
    section.line = line;
    section.entry_lines.reserve(count);
    const std::size_t fields = keyword.fields.size();
    switch (keyword.role) {
      case KeywordRole::kVertices:
        section.reals.reserve(3 * count);
        section.refs.reserve(count);
        break;
      case KeywordRole::kElements:
      case KeywordRole::kRequiredVertices:
        section.integers.reserve(fields * count);
        break;
      default:
        section.entries.reserve(count);
        break;
    }
    std::string entry;
    for (std::int64_t index = 0; index < count; ++index) {
      entry.clear();
      for (std::size_t field = 0; field < fields; ++field) {
        const std::optional<Token> token = scanner_.Next();
        if (!token) {
          return Error(scanner_.line(), absl::StrCat("the file ends in ", keyword.name, " entry ",
                                                     index + 1, " of ", count, " (truncated?)"));
        }
        if (field == 0) section.entry_lines.push_back(token->line);
        const char type = keyword.fields[field];
        if (std::optional<std::string> problem = medit::FieldError(type, token->text)) {
          return Error(token->line, absl::StrCat(keyword.name, " entry ", index + 1, ", field ",
                                                 field + 1, ": ", *problem));
        }
        switch (keyword.role) {
          case KeywordRole::kVertices:
            if (type == 'r') {
              section.reals.push_back(*medit::ParseReal(token->text));
            } else if (absl::Status status = AddRef(keyword, index, *token, section.refs);
                       !status.ok()) {
              return status;
            }
            break;
          case KeywordRole::kElements:
            if (field + 1 == fields) {
              if (absl::Status status = AddRef(keyword, index, *token, section.refs);
                  !status.ok()) {
                return status;
              }
            } else {
              section.integers.push_back(*medit::ParseInteger(token->text));
            }
            break;
          case KeywordRole::kRequiredVertices:
            section.integers.push_back(*medit::ParseInteger(token->text));
            break;
          default:
            if (field > 0) entry.push_back(' ');
            absl::StrAppend(&entry, token->text);
            break;
        }
      }
      if (keyword.role == KeywordRole::kKept) section.entries.push_back(entry);
    }
    sections_.push_back(std::move(section));
    return absl::OkStatus();
  }

  absl::Status AddRef(const Keyword& keyword, std::int64_t index, const Token& token,
                      std::vector<std::int64_t>& refs) {
    const std::int64_t ref = *medit::ParseInteger(token.text);
    if (ref < kMinRef || ref > kMaxRef) {
      return Error(token.line, absl::StrCat(keyword.name, " entry ", index + 1, ": reference ", ref,
                                            " does not fit a 32-bit integer"));
    }
    refs.push_back(ref);
    return absl::OkStatus();
  }

  EntityCounts Counts() const {
    EntityCounts counts{};
    for (const Section& section : sections_) {
      Entity entity = Entity::kNone;
      if (section.keyword->role == KeywordRole::kVertices) entity = Entity::kVertex;
      if (section.keyword->role == KeywordRole::kElements) {
        entity = section.keyword->element->entity;
      }
      if (section.keyword->name == "Normals") entity = Entity::kNormal;
      if (section.keyword->name == "Tangents") entity = Entity::kTangent;
      if (entity != Entity::kNone) counts[static_cast<int>(entity)] = section.size();
    }
    return counts;
  }

  absl::Status CheckIndices() const {
    const EntityCounts counts = Counts();
    for (const Section& section : sections_) {
      const Keyword& keyword = *section.keyword;
      const std::size_t fields = keyword.fields.size();
      for (std::int64_t index = 0; index < section.size(); ++index) {
        std::vector<absl::string_view> tokens;
        if (keyword.role == KeywordRole::kKept) {
          tokens = absl::StrSplit(section.entries[index], ' ');
        }
        for (std::size_t field = 0; field < fields; ++field) {
          const Entity entity = medit::EntityOf(keyword.refers[field]);
          if (entity == Entity::kNone) continue;
          std::int64_t value = 0;
          if (keyword.role == KeywordRole::kElements) {
            value = section.integers[index * (fields - 1) + field];
          } else if (keyword.role == KeywordRole::kRequiredVertices) {
            value = section.integers[index];
          } else {
            value = *medit::ParseInteger(tokens[field]);
          }
          if (std::optional<std::string> problem = medit::IndexError(entity, value, counts)) {
            return Error(section.entry_lines[index],
                         absl::StrCat(keyword.name, " entry ", index + 1, ": ", *problem));
          }
        }
      }
    }
    return absl::OkStatus();
  }

  static DataArray IntArray(std::string name) {
    DataArray array;
    array.name = std::move(name);
    array.type = VtkDataType::kInt;
    return array;
  }

  static VtkAttribute Scalars(DataArray array) {
    VtkAttribute attribute{VtkAttributeKind::kScalars, array.name, "default", {}};
    attribute.arrays.push_back(std::move(array));
    return attribute;
  }

  absl::StatusOr<MeshDocument> Build() {
    MeshDocument document;
    document.format = FileFormat::kMedit;
    document.as_read.encoding = Encoding::kAscii;
    UnstructuredGrid& grid = document.grid;
    grid.points.components = 3;
    grid.points.type = version_ == 1 ? VtkDataType::kFloat : VtkDataType::kDouble;
    MeditExtras extras;
    extras.version = version_;

    DataArray point_refs = IntArray("medit:ref");
    DataArray cell_refs = IntArray("medit:ref");
    std::optional<DataArray> fixed;
    for (Section& section : sections_) {
      switch (section.keyword->role) {
        case KeywordRole::kVertices:
          grid.points.reals = std::move(section.reals);
          point_refs.integers = std::move(section.refs);
          break;
        case KeywordRole::kElements:
          AddCells(section, grid.cells);
          cell_refs.integers.insert(cell_refs.integers.end(), section.refs.begin(),
                                    section.refs.end());
          break;
        case KeywordRole::kRequiredVertices:
          extras.required_vertices = std::move(section.integers);
          break;
        default:
          extras.sections.push_back(
              MeditSection{std::string(section.keyword->name), std::move(section.entries)});
          break;
      }
    }
    if (extras.required_vertices) {
      fixed = IntArray("fixed");
      fixed->integers.assign(grid.point_count(), 0);
      for (const std::int64_t vertex : *extras.required_vertices) fixed->integers[vertex - 1] = 1;
    }
    grid.point_data.push_back(Scalars(std::move(point_refs)));
    if (fixed) grid.point_data.push_back(Scalars(std::move(*fixed)));
    if (grid.cells.size() > 0) grid.cell_data.push_back(Scalars(std::move(cell_refs)));
    document.medit = std::move(extras);
    return document;
  }

  static void AddCells(const Section& section, GridCells& cells) {
    const medit::ElementKind& kind = *section.keyword->element;
    const auto nodes = static_cast<std::size_t>(kind.node_count);
    std::vector<std::int64_t> vtk_nodes(nodes);
    for (std::int64_t index = 0; index < section.size(); ++index) {
      const std::int64_t* medit_nodes = section.integers.data() + index * nodes;
      for (std::size_t k = 0; k < nodes; ++k) {
        vtk_nodes[k] = medit_nodes[medit::MeditToVtkNode(kind, static_cast<int>(k))] - 1;
      }
      cells.Add(kind.vtk_type, vtk_nodes);
    }
  }

  medit::Scanner scanner_;
  int version_ = 2;
  std::int64_t last_line_ = 1;
  std::map<absl::string_view, std::int64_t> section_lines_;
  std::vector<Section> sections_;
};

}  // namespace

absl::StatusOr<MeshDocument> ParseMedit(absl::string_view bytes) { return Parser(bytes).Parse(); }

}  // namespace getme::formats
