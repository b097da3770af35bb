// Gmsh MSH reader, hand-written rather than built on libgmsh (gmsh.h / gmsh::open) because:
// (1) Gmsh's API is one process-wide model with global options and is not reentrant, so a
//     client library embedded in a pipeline would fight the pipeline's own use of Gmsh (after a
//     failed gmsh::open, for one, the next failures in the same process are only logged);
// (2) its reader's failures do not say where: Gmsh 4.8 reports a bad coordinate, an unknown
//     element type or a truncated 2.2 file as "Error loading 'file.msh'", a truncated 4.1 file
//     as "Could not read nodes" / "Could not read elements", a missing node as "Wrong node
//     index 9" — no line, section offset or element — and we must name them;
// (3) it writes files back in its own layout: gmsh::write renumbers 2.2 nodes and elements,
//     regroups elements by type and prints ASCII coordinates with 16 significant digits
//     (0.30000000000000004 comes back as 0.3), where a round trip here must keep the file's
//     order, tags and every bit of the coordinates.
// Gmsh's Python API is still what writes the test inputs (tests/formats/gmsh).
//
// Format reference: the Gmsh reference manual, "MSH file format" (4.1) and "Legacy formats"
// (2.2).

#include "formats/gmsh/gmsh_reader.h"

#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "absl/container/flat_hash_map.h"
#include "absl/status/status.h"
#include "absl/strings/ascii.h"
#include "absl/strings/match.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_split.h"
#include "formats/gmsh/gmsh_cursor.h"
#include "formats/gmsh/gmsh_element_type.h"
#include "formats/gmsh/gmsh_tag_index.h"
#include "formats/quote.h"
#include "formats/vtk_values.h"

namespace getme::formats {
namespace {

// Gmsh ends a quoted name at its first inner '"' (ExtractDoubleQuotedString) and MSH has no
// escape, so a name holding one (or a stray carriage return) could not be written back as read.
bool HoldsUnwritableText(absl::string_view text) {
  return text.find_first_of("\"\r") != absl::string_view::npos;
}

std::optional<std::int64_t> ParseInt(absl::string_view token) {
  return ParseIntegerToken(token, VtkDataType::kInt64);
}

VtkAttribute MakeAttribute(DataArray array) {
  // 3 and 9 components are Gmsh's vectors and tensors; VTK's SCALARS take at most 4.
  VtkAttributeKind kind = VtkAttributeKind::kField;
  if (array.components == 1) kind = VtkAttributeKind::kScalars;
  if (array.components == 3) kind = VtkAttributeKind::kVectors;
  if (array.components == 9) kind = VtkAttributeKind::kTensors;
  std::string name = array.name;
  return VtkAttribute{kind,
                      std::move(name),
                      kind == VtkAttributeKind::kScalars ? "default" : "",
                      {std::move(array)}};
}

class Parser {
 public:
  explicit Parser(absl::string_view bytes) : cursor_(bytes) {}

  absl::StatusOr<MeshDocument> Parse() {
    document_.format = FileFormat::kGmsh;
    document_.grid.points.type = VtkDataType::kDouble;
    document_.grid.points.components = 3;
    document_.gmsh.emplace();
    if (absl::Status status = ParseMeshFormat(); !status.ok()) return status;
    if (absl::Status status = ParseSections(); !status.ok()) return status;
    Finish();
    return std::move(document_);
  }

 private:
  GmshExtras& extras() { return *document_.gmsh; }
  bool is41() const { return version_major_ == 4; }

  absl::Status Error(const std::string& where, absl::string_view message) const {
    return absl::InvalidArgumentError(absl::StrCat(
        where, section_.empty() ? "" : absl::StrCat(" in $", section_), ": ", message));
  }

  // ---- Values: ASCII tokens, or binary int32 / size_t / double. `what` builds the value's
  // description only when there is an error. ----

  template <typename What>
  absl::Status EndError(const What& what) const {
    return Error(cursor_.Here(), absl::StrCat("the file ends where ", what(), " was expected"));
  }

  template <typename What>
  absl::StatusOr<std::int64_t> Int(const What& what) {
    if (cursor_.binary()) {
      const std::optional<std::int32_t> value = cursor_.TakeInt32();
      if (!value) return EndError(what);
      return *value;
    }
    return IntToken(what);
  }

  // 4.1 binary: a size_t; 2.2 binary has none.
  template <typename What>
  absl::StatusOr<std::int64_t> Size(const What& what) {
    if (cursor_.binary()) {
      const std::optional<std::uint64_t> value = cursor_.TakeSize();
      if (!value) return EndError(what);
      if (*value > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max())) {
        return Error(cursor_.Where(), absl::StrCat(what(), " is ", *value, ", which is too large"));
      }
      return static_cast<std::int64_t>(*value);
    }
    return IntToken(what);
  }

  template <typename What>
  absl::StatusOr<std::int64_t> IntToken(const What& what) {
    const std::optional<absl::string_view> token = cursor_.NextToken();
    if (!token) return EndError(what);
    const std::optional<std::int64_t> value = ParseInt(*token);
    if (!value) {
      return Error(cursor_.Where(),
                   absl::StrCat("expected ", what(), " (an integer), found ", Quote(*token)));
    }
    return *value;
  }

  template <typename What>
  absl::StatusOr<double> Real(const What& what) {
    if (cursor_.binary()) {
      const std::optional<double> value = cursor_.TakeDouble();
      if (!value) return EndError(what);
      return *value;
    }
    const std::optional<absl::string_view> token = cursor_.NextToken();
    if (!token) return EndError(what);
    const std::optional<double> value = ParseRealToken(*token);
    if (!value) {
      return Error(cursor_.Where(),
                   absl::StrCat("expected ", what(), " (a number), found ", Quote(*token)));
    }
    return *value;
  }

  // A line holding one integer: the counts of 2.2 sections and of data-section tags, which Gmsh
  // writes as text even in binary files.
  template <typename What>
  absl::StatusOr<std::int64_t> LineInt(const What& what) {
    if (!cursor_.binary()) return IntToken(what);
    const std::optional<absl::string_view> line = cursor_.ReadNonBlankLine();
    if (!line) return EndError(what);
    const std::optional<std::int64_t> value = ParseInt(*line);
    if (!value) {
      return Error(cursor_.Where(),
                   absl::StrCat("expected ", what(), " (an integer), found ", Quote(*line)));
    }
    return *value;
  }

