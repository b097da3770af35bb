#include "formats/su2/su2_reader.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "absl/container/flat_hash_map.h"
#include "absl/container/flat_hash_set.h"
#include "absl/strings/ascii.h"
#include "absl/strings/str_cat.h"
#include "formats/su2/su2_lines.h"
#include "formats/su2/su2_mirrored_elements.h"
#include "formats/vtk_cell_type.h"
#include "formats/vtk_values.h"

namespace getme::formats {
namespace {

using su2::Line;
using su2::Lines;

// The longest row any section has: a hexahedron's type, 8 nodes and its index.
constexpr int kMaxRowTokens = 10;

// The whitespace-separated tokens of a line: the first kMaxRowTokens of them and how many there
// are in all.
struct Row {
  std::array<absl::string_view, kMaxRowTokens> tokens;
  int count = 0;
};

Row SplitRow(absl::string_view text) {
  Row row;
  std::size_t pos = 0;
  while (pos < text.size()) {
    while (pos < text.size() && absl::ascii_isspace(static_cast<unsigned char>(text[pos]))) ++pos;
    if (pos == text.size()) break;
    const std::size_t start = pos;
    while (pos < text.size() && !absl::ascii_isspace(static_cast<unsigned char>(text[pos]))) ++pos;
    if (row.count < kMaxRowTokens) row.tokens[row.count] = text.substr(start, pos - start);
    ++row.count;
  }
  return row;
}

std::optional<std::int64_t> ParseInteger(absl::string_view token) {
  std::int64_t value = 0;
  const char* end = token.data() + token.size();
  const auto [ptr, ec] = std::from_chars(token.data(), end, value);
  if (ec != std::errc() || ptr != end) return std::nullopt;
  return value;
}

// "NAME= value", the form of every section header (SU2 looks for "NELEM=" and so on).
struct Keyword {
  absl::string_view name;
  absl::string_view value;
};

std::optional<Keyword> SplitKeyword(absl::string_view text) {
  const std::size_t equals = text.find('=');
  if (equals == absl::string_view::npos) return std::nullopt;
  return Keyword{absl::StripAsciiWhitespace(text.substr(0, equals)),
                 absl::StripAsciiWhitespace(text.substr(equals + 1))};
}

// An element kind a section may hold: its VTK type code (SU2's element codes are VTK's) and node
// count.
struct RowKind {
  int type;
  int nodes;
  const char* name;
};

constexpr std::array<RowKind, 4> kVolumeKinds = {{{kVtkTetra, 4, "tetrahedron"},
                                                  {kVtkHexahedron, 8, "hexahedron"},
                                                  {kVtkWedge, 6, "prism"},
                                                  {kVtkPyramid, 5, "pyramid"}}};
constexpr std::array<RowKind, 3> kBoundaryKinds = {
    {{kVtkTriangle, 3, "triangle"}, {kVtkQuad, 4, "quadrilateral"}, {3, 2, "line"}}};

template <std::size_t kCount>
const RowKind* FindKind(const std::array<RowKind, kCount>& kinds, std::int64_t type) {
  for (const RowKind& kind : kinds) {
    if (kind.type == type) return &kind;
  }
  return nullptr;
}

absl::Status LineError(std::int64_t line, absl::string_view message) {
  return absl::InvalidArgumentError(absl::StrCat("line ", line, ": ", message));
}

// Keywords that must not appear in the text kept verbatim after the mesh: the tail would hide
// them.
constexpr std::array<absl::string_view, 7> kMeshKeywords = {
    "NDIME", "NELEM", "NPOIN", "NMARK", "MARKER_TAG", "MARKER_ELEMS", "NZONE"};

class Parser {
 public:
  explicit Parser(absl::string_view bytes) : bytes_(bytes), lines_(bytes) {}