  // Refuses a declared count that the rest of the input cannot hold at `min_bytes` each, so
  // nothing is reserved for it.
  // `where`: the count's place, by default the last value read.
  absl::Status CheckCount(std::int64_t count, std::int64_t min_bytes, absl::string_view what,
                          std::optional<std::string> where = std::nullopt) {
    const auto remaining = static_cast<std::int64_t>(cursor_.remaining());
    if (!where) where = cursor_.Where();
    if (count < 0) return Error(*where, absl::StrCat("negative ", what, " count ", count));
    if (count > remaining / min_bytes) {
      return Error(*where, absl::StrCat("declares ", count, " ", what, ", but the ", remaining,
                                        " bytes left in the file cannot hold them"));
    }
    return absl::OkStatus();
  }

  absl::Status ExpectEnd() {
    const std::string end = absl::StrCat("$End", section_);
    const std::optional<absl::string_view> line = cursor_.ReadNonBlankLine();
    if (!line) return Error(cursor_.Here(), absl::StrCat("the file ends before '", end, "'"));
    if (*line != end) {
      return Error(cursor_.Where(),
                   absl::StrCat("expected '", end, "' after the declared number of entries, found ",
                                Quote(*line)));
    }
    return absl::OkStatus();
  }

  // ---- $MeshFormat ----

  absl::Status ParseMeshFormat() {
    const std::optional<absl::string_view> first = cursor_.ReadNonBlankLine();
    if (!first) return Error("line 1", "the file is empty; expected '$MeshFormat'");
    if (*first != "$MeshFormat") {
      if (absl::StartsWith(*first, "$NOD")) {
        return Error(cursor_.Where(), "this is an MSH 1 file ($NOD); getme reads MSH 2.2 and 4.1");
      }
      return Error(cursor_.Where(), absl::StrCat("expected '$MeshFormat', found ", Quote(*first),
                                                 "; this is not a Gmsh MSH file"));
    }
    section_ = "MeshFormat";
    extras().section_order.push_back(section_);
    const std::optional<absl::string_view> line = cursor_.ReadNonBlankLine();
    if (!line) return Error(cursor_.Here(), "the file ends before the version line");
    const std::vector<absl::string_view> words =
        absl::StrSplit(*line, absl::ByAnyChar(" \t"), absl::SkipEmpty());
    std::int64_t file_type = -1;
    std::int64_t data_size = -1;
    if (words.size() != 3 || !ParseInt(words[1]) || !ParseInt(words[2])) {
      return Error(cursor_.Where(),
                   absl::StrCat("expected 'version file-type data-size' (e.g. '4.1 0 8'), found ",
                                Quote(*line)));
    }
    file_type = *ParseInt(words[1]);
    data_size = *ParseInt(words[2]);
    const absl::string_view version = words[0];
    if (version == "2" || version == "2.0" || version == "2.1" || version == "2.2") {
      version_major_ = 2;
    } else if (version == "4.1") {
      version_major_ = 4;
    } else if (version == "4" || version == "4.0") {
      return Error(cursor_.Where(),
                   "MSH 4.0 is not supported (its layout differs from 4.1); getme reads MSH 2.2 "
                   "and 4.1 (gmsh -save -format msh41 converts)");
    } else {
      return Error(cursor_.Where(), absl::StrCat("unsupported MSH version ", Quote(version),
                                                 "; getme reads 2.2 and 4.1"));
    }
    if (file_type != 0 && file_type != 1) {
      return Error(cursor_.Where(),
                   absl::StrCat("file-type must be 0 (ASCII) or 1 (binary), found ", file_type));
    }
    // 2.2: data-size is sizeof(double); 4.1: sizeof(size_t) of the writing machine.
    if ((version_major_ == 2 && data_size != 8) ||
        (version_major_ == 4 && data_size != 4 && data_size != 8)) {
      return Error(cursor_.Where(),
                   absl::StrCat("data-size ", data_size, " is not supported; MSH ",
                                version_major_ == 2 ? "2.2 needs 8 (sizeof(double))"
                                                    : "4.1 needs 4 or 8 (sizeof(size_t))"));
    }
    extras().version_major = version_major_;
    extras().binary = file_type == 1;
    extras().data_size = static_cast<int>(data_size);
    document_.as_read.gmsh_version = is41() ? GmshVersion::k41 : GmshVersion::k22;
    document_.as_read.encoding = file_type == 1 ? Encoding::kBinary : Encoding::kAscii;
    document_.grid.encoding = document_.as_read.encoding;

    if (file_type == 1) {
      // The integer 1 in the writer's byte order, right after the version line. From here on
      // places are byte offsets.
      cursor_.SetBinary(false, static_cast<int>(data_size));
      const std::optional<absl::string_view> one = cursor_.Take(4);
      if (!one) {
        return Error(cursor_.Here(), "the file ends before the endianness check (the integer 1)");
      }
      const auto byte = [&](int i) { return static_cast<unsigned char>((*one)[i]); };
      const bool little = byte(0) == 1 && byte(1) == 0 && byte(2) == 0 && byte(3) == 0;
      const bool big = byte(0) == 0 && byte(1) == 0 && byte(2) == 0 && byte(3) == 1;
      if (!little && !big) {
        return Error(
            cursor_.Where(),
            absl::StrCat("the endianness check must be the integer 1 (bytes 01 00 00 00, "
                         "or 00 00 00 01 from a big-endian machine), found bytes ",
                         Hex(byte(0)), " ", Hex(byte(1)), " ", Hex(byte(2)), " ", Hex(byte(3))));
      }
      extras().big_endian = big;
      cursor_.SetBinary(big, static_cast<int>(data_size));
    }
    return ExpectEnd();
  }

  static std::string Hex(unsigned char value) {
    constexpr char kDigits[] = "0123456789abcdef";
    return {kDigits[value >> 4], kDigits[value & 15]};
  }

  // ---- The section loop ----

  absl::Status ParseSections() {
    for (;;) {
      section_.clear();
      const std::optional<absl::string_view> line = cursor_.ReadNonBlankLine();
      if (!line) return absl::OkStatus();
      if (line->empty() || line->front() != '$' || line->size() == 1) {
        return Error(cursor_.Where(),
                     absl::StrCat("expected a section header '$Name', found ", Quote(*line)));
      }
      const absl::string_view name = line->substr(1);
      if (absl::StartsWith(name, "End")) {
        return Error(cursor_.Where(),
                     absl::StrCat("'", *line, "' without a matching '$", name.substr(3), "'"));
      }
      section_ = std::string(name);
      section_where_ = cursor_.Where();
      extras().section_order.push_back(section_);
      absl::Status status;
      if (name == "MeshFormat") {
        status = Error(cursor_.Where(), "a second $MeshFormat section");
      } else if (name == "PhysicalNames") {
        status = ParsePhysicalNames();
      } else if (name == "Entities" && is41()) {
        status = ParseEntities();
      } else if (name == "Nodes") {
        status = is41() ? ParseNodes41() : ParseNodes22();
      } else if (name == "Elements") {
        status = is41() ? ParseElements41() : ParseElements22();
      } else if (name == "NodeData" || name == "ElementData") {
        status = ParseDataView(name == "NodeData", /*element_nodes=*/false);
      } else if (name == "ElementNodeData") {
        // A cell array as getme's 2.2 writer stores it (one value per element, repeated at its
        // nodes) becomes that array again; any other $ElementNodeData is kept verbatim.
        const GmshCursor section_start = cursor_;
        status = ParseDataView(/*on_nodes=*/false, /*element_nodes=*/true);
        if (status.ok()) {
          extras().section_order.back() = "ElementData";
        } else {
          cursor_ = section_start;
          status = ParseRaw();
        }
      } else {
        status = ParseRaw();
      }
      if (!status.ok()) return status;
    }
  }

  absl::Status ParseRaw() {
    const std::string where = cursor_.Where();
    const std::optional<absl::string_view> body = cursor_.TakeUntilEnd(section_);
    if (!body) {
      return Error(where, absl::StrCat("no '$End", section_, "' closes the section"));
    }
    extras().raw_sections.push_back(GmshRawSection{section_, std::string(*body)});
    return absl::OkStatus();
  }

  // ---- $PhysicalNames: text in both encodings ----

  absl::Status ParsePhysicalNames() {
    if (seen_physical_names_) return Error(section_where_, "a second $PhysicalNames section");
    seen_physical_names_ = true;
    absl::StatusOr<std::int64_t> count = LineInt([] { return "the number of physical names"; });
    if (!count.ok()) return count.status();
    if (absl::Status status = CheckCount(*count, 6, "physical names"); !status.ok()) return status;
    if (!cursor_.binary()) {
      // The count was read as a token: the rest of its line is empty.
      cursor_.ReadLine();
    }
    extras().physical_names.reserve(*count);
    for (std::int64_t i = 0; i < *count; ++i) {
      const std::optional<absl::string_view> line = cursor_.ReadNonBlankLine();
      if (!line) {
        return Error(cursor_.Here(),
                     absl::StrCat("the file ends at physical name ", i + 1, " of ", *count));
      }
      // dim tag "name" — the name may hold spaces.
      const std::size_t open = line->find('"');
      const std::size_t close = line->rfind('"');
      const std::vector<absl::string_view> numbers =
          absl::StrSplit(line->substr(0, open), absl::ByAnyChar(" \t"), absl::SkipEmpty());
      std::optional<std::int64_t> dim;
      std::optional<std::int64_t> tag;
      if (numbers.size() == 2) {
        dim = ParseInt(numbers[0]);
        tag = ParseInt(numbers[1]);
      }
      if (open == absl::string_view::npos || close == open || !dim || !tag || *dim < 0 ||
          *dim > 3 || *tag < std::numeric_limits<int>::min() ||
          *tag > std::numeric_limits<int>::max()) {
        return Error(cursor_.Where(),
                     absl::StrCat("physical name ", i + 1, " of ", *count,
                                  ": expected 'dim tag \"name\"' (dim 0-3), found ", Quote(*line)));
      }
      const absl::string_view name = line->substr(open + 1, close - open - 1);
      if (HoldsUnwritableText(name)) {
        return Error(cursor_.Where(), absl::StrCat("physical name ", i + 1, " of ", *count,
                                                   ": the name holds a '\"' or a carriage "
                                                   "return, found ",
                                                   Quote(*line)));
      }
      extras().physical_names.push_back(
          GmshPhysicalName{static_cast<int>(*dim), static_cast<int>(*tag), std::string(name)});
    }
    return ExpectEnd();
  }

  // ---- $Entities (4.1) ----

  absl::StatusOr<int> IntTag(std::int64_t value, absl::string_view what) {
    if (value < std::numeric_limits<int>::min() || value > std::numeric_limits<int>::max()) {
      return Error(cursor_.Where(), absl::StrCat(what, " ", value, " is outside the int range"));
    }
    return static_cast<int>(value);
  }

  struct SectionHeader41 {
    std::int64_t blocks = 0;
    std::int64_t count = 0;
  };

  // The four numbers that open a 4.1 $Nodes or $Elements section (`kind` "node" or "element"):
  // entity blocks, entries, minimum and maximum tag (read past: tags are checked one by one).
  // The counts are checked against the bytes left, at least 8 per block and `entry_bytes` per
  // entry, before anything is reserved.
  absl::StatusOr<SectionHeader41> ReadSectionHeader41(absl::string_view kind,
                                                      std::int64_t entry_bytes) {
    const std::string names[4] = {
        "the number of entity blocks", absl::StrCat("the number of ", kind, "s"),
        absl::StrCat("the minimum ", kind, " tag"), absl::StrCat("the maximum ", kind, " tag")};
    std::int64_t values[4];
    std::string where[4];
    for (int k = 0; k < 4; ++k) {
      absl::StatusOr<std::int64_t> value = Size([&] { return names[k]; });
      if (!value.ok()) return value.status();
      values[k] = *value;
      where[k] = cursor_.Where();
    }
    if (absl::Status status = CheckCount(values[0], 8, absl::StrCat(kind, " blocks"), where[0]);
        !status.ok()) {
      return status;
    }
    if (absl::Status status = CheckCount(values[1], entry_bytes, absl::StrCat(kind, "s"), where[1]);
        !status.ok()) {
      return status;
    }
    return SectionHeader41{values[0], values[1]};
  }