  absl::StatusOr<MeshDocument> Parse() {
    while (std::optional<Line> line = lines_.Next()) {
      const std::optional<Keyword> keyword = SplitKeyword(line->text);
      if (!keyword.has_value()) {
        return LineError(line->number,
                         absl::StrCat("'", line->text,
                                      "' is not a section header (NAME= value): does a count "
                                      "announce fewer rows than follow?"));
      }
      absl::Status status = absl::OkStatus();
      if (keyword->name == "NDIME") {
        status = ReadDimension(*line, *keyword);
      } else if (keyword->name == "NZONE" || keyword->name == "IZONE") {
        status = CheckSingleZone(*line, *keyword);
      } else if (keyword->name == "NELEM") {
        status = ReadSection(*line, *keyword, elements_line_, &Parser::ReadElements);
      } else if (keyword->name == "NPOIN") {
        status = ReadSection(*line, *keyword, points_line_, &Parser::ReadPoints);
      } else if (keyword->name == "NMARK") {
        status = ReadSection(*line, *keyword, markers_line_, &Parser::ReadMarkers);
      } else if (keyword->name == "MARKER_TAG" || keyword->name == "MARKER_ELEMS") {
        return LineError(
            line->number,
            absl::StrCat(keyword->name, "= outside the markers: ",
                         markers_line_.has_value() ? absl::StrCat("NMARK= at line ", *markers_line_,
                                                                  " announces fewer markers")
                                                   : std::string("no NMARK= comes before it")));
      } else if (dimension_line_ && elements_line_ && points_line_) {
        status = KeepTail(*line);
        if (status.ok()) break;
      } else {
        return LineError(line->number,
                         absl::StrCat("unknown section '", keyword->name,
                                      "=' before the mesh is complete (an SU2 mesh has NDIME=, "
                                      "NELEM=, NPOIN= and NMARK=)"));
      }
      if (!status.ok()) return status;
    }
    const std::int64_t last = std::max<std::int64_t>(1, lines_.last_line());
    for (const auto& [seen, what] : {std::pair{dimension_line_, "NDIME= (the dimension)"},
                                     std::pair{elements_line_, "NELEM= (the elements)"},
                                     std::pair{points_line_, "NPOIN= (the points)"}}) {
      if (!seen.has_value()) {
        return LineError(last, absl::StrCat("the file ends without ", what));
      }
    }
    if (absl::Status status = CheckNodeRanges(volume_, volume_lines_, nullptr); !status.ok()) {
      return status;
    }
    if (absl::Status status = CheckNodeRanges(boundary_, boundary_lines_, &boundary_marker_);
        !status.ok()) {
      return status;
    }
    return Build();
  }

 private:
  using SectionReader = absl::Status (Parser::*)(const Line&, std::int64_t);

  absl::Status ReadDimension(const Line& line, const Keyword& keyword) {
    if (dimension_line_.has_value()) {
      return LineError(line.number, absl::StrCat("a second NDIME= (the first is at line ",
                                                 *dimension_line_, ")"));
    }
    const std::optional<std::int64_t> dimension = ParseInteger(keyword.value);
    if (!dimension.has_value()) {
      return LineError(line.number,
                       absl::StrCat("NDIME= '", keyword.value, "' is not a dimension"));
    }
    if (*dimension != 3) {
      return LineError(line.number, absl::StrCat("NDIME= ", *dimension,
                                                 ": only 3D meshes are read (getme smooths "
                                                 "volume meshes)"));
    }
    dimension_line_ = line.number;
    return absl::OkStatus();
  }

  // SU2's multi-zone mesh files (NZONE= n, then IZONE= 1 … n, each a complete mesh) would need a
  // document per zone.
  static absl::Status CheckSingleZone(const Line& line, const Keyword& keyword) {
    const std::optional<std::int64_t> value = ParseInteger(keyword.value);
    if (value == 1) return absl::OkStatus();
    return LineError(line.number,
                     absl::StrCat(keyword.name, "= ", keyword.value,
                                  ": multi-zone SU2 meshes are not supported; write each zone "
                                  "to a file of its own"));
  }