  // The entity (dimension, tag) that opens block `b` of `blocks` of a 4.1 $Nodes or $Elements
  // section; `kind` is "node" or "element".
  absl::StatusOr<GmshDimTag> BlockEntity(absl::string_view kind, std::int64_t b,
                                         std::int64_t blocks) {
    const auto what = [&](absl::string_view field) {
      return [&, field] {
        return absl::StrCat(field, " of ", kind, " block ", b + 1, " of ", blocks);
      };
    };
    absl::StatusOr<std::int64_t> dim = Int(what("the entity dimension"));
    if (!dim.ok()) return dim.status();
    if (*dim < 0 || *dim > 3) {
      return Error(cursor_.Where(), absl::StrCat(kind, " block ", b + 1, ": entity dimension ",
                                                 *dim, " is not 0-3"));
    }
    absl::StatusOr<std::int64_t> tag = Int(what("the entity tag"));
    if (!tag.ok()) return tag.status();
    absl::StatusOr<int> int_tag = IntTag(*tag, "entity tag");
    if (!int_tag.ok()) return int_tag.status();
    return GmshDimTag{static_cast<int>(*dim), *int_tag};
  }

  absl::Status ParseEntities() {
    if (extras().has_entities) return Error(section_where_, "a second $Entities section");
    extras().has_entities = true;
    static constexpr absl::string_view kKinds[] = {"points", "curves", "surfaces", "volumes"};
    std::int64_t counts[4];
    for (int dim = 0; dim < 4; ++dim) {
      absl::StatusOr<std::int64_t> count =
          Size([&] { return absl::StrCat("the number of ", kKinds[dim]); });
      if (!count.ok()) return count.status();
      if (absl::Status status = CheckCount(*count, 8, kKinds[dim]); !status.ok()) return status;
      counts[dim] = *count;
    }
    for (int dim = 0; dim < 4; ++dim) {
      for (std::int64_t i = 0; i < counts[dim]; ++i) {
        GmshEntity entity;
        entity.dim = dim;
        const auto what = [&](absl::string_view field) {
          return [&, field] {
            return absl::StrCat(field, " of entity ", i + 1, " of ", counts[dim], " ", kKinds[dim]);
          };
        };
        absl::StatusOr<std::int64_t> tag = Int(what("the tag"));
        if (!tag.ok()) return tag.status();
        absl::StatusOr<int> int_tag = IntTag(*tag, "entity tag");
        if (!int_tag.ok()) return int_tag.status();
        entity.tag = *int_tag;
        for (int k = 0; k < (dim == 0 ? 3 : 6); ++k) {
          absl::StatusOr<double> value =
              Real(what(dim == 0 ? "a coordinate" : "a bounding-box value"));
          if (!value.ok()) return value.status();
          (k < 3 ? entity.min[k] : entity.max[k - 3]) = *value;
        }
        if (dim == 0) entity.max = entity.min;
        for (int list = 0; list < (dim == 0 ? 1 : 2); ++list) {
          absl::StatusOr<std::int64_t> n = Size(
              what(list == 0 ? "the number of physical tags" : "the number of boundary entities"));
          if (!n.ok()) return n.status();
          if (absl::Status status =
                  CheckCount(*n, 2, list == 0 ? "physical tags" : "boundary entities");
              !status.ok()) {
            return status;
          }
          std::vector<int>& values = list == 0 ? entity.physical_tags : entity.boundary_tags;
          values.reserve(*n);
          for (std::int64_t k = 0; k < *n; ++k) {
            absl::StatusOr<std::int64_t> value =
                Int(what(list == 0 ? "a physical tag" : "a boundary entity tag"));
            if (!value.ok()) return value.status();
            absl::StatusOr<int> int_value = IntTag(*value, "tag");
            if (!int_value.ok()) return int_value.status();
            values.push_back(*int_value);
          }
        }
        entity_physical_.try_emplace(std::pair(entity.dim, entity.tag),
                                     entity.physical_tags.empty() ? 0 : entity.physical_tags[0]);
        extras().entities.push_back(std::move(entity));
      }
    }
    return ExpectEnd();
  }

  // ---- $Nodes ----

  absl::Status BeginNodes(std::int64_t count) {
    if (seen_nodes_) return Error(section_where_, "a second $Nodes section");
    seen_nodes_ = true;
    extras().node_tags.reserve(count);
    document_.grid.points.reals.reserve(3 * count);
    node_index_.emplace(count);
    return absl::OkStatus();
  }

  absl::Status AddNodeTag(std::int64_t tag, std::int64_t i, std::int64_t count) {
    if (tag <= 0) {
      return Error(cursor_.Where(), absl::StrCat("node ", i + 1, " of ", count, ": node tag ", tag,
                                                 " is not positive"));
    }
    const auto index = static_cast<std::int64_t>(extras().node_tags.size());
    if (!node_index_->Insert(tag, index)) {
      return Error(cursor_.Where(),
                   absl::StrCat("node ", i + 1, " of ", count, ": node tag ", tag,
                                " appears twice (first as node ", node_index_->Find(tag) + 1, ")"));
    }
    extras().node_tags.push_back(tag);
    return absl::OkStatus();
  }

  absl::Status ReadCoordinates(std::int64_t i, std::int64_t count, int parametric,
                               GmshNodeBlock* block) {
    static constexpr absl::string_view kAxes[] = {"x", "y", "z", "u", "v", "w"};
    for (int k = 0; k < 3 + parametric; ++k) {
      absl::StatusOr<double> value = Real([&] {
        return absl::StrCat("the ", kAxes[k], " coordinate of node ", i + 1, " of ", count);
      });
      if (!value.ok()) return value.status();
      if (k < 3) {
        document_.grid.points.reals.push_back(*value);
      } else {
        block->parametric_coords.push_back(*value);
      }
    }
    return absl::OkStatus();
  }

  absl::Status ParseNodes22() {
    absl::StatusOr<std::int64_t> count = LineInt([] { return "the number of nodes"; });
    if (!count.ok()) return count.status();
    // Binary: an int tag and three doubles; ASCII: at least "1 0 0 0\n".
    if (absl::Status status = CheckCount(*count, cursor_.binary() ? 28 : 8, "nodes");
        !status.ok()) {
      return status;
    }
    if (absl::Status status = BeginNodes(*count); !status.ok()) return status;
    for (std::int64_t i = 0; i < *count; ++i) {
      absl::StatusOr<std::int64_t> tag =
          Int([&] { return absl::StrCat("the tag of node ", i + 1, " of ", *count); });
      if (!tag.ok()) return tag.status();
      if (absl::Status status = AddNodeTag(*tag, i, *count); !status.ok()) return status;
      if (absl::Status status = ReadCoordinates(i, *count, 0, nullptr); !status.ok()) {
        return status;
      }
    }
    return ExpectEnd();
  }

  absl::Status ParseNodes41() {
    absl::StatusOr<SectionHeader41> header =
        ReadSectionHeader41("node", cursor_.binary() ? 24 + cursor_.size_t_size() : 8);
    if (!header.ok()) return header.status();
    const std::int64_t blocks = header->blocks;
    const std::int64_t count = header->count;
    if (absl::Status status = BeginNodes(count); !status.ok()) return status;
    extras().node_blocks.reserve(blocks);
    std::int64_t read = 0;
    for (std::int64_t b = 0; b < blocks; ++b) {
      GmshNodeBlock block;
      const auto what = [&](absl::string_view field) {
        return [&, field] { return absl::StrCat(field, " of node block ", b + 1, " of ", blocks); };
      };
      absl::StatusOr<GmshDimTag> entity = BlockEntity("node", b, blocks);
      if (!entity.ok()) return entity.status();
      absl::StatusOr<std::int64_t> parametric = Int(what("the parametric flag"));
      if (!parametric.ok()) return parametric.status();
      if (*parametric != 0 && *parametric != 1) {
        return Error(
            cursor_.Where(),
            absl::StrCat("node block ", b + 1, ": parametric must be 0 or 1, found ", *parametric));
      }
      absl::StatusOr<std::int64_t> n = Size(what("the number of nodes"));
      if (!n.ok()) return n.status();
      if (*n < 0 || *n > count - read) {
        return Error(cursor_.Where(),
                     absl::StrCat("node block ", b + 1, " declares ", *n,
                                  " nodes, but the header's ", count, " leave ", count - read));
      }
      block.dim = entity->dim;
      block.tag = entity->tag;
      block.parametric = *parametric == 1;
      block.count = *n;
      const int parametric_count = block.parametric ? block.dim : 0;
      for (std::int64_t i = 0; i < *n; ++i) {
        absl::StatusOr<std::int64_t> node_tag = Size(
            [&] { return absl::StrCat("node tag ", i + 1, " of ", *n, " of node block ", b + 1); });
        if (!node_tag.ok()) return node_tag.status();
        if (absl::Status status = AddNodeTag(*node_tag, read + i, count); !status.ok()) {
          return status;
        }
      }
      block.parametric_coords.reserve(*n * parametric_count);
      for (std::int64_t i = 0; i < *n; ++i) {
        if (absl::Status status = ReadCoordinates(read + i, count, parametric_count, &block);
            !status.ok()) {
          return status;
        }
      }
      read += *n;
      extras().node_blocks.push_back(std::move(block));
    }
    if (read != count) {
      return Error(cursor_.Where(), absl::StrCat("the header declares ", count,
                                                 " nodes, but the blocks hold ", read));
    }
    return ExpectEnd();
  }

  // ---- $Elements ----

  absl::Status BeginElements(std::int64_t count) {
    if (seen_elements_) return Error(section_where_, "a second $Elements section");
    seen_elements_ = true;
    if (!seen_nodes_) {
      return Error(section_where_, "$Elements comes before $Nodes; elements refer to node tags");
    }
    GridCells& cells = document_.grid.cells;
    cells.types.reserve(count);
    cells.offsets.reserve(count + 1);
    extras().element_tags.reserve(count);
    element_index_.emplace(count);
    return absl::OkStatus();
  }

  // The element's type, refused unless it is a linear type getme reads.
  absl::StatusOr<GmshElementTypeInfo> ElementType(std::int64_t type, std::int64_t element_tag,
                                                  const std::string& where) {
    const std::optional<GmshElementTypeInfo> info =
        type >= 0 && type <= 1000 ? GmshElementType(static_cast<int>(type)) : std::nullopt;
    if (!info) {
      return Error(where,
                   absl::StrCat("element ", element_tag, ": unknown Gmsh element type ", type));
    }
    if (info->vtk_code == 0) {
      return Error(where, absl::StrCat("element ", element_tag, ": Gmsh element type ", type, " (",
                                       info->name,
                                       ") is not supported; getme reads linear elements (types "
                                       "1-7 and 15)"));
    }
    return *info;
  }

  absl::Status AddElementTag(std::int64_t tag) {
    if (tag <= 0) {
      return Error(cursor_.Where(), absl::StrCat("element tag ", tag, " is not positive"));
    }
    const auto index = static_cast<std::int64_t>(extras().element_tags.size());
    if (!element_index_->Insert(tag, index)) {
      return Error(cursor_.Where(),
                   absl::StrCat("element tag ", tag, " appears twice (first as element ",
                                element_index_->Find(tag) + 1, " of $Elements)"));
    }
    extras().element_tags.push_back(tag);
    return absl::OkStatus();
  }