  absl::Status ReadSection(const Line& line, const Keyword& keyword,
                           std::optional<std::int64_t>& seen, SectionReader reader) {
    if (!dimension_line_.has_value()) {
      return LineError(line.number,
                       absl::StrCat(keyword.name, "= before NDIME=: the dimension comes first"));
    }
    if (seen.has_value()) {
      return LineError(line.number, absl::StrCat("a second ", keyword.name,
                                                 "= (the first is at line ", *seen, ")"));
    }
    seen = line.number;
    // NPOIN= may carry a second number, the points of the domain without halo points (SU2's
    // partitioned meshes); it is not needed for a whole mesh.
    const Row row = SplitRow(keyword.value);
    const bool two_allowed = keyword.name == "NPOIN";
    std::optional<std::int64_t> count =
        row.count >= 1 ? ParseInteger(row.tokens[0]) : std::optional<std::int64_t>();
    if (!count.has_value() || *count < 0 || row.count > (two_allowed ? 2 : 1) ||
        (row.count == 2 && !ParseInteger(row.tokens[1]).has_value())) {
      return LineError(line.number,
                       absl::StrCat(keyword.name, "= '", keyword.value, "' is not a count"));
    }
    return (this->*reader)(line, *count);
  }

  // The next row of a section announced at `header`, or an error saying that the section ends
  // early.
  absl::StatusOr<Line> NextRow(const Line& header, absl::string_view what, std::int64_t count,
                               std::int64_t index) {
    std::optional<Line> line = lines_.Next();
    if (!line.has_value()) {
      return LineError(header.number, absl::StrCat(header.text, " announces ", count, " ", what,
                                                   "; the file ends after ", index));
    }
    if (line->text.find('=') != absl::string_view::npos) {
      return LineError(line->number,
                       absl::StrCat("expected ", what, " row ", index, " of ", header.text,
                                    " (line ", header.number, "), found '", line->text, "'"));
    }
    return *line;
  }

  // How many rows of at least `min_bytes` bytes the rest of the file could hold: the bound on
  // any reservation.
  std::int64_t Reservable(std::int64_t count, std::int64_t min_bytes) const {
    return std::min<std::int64_t>(count, static_cast<std::int64_t>(lines_.remaining()) / min_bytes);
  }

  // One element row of the NELEM section or of a marker: "type node… [index]".
  template <std::size_t kCount>
  absl::Status ReadCellRow(const Line& line, absl::string_view what,
                           const std::array<RowKind, kCount>& kinds, absl::string_view known,
                           GridCells& cells, bool& indexed) {
    const Row row = SplitRow(line.text);
    const std::optional<std::int64_t> type = ParseInteger(row.tokens[0]);
    if (!type.has_value()) {
      return LineError(line.number, absl::StrCat(what, ": element type '", row.tokens[0],
                                                 "' is not an integer"));
    }
    const RowKind* kind = FindKind(kinds, *type);
    if (kind == nullptr) {
      return LineError(line.number,
                       absl::StrCat(what, ": unknown element type ", *type, " (", known, ")"));
    }
    const int extra = row.count - 1 - kind->nodes;
    if (extra < 0 || extra > 1) {
      return LineError(line.number, absl::StrCat(what, ": a ", kind->name, " (type ", *type,
                                                 ") has ", kind->nodes,
                                                 " nodes and an optional "
                                                 "index; the row has ",
                                                 row.count - 1, " values after the type"));
    }
    for (int k = 1; k <= kind->nodes; ++k) {
      const std::optional<std::int64_t> node = ParseInteger(row.tokens[k]);
      if (!node.has_value() || *node < 0) {
        return LineError(line.number, absl::StrCat(what, ": node ", k, " '", row.tokens[k],
                                                   "' is not a point index"));
      }
      cells.connectivity.push_back(*node);
    }
    if (extra == 1) {
      if (!ParseInteger(row.tokens[row.count - 1]).has_value()) {
        return LineError(line.number,
                         absl::StrCat(what, ": element index '", row.tokens[row.count - 1],
                                      "' is not an integer"));
      }
      indexed = true;
    }
    cells.types.push_back(static_cast<std::uint8_t>(kind->type));
    cells.offsets.push_back(static_cast<std::int64_t>(cells.connectivity.size()));
    return absl::OkStatus();
  }

  absl::Status ReadElements(const Line& header, std::int64_t count) {
    const std::int64_t reservable = Reservable(count, 10);  // "10 0 1 2 3\n"
    volume_.types.reserve(reservable);
    volume_.offsets.reserve(reservable + 1);
    volume_lines_.reserve(reservable);
    bool indexed = false;
    for (std::int64_t index = 0; index < count; ++index) {
      absl::StatusOr<Line> line = NextRow(header, "elements", count, index);
      if (!line.ok()) return line.status();
      if (absl::Status status =
              ReadCellRow(*line, absl::StrCat("NELEM element ", index), kVolumeKinds,
                          "volume elements: 10 tetrahedron, 12 hexahedron, 13 prism, 14 pyramid",
                          volume_, indexed);
          !status.ok()) {
        return status;
      }
      volume_lines_.push_back(line->number);
    }
    element_indices_ = indexed || count == 0;
    return absl::OkStatus();
  }

  absl::Status ReadPoints(const Line& header, std::int64_t count) {
    coordinates_.reserve(3 * Reservable(count, 6));  // "0 0 0\n"
    point_count_ = count;
    bool indexed = false;
    for (std::int64_t index = 0; index < count; ++index) {
      absl::StatusOr<Line> line = NextRow(header, "points", count, index);
      if (!line.ok()) return line.status();
      const Row row = SplitRow(line->text);
      if (row.count < 3 || row.count > 5) {
        return LineError(line->number,
                         absl::StrCat("NPOIN point ", index,
                                      ": expected 3 coordinates and an optional index, found ",
                                      row.count, " values"));
      }
      for (int k = 0; k < 3; ++k) {
        const std::optional<double> value = ParseRealToken(row.tokens[k]);
        if (!value.has_value() || !std::isfinite(*value)) {
          return LineError(line->number,
                           absl::StrCat("NPOIN point ", index, ": coordinate ", k, " '",
                                        row.tokens[k], "' is not a finite number"));
        }
        coordinates_.push_back(*value);
      }
      for (int k = 3; k < row.count; ++k) {
        if (!ParseInteger(row.tokens[k]).has_value()) {
          return LineError(line->number, absl::StrCat("NPOIN point ", index, ": point index '",
                                                      row.tokens[k], "' is not an integer"));
        }
        indexed = true;
      }
    }
    point_indices_ = indexed || count == 0;
    return absl::OkStatus();
  }