  // Reads the element's node tags and appends the cell in VTK's node order.
  absl::Status ReadElementNodes(std::int64_t element_tag, const GmshElementTypeInfo& info,
                                bool size_t_tags) {
    std::int64_t nodes[8];
    for (int k = 0; k < info.node_count; ++k) {
      const auto what = [&] {
        return absl::StrCat("node ", k + 1, " of ", info.node_count, " of element ", element_tag,
                            " (", info.name, ")");
      };
      absl::StatusOr<std::int64_t> node_tag = size_t_tags ? Size(what) : Int(what);
      if (!node_tag.ok()) return node_tag.status();
      nodes[k] = node_index_->Find(*node_tag);
      if (nodes[k] < 0) {
        return Error(cursor_.Where(), absl::StrCat("element ", element_tag, ": node tag ",
                                                   *node_tag, " is not in $Nodes"));
      }
    }
    GridCells& cells = document_.grid.cells;
    for (int k = 0; k < info.node_count; ++k) {
      cells.connectivity.push_back(nodes[GmshNodeOfVtkNode(info.code, k)]);
    }
    cells.types.push_back(static_cast<std::uint8_t>(info.vtk_code));
    cells.offsets.push_back(static_cast<std::int64_t>(cells.connectivity.size()));
    return absl::OkStatus();
  }

  absl::Status ReadTagList(std::int64_t element_tag, std::int64_t tag_count) {
    GmshTagLists& lists = extras().element_tag_lists;
    for (std::int64_t k = 0; k < tag_count; ++k) {
      absl::StatusOr<std::int64_t> value = Int([&] {
        return absl::StrCat("tag ", k + 1, " of ", tag_count, " of element ", element_tag);
      });
      if (!value.ok()) return value.status();
      absl::StatusOr<int> int_value = IntTag(*value, "tag");
      if (!int_value.ok()) return int_value.status();
      lists.values.push_back(*int_value);
    }
    lists.offsets.push_back(static_cast<std::int64_t>(lists.values.size()));
    return absl::OkStatus();
  }

  absl::Status ParseElements22() {
    absl::StatusOr<std::int64_t> count = LineInt([] { return "the number of elements"; });
    if (!count.ok()) return count.status();
    // Binary: at least an int tag and one node; ASCII: at least "1 15 0 1\n".
    if (absl::Status status = CheckCount(*count, 8, "elements"); !status.ok()) return status;
    if (absl::Status status = BeginElements(*count); !status.ok()) return status;
    extras().element_tag_lists.offsets.reserve(*count + 1);
    if (!cursor_.binary()) {
      for (std::int64_t i = 0; i < *count; ++i) {
        const auto what = [&](absl::string_view field) {
          return [&, field] { return absl::StrCat(field, " of element ", i + 1, " of ", *count); };
        };
        absl::StatusOr<std::int64_t> tag = Int(what("the tag"));
        if (!tag.ok()) return tag.status();
        const std::string where = cursor_.Where();
        if (absl::Status status = AddElementTag(*tag); !status.ok()) return status;
        absl::StatusOr<std::int64_t> type = Int(what("the type"));
        if (!type.ok()) return type.status();
        absl::StatusOr<GmshElementTypeInfo> info = ElementType(*type, *tag, where);
        if (!info.ok()) return info.status();
        absl::StatusOr<std::int64_t> tag_count = Int(what("the number of tags"));
        if (!tag_count.ok()) return tag_count.status();
        if (absl::Status status = CheckCount(*tag_count, 2, "tags"); !status.ok()) return status;
        if (absl::Status status = ReadTagList(*tag, *tag_count); !status.ok()) return status;
        if (absl::Status status = ReadElementNodes(*tag, *info, false); !status.ok()) return status;
      }
      return ExpectEnd();
    }
    // Binary: blocks of "type, elements following, tags per element" headers.
    std::int64_t read = 0;
    while (read < *count) {
      std::int64_t header[3];
      static constexpr absl::string_view kHeader[] = {
          "the element type", "the number of elements following", "the number of tags"};
      for (int k = 0; k < 3; ++k) {
        absl::StatusOr<std::int64_t> value = Int([&] {
          return absl::StrCat(kHeader[k], " of the block header after element ", read, " of ",
                              *count);
        });
        if (!value.ok()) return value.status();
        header[k] = *value;
      }
      const std::string where = cursor_.Where();
      if (header[1] < 1 || header[1] > *count - read) {
        return Error(where, absl::StrCat("a block header declares ", header[1], " elements, but ",
                                         *count - read, " of the ", *count, " remain"));
      }
      if (absl::Status status = CheckCount(header[2], 4, "tags"); !status.ok()) return status;
      const std::optional<GmshElementTypeInfo> known =
          header[0] >= 0 && header[0] <= 1000 ? GmshElementType(static_cast<int>(header[0]))
                                              : std::nullopt;
      if (!known || known->vtk_code == 0) {
        // Name the first element of the block.
        const std::optional<std::int32_t> first = cursor_.TakeInt32();
        absl::StatusOr<GmshElementTypeInfo> info =
            ElementType(header[0], first ? *first : 0, where);
        return info.status();
      }
      const GmshElementTypeInfo info = *known;
      if (absl::Status status =
              CheckCount(header[1], 4 * (1 + header[2] + info.node_count), "elements");
          !status.ok()) {
        return status;
      }
      for (std::int64_t i = 0; i < header[1]; ++i, ++read) {
        absl::StatusOr<std::int64_t> tag =
            Int([&] { return absl::StrCat("the tag of element ", read + 1, " of ", *count); });
        if (!tag.ok()) return tag.status();
        if (absl::Status status = AddElementTag(*tag); !status.ok()) return status;
        if (absl::Status status = ReadTagList(*tag, header[2]); !status.ok()) return status;
        if (absl::Status status = ReadElementNodes(*tag, info, false); !status.ok()) return status;
      }
    }
    return ExpectEnd();
  }

  absl::Status ParseElements41() {
    absl::StatusOr<SectionHeader41> header =
        ReadSectionHeader41("element", cursor_.binary() ? 2 * cursor_.size_t_size() : 4);
    if (!header.ok()) return header.status();
    const std::int64_t blocks = header->blocks;
    const std::int64_t count = header->count;
    if (absl::Status status = BeginElements(count); !status.ok()) return status;
    extras().element_entities.reserve(count);
    std::int64_t read = 0;
    for (std::int64_t b = 0; b < blocks; ++b) {
      const auto what = [&](absl::string_view field) {
        return
            [&, field] { return absl::StrCat(field, " of element block ", b + 1, " of ", blocks); };
      };
      absl::StatusOr<GmshDimTag> entity = BlockEntity("element", b, blocks);
      if (!entity.ok()) return entity.status();
      absl::StatusOr<std::int64_t> type = Int(what("the element type"));
      if (!type.ok()) return type.status();
      const std::string type_where = cursor_.Where();
      absl::StatusOr<std::int64_t> n = Size(what("the number of elements"));
      if (!n.ok()) return n.status();
      if (*n < 0 || *n > count - read) {
        return Error(cursor_.Where(),
                     absl::StrCat("element block ", b + 1, " declares ", *n,
                                  " elements, but the header's ", count, " leave ", count - read));
      }
      if (*n == 0) continue;
      const std::optional<GmshElementTypeInfo> known =
          *type >= 0 && *type <= 1000 ? GmshElementType(static_cast<int>(*type)) : std::nullopt;
      if (!known || known->vtk_code == 0) {
        absl::StatusOr<std::int64_t> first = Size(what("the first element tag"));
        absl::StatusOr<GmshElementTypeInfo> info =
            ElementType(*type, first.ok() ? *first : 0, type_where);
        return info.status();
      }
      const GmshElementTypeInfo info = *known;
      const std::int64_t min_bytes = cursor_.binary()
                                         ? cursor_.size_t_size() * (1 + info.node_count)
                                         : 2 * (1 + info.node_count);
      if (absl::Status status = CheckCount(*n, min_bytes, "elements"); !status.ok()) return status;
      for (std::int64_t i = 0; i < *n; ++i, ++read) {
        absl::StatusOr<std::int64_t> element_tag = Size([&] {
          return absl::StrCat("the tag of element ", i + 1, " of element block ", b + 1);
        });
        if (!element_tag.ok()) return element_tag.status();
        if (absl::Status status = AddElementTag(*element_tag); !status.ok()) return status;
        if (absl::Status status = ReadElementNodes(*element_tag, info, true); !status.ok()) {
          return status;
        }
        extras().element_entities.push_back(*entity);
      }
    }
    if (read != count) {
      return Error(cursor_.Where(), absl::StrCat("the header declares ", count,
                                                 " elements, but the blocks hold ", read));
    }
    return ExpectEnd();
  }

  // ---- $NodeData / $ElementData ----

  // `element_nodes`: an $ElementNodeData section, accepted only if every entry has the same
  // values at each node of its element (anything else is an error here, and the caller keeps the
  // section verbatim instead).
  absl::Status ParseDataView(bool on_nodes, bool element_nodes) {
    const absl::string_view targets = on_nodes ? "$Nodes" : "$Elements";
    if (!(on_nodes ? seen_nodes_ : seen_elements_)) {
      return Error(section_where_,
                   absl::StrCat("comes before ", targets, ", whose tags its entries refer to"));
    }
    GmshDataView view;
    view.on_nodes = on_nodes;
    view.element_nodes = element_nodes;
    // The three tag lists are text, one value a line, in both encodings.
    for (int list = 0; list < 3; ++list) {
      static constexpr absl::string_view kLists[] = {"string", "real", "integer"};
      const std::optional<absl::string_view> line = cursor_.ReadNonBlankLine();
      const std::optional<std::int64_t> n = line ? ParseInt(*line) : std::nullopt;
      if (!line) {
        return Error(cursor_.Here(),
                     absl::StrCat("the file ends before the number of ", kLists[list], " tags"));
      }
      if (!n || *n < 0) {
        return Error(cursor_.Where(), absl::StrCat("expected the number of ", kLists[list],
                                                   " tags, found ", Quote(*line)));
      }
      if (absl::Status status = CheckCount(*n, 2, absl::StrCat(kLists[list], " tags"));
          !status.ok()) {
        return status;
      }
      for (std::int64_t k = 0; k < *n; ++k) {
        const std::optional<absl::string_view> value = cursor_.ReadNonBlankLine();
        if (!value) {
          return Error(cursor_.Here(),
                       absl::StrCat("the file ends at ", kLists[list], " tag ", k + 1, " of ", *n));
        }
        if (list == 0) {
          absl::string_view text = *value;
          if (text.size() >= 2 && text.front() == '"' && text.back() == '"') {
            text = text.substr(1, text.size() - 2);
          }
          if (HoldsUnwritableText(text)) {
            return Error(cursor_.Where(),
                         absl::StrCat("string tag ", k + 1, " of ", *n,
                                      ": the text holds a '\"' or a carriage return, found ",
                                      Quote(*value)));
          }
          view.string_tags.emplace_back(text);
        } else if (list == 1) {
          const std::optional<double> real = ParseRealToken(*value);
          if (!real) {
            return Error(cursor_.Where(),
                         absl::StrCat("real tag ", k + 1, " of ", *n, ": expected a number, found ",
                                      Quote(*value)));
          }
          view.real_tags.push_back(*real);
        } else {
          const std::optional<std::int64_t> integer = ParseInt(*value);
          if (!integer) {
            return Error(cursor_.Where(),
                         absl::StrCat("integer tag ", k + 1, " of ", *n,
                                      ": expected an integer, found ", Quote(*value)));
          }
          view.integer_tags.push_back(*integer);
        }
      }
    }
    // Integer tags: time step, number of components, number of entries[, partition].
    if (view.integer_tags.size() < 3) {
      return Error(cursor_.Where(),
                   absl::StrCat("expected at least 3 integer tags (time step, components, "
                                "entries), found ",
                                view.integer_tags.size()));
    }
    const std::int64_t components = view.integer_tags[1];
    const std::int64_t entries = view.integer_tags[2];
    const std::int64_t targets_count =
        on_nodes ? document_.grid.point_count() : document_.grid.cells.size();
    if (components < 1 || components > 1024) {
      return Error(cursor_.Where(),
                   absl::StrCat("the number of components must be 1-1024, found ", components));
    }
    if (absl::Status status = CheckCount(
            entries, cursor_.binary() ? 4 + 8 * components : 2 * (1 + components), "entries");
        !status.ok()) {
      return status;
    }
    // The array covers every point / cell whatever the section lists: keep a few listed
    // entries of many components from asking for far more memory than the input holds.
    if (targets_count * components > static_cast<std::int64_t>(cursor_.size()) + 1024) {
      return Error(cursor_.Where(), absl::StrCat(components, " components for each of the ",
                                                 targets_count, on_nodes ? " nodes" : " elements",
                                                 " exceed what a file of this size can carry"));
    }
    const std::string base_name = view.string_tags.empty()
                                      ? std::string(on_nodes ? "node data" : "element data")
                                      : view.string_tags.front();
    DataArray array;
    array.name = UniqueName(base_name, view.integer_tags[0], on_nodes);
    array.type = VtkDataType::kDouble;
    array.components = static_cast<int>(components);
    // Unlisted entries: NaN says "no value"; for "fixed" 0 says "not fixed", as its meaning is
    // defined by the grid (grid_mesh.h), where NaN would count as nonzero.
    const double missing = base_name == "fixed" ? 0.0 : std::numeric_limits<double>::quiet_NaN();
    array.reals.assign(targets_count * components, missing);
    view.listed.reserve(entries);
    const GmshTagIndex& index = on_nodes ? *node_index_ : *element_index_;
    bool in_order = entries == targets_count;
    for (std::int64_t i = 0; i < entries; ++i) {
      absl::StatusOr<std::int64_t> tag = Int([&] {
        return absl::StrCat("the ", on_nodes ? "node" : "element", " tag of entry ", i + 1, " of ",
                            entries);
      });
      if (!tag.ok()) return tag.status();
      const std::int64_t target = index.Find(*tag);
      if (target < 0) {
        return Error(cursor_.Where(), absl::StrCat("entry ", i + 1, " of ", entries, ": ",
                                                   on_nodes ? "node" : "element", " tag ", *tag,
                                                   " is not in ", targets));
      }
      in_order = in_order && target == i;
      view.listed.push_back(target);
      std::int64_t nodes = 1;
      if (element_nodes) {
        absl::StatusOr<std::int64_t> count =
            Int([&] { return absl::StrCat("the node count of entry ", i + 1); });
        if (!count.ok()) return count.status();
        if (*count != document_.grid.cells.node_count(target)) {
          return Error(cursor_.Where(), "not one value per element");
        }
        nodes = *count;
      }
      for (std::int64_t node = 0; node < nodes; ++node) {
        for (std::int64_t c = 0; c < components; ++c) {
          absl::StatusOr<double> value = Real([&] {
            return absl::StrCat("value ", c + 1, " of ", components, " of entry ", i + 1, " (",
                                on_nodes ? "node" : "element", " ", *tag, ")");
          });
          if (!value.ok()) return value.status();
          double& stored = array.reals[target * components + c];
          if (node == 0) {
            stored = *value;
          } else if (!(*value == stored || (std::isnan(*value) && std::isnan(stored)))) {
            return Error(cursor_.Where(), "not one value per element");
          }
        }
      }
    }
    if (in_order) view.listed.clear();
    view.array_name = array.name;
    if (absl::Status status = ExpectEnd(); !status.ok()) return status;
    (on_nodes ? document_.grid.point_data : document_.grid.cell_data)
        .push_back(MakeAttribute(std::move(array)));
    extras().data_views.push_back(std::move(view));
    return absl::OkStatus();
  }