  absl::Status ReadMarkers(const Line& header, std::int64_t count) {
    absl::flat_hash_map<std::string, std::int64_t> marker_lines;
    std::int64_t previous_tag = 0;
    absl::flat_hash_set<std::int64_t> used_tags;
    for (std::int64_t marker = 0; marker < count; ++marker) {
      std::optional<Line> tag_line = lines_.Next();
      if (!tag_line.has_value()) {
        return LineError(header.number, absl::StrCat(header.text, " announces ", count,
                                                     " markers; the file ends after ", marker));
      }
      const std::optional<Keyword> tag = SplitKeyword(tag_line->text);
      if (!tag.has_value() || tag->name != "MARKER_TAG") {
        return LineError(
            tag_line->number,
            absl::StrCat("expected MARKER_TAG= for marker ", marker + 1, " of ", header.text,
                         " (line ", header.number, "), found '", tag_line->text, "'"));
      }
      const std::string name(tag->value);
      if (name.empty()) return LineError(tag_line->number, "MARKER_TAG= without a name");
      if (const auto [it, inserted] = marker_lines.emplace(name, tag_line->number); !inserted) {
        return LineError(tag_line->number, absl::StrCat("marker '", name,
                                                        "' again (its first MARKER_TAG= is at "
                                                        "line ",
                                                        it->second, ")"));
      }
      std::optional<Line> elems_line = lines_.Next();
      if (!elems_line.has_value()) {
        return LineError(tag_line->number,
                         absl::StrCat("marker '", name, "': the file ends before MARKER_ELEMS="));
      }
      const std::optional<Keyword> elems = SplitKeyword(elems_line->text);
      if (!elems.has_value() || elems->name != "MARKER_ELEMS") {
        return LineError(elems_line->number,
                         absl::StrCat("marker '", name, "': expected MARKER_ELEMS=, found '",
                                      elems_line->text, "'"));
      }
      const std::optional<std::int64_t> elements = ParseInteger(elems->value);
      if (!elements.has_value() || *elements < 0) {
        return LineError(elems_line->number, absl::StrCat("marker '", name, "': MARKER_ELEMS= '",
                                                          elems->value, "' is not a count"));
      }
      // meshio's rule (header): an integer name is the tag, any other name follows on.
      std::int64_t value = 0;
      const std::optional<std::int64_t> number = ParseInteger(name);
      if (number.has_value() && *number >= std::numeric_limits<std::int32_t>::min() &&
          *number <= std::numeric_limits<std::int32_t>::max()) {
        value = *number;
      } else {
        value = previous_tag + 1;
      }
      // Two markers must not share a tag (the tag is all a converted file keeps of the marker):
      // a clash, which meshio would let through, takes the next free tag.
      if (!used_tags.insert(value).second) {
        value = *std::max_element(used_tags.begin(), used_tags.end()) + 1;
        used_tags.insert(value);
      }
      previous_tag = value;
      markers_.push_back(Su2Marker{name, value});
      marker_first_cell_.push_back(boundary_.size());
      const std::int64_t reservable = Reservable(*elements, 8);  // "5 0 1 2\n"
      boundary_.types.reserve(boundary_.types.size() + reservable);
      bool indexed = false;
      for (std::int64_t index = 0; index < *elements; ++index) {
        absl::StatusOr<Line> line = NextRow(*elems_line, "boundary elements", *elements, index);
        if (!line.ok()) return line.status();
        if (absl::Status status = ReadCellRow(
                *line, absl::StrCat("marker '", name, "' element ", index), kBoundaryKinds,
                "marker elements: 5 triangle, 9 quadrilateral, 3 line", boundary_, indexed);
            !status.ok()) {
          return status;
        }
        boundary_lines_.push_back(line->number);
        boundary_marker_.push_back(static_cast<std::int32_t>(markers_.size() - 1));
        boundary_tags_.push_back(value);
      }
    }
    return absl::OkStatus();
  }

  // What follows the mesh sections is kept verbatim (Su2Extras::tail), unless it hides one of
  // them.
  absl::Status KeepTail(const Line& first) {
    const absl::string_view tail = bytes_.substr(first.start);
    Lines lines(tail);
    while (std::optional<Line> line = lines.Next()) {
      const std::optional<Keyword> keyword = SplitKeyword(line->text);
      if (!keyword.has_value()) continue;
      if (std::find(kMeshKeywords.begin(), kMeshKeywords.end(), keyword->name) !=
          kMeshKeywords.end()) {
        return LineError(first.number + line->number - 1,
                         absl::StrCat(keyword->name, "= after the section '",
                                      SplitKeyword(first.text)->name, "=' at line ", first.number,
                                      ", which getme keeps as it is without reading it: move the "
                                      "mesh sections before it"));
      }
    }
    tail_ = std::string(tail);
    if (!tail_.empty() && tail_.back() != '\n') tail_.push_back('\n');
    return absl::OkStatus();
  }