  std::string UniqueName(const std::string& base, std::int64_t step, bool on_nodes) {
    const std::vector<VtkAttribute>& attributes =
        on_nodes ? document_.grid.point_data : document_.grid.cell_data;
    const auto taken = [&](const std::string& name) {
      return FindArray(attributes, name) != nullptr ||
             (!on_nodes && (name == "gmsh:physical" || name == "gmsh:geometrical"));
    };
    if (!taken(base)) return base;
    std::string name = absl::StrCat(base, " [step ", step, "]");
    for (int k = 2; taken(name); ++k) name = absl::StrCat(base, " [", k, "]");
    return name;
  }

  // ---- After the last section ----

  void Finish() {
    const std::int64_t cells = document_.grid.cells.size();
    if (cells == 0) return;
    DataArray physical{"gmsh:physical", VtkDataType::kInt32, 1, {}, {}};
    DataArray geometrical{"gmsh:geometrical", VtkDataType::kInt32, 1, {}, {}};
    physical.integers.reserve(cells);
    geometrical.integers.reserve(cells);
    const GmshExtras& ex = extras();
    for (std::int64_t c = 0; c < cells; ++c) {
      if (is41()) {
        const GmshDimTag entity = ex.element_entities[c];
        const auto it = entity_physical_.find(std::pair(entity.dim, entity.tag));
        physical.integers.push_back(it == entity_physical_.end() ? 0 : it->second);
        geometrical.integers.push_back(entity.tag);
      } else {
        const std::int64_t begin = ex.element_tag_lists.offsets[c];
        const std::int64_t size = ex.element_tag_lists.offsets[c + 1] - begin;
        physical.integers.push_back(size > 0 ? ex.element_tag_lists.values[begin] : 0);
        geometrical.integers.push_back(size > 1 ? ex.element_tag_lists.values[begin + 1] : 0);
      }
    }
    std::vector<VtkAttribute>& cell_data = document_.grid.cell_data;
    cell_data.insert(cell_data.begin(), MakeAttribute(std::move(geometrical)));
    cell_data.insert(cell_data.begin(), MakeAttribute(std::move(physical)));
  }

  GmshCursor cursor_;
  MeshDocument document_;
  std::string section_;
  std::string section_where_;  // the current section's header line
  int version_major_ = 4;
  bool seen_physical_names_ = false;
  bool seen_nodes_ = false;
  bool seen_elements_ = false;
  std::optional<GmshTagIndex> node_index_;
  std::optional<GmshTagIndex> element_index_;
  absl::flat_hash_map<std::pair<int, int>, int> entity_physical_;  // 4.1: first physical tag
};

}  // namespace

absl::StatusOr<MeshDocument> ParseGmsh(absl::string_view bytes) { return Parser(bytes).Parse(); }

}  // namespace getme::formats