  absl::Status CheckNodeRanges(const GridCells& cells, const std::vector<std::int64_t>& lines,
                               const std::vector<std::int32_t>* markers) const {
    for (std::int64_t cell = 0; cell < cells.size(); ++cell) {
      const std::int64_t* nodes = cells.nodes(cell);
      for (std::int64_t k = 0; k < cells.node_count(cell); ++k) {
        if (nodes[k] < point_count_) continue;
        std::string what = absl::StrCat("NELEM element ", cell);
        if (markers != nullptr) {
          const std::int32_t marker = (*markers)[cell];
          what = absl::StrCat("marker '", markers_[marker].name, "' element ",
                              cell - marker_first_cell_[marker]);
        }
        return LineError(lines[cell],
                         absl::StrCat(what, ": node ", k + 1, " refers to point ", nodes[k],
                                      ", out of range 0..", point_count_ - 1,
                                      " (NPOIN= ", point_count_, " at line ", *points_line_, ")"));
      }
    }
    return absl::OkStatus();
  }

  static VtkAttribute TagAttribute(std::vector<std::int64_t> tags) {
    DataArray array;
    array.name = "su2:tag";
    array.type = VtkDataType::kInt;
    array.integers = std::move(tags);
    VtkAttribute attribute{VtkAttributeKind::kScalars, array.name, "default", {}};
    attribute.arrays.push_back(std::move(array));
    return attribute;
  }

  absl::StatusOr<MeshDocument> Build() {
    MeshDocument document;
    document.format = FileFormat::kSu2;
    document.as_read.encoding = Encoding::kAscii;
    UnstructuredGrid& grid = document.grid;
    grid.points.name = "points";
    grid.points.type = VtkDataType::kDouble;
    grid.points.components = 3;
    grid.points.reals = std::move(coordinates_);
    grid.cells = std::move(volume_);
    const std::int64_t volume_count = grid.cells.size();
    const std::int64_t base = static_cast<std::int64_t>(grid.cells.connectivity.size());
    grid.cells.types.insert(grid.cells.types.end(), boundary_.types.begin(), boundary_.types.end());
    grid.cells.connectivity.insert(grid.cells.connectivity.end(), boundary_.connectivity.begin(),
                                   boundary_.connectivity.end());
    for (std::size_t k = 1; k < boundary_.offsets.size(); ++k) {
      grid.cells.offsets.push_back(base + boundary_.offsets[k]);
    }
    std::vector<std::int64_t> tags(static_cast<std::size_t>(volume_count), 0);
    tags.insert(tags.end(), boundary_tags_.begin(), boundary_tags_.end());
    if (grid.cells.size() > 0) grid.cell_data.push_back(TagAttribute(std::move(tags)));

    Su2Extras extras;
    extras.markers = std::move(markers_);
    extras.element_indices = element_indices_;
    extras.point_indices = point_indices_;
    extras.mirrored_cells = RenumberMirroredCells(grid);
    extras.tail = std::move(tail_);
    document.su2 = std::move(extras);
    return document;
  }

  absl::string_view bytes_;
  Lines lines_;
  std::optional<std::int64_t> dimension_line_;
  std::optional<std::int64_t> elements_line_;
  std::optional<std::int64_t> points_line_;
  std::optional<std::int64_t> markers_line_;
  GridCells volume_;
  std::vector<std::int64_t> volume_lines_;
  GridCells boundary_;
  std::vector<std::int64_t> boundary_lines_;
  std::vector<std::int32_t> boundary_marker_;
  std::vector<std::int64_t> boundary_tags_;
  std::vector<std::int64_t> marker_first_cell_;
  std::vector<Su2Marker> markers_;
  std::vector<double> coordinates_;
  std::int64_t point_count_ = 0;
  bool element_indices_ = true;
  bool point_indices_ = true;
  std::string tail_;
};

}  // namespace

absl::StatusOr<MeshDocument> ParseSu2(absl::string_view bytes) { return Parser(bytes).Parse(); }

}  // namespace getme::formats
