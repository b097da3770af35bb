#include "formats/vtk_reader.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <sstream>
#include <utility>

#include "absl/status/status.h"
#include "absl/strings/ascii.h"
#include "absl/strings/match.h"
#include "absl/strings/numbers.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_join.h"
#include "formats/file_io.h"
#include "formats/quote.h"
#include "formats/vtk_cell_type.h"
#include "formats/vtk_scanner.h"
#include "formats/vtk_values.h"

namespace getme::formats {
namespace {

constexpr absl::string_view kHeaderPrefix = "# vtk DataFile Version";
constexpr std::int64_t kMaxInt64 = std::numeric_limits<std::int64_t>::max();

// VTK writes spaces and other special characters of array names as %XX.
std::string DecodeName(absl::string_view encoded) {
  const auto hex_value = [](char c) {
    return absl::ascii_isdigit(static_cast<unsigned char>(c)) ? c - '0'
                                                              : absl::ascii_tolower(c) - 'a' + 10;
  };
  std::string name;
  name.reserve(encoded.size());
  for (std::size_t i = 0; i < encoded.size(); ++i) {
    if (encoded[i] == '%' && i + 2 < encoded.size() &&
        absl::ascii_isxdigit(static_cast<unsigned char>(encoded[i + 1])) &&
        absl::ascii_isxdigit(static_cast<unsigned char>(encoded[i + 2]))) {
      name.push_back(static_cast<char>(16 * hex_value(encoded[i + 1]) + hex_value(encoded[i + 2])));
      i += 2;
    } else {
      name.push_back(encoded[i]);
    }
  }
  return name;
}

bool LooksLikeKeyword(absl::string_view token) {
  return !token.empty() && absl::ascii_isalpha(static_cast<unsigned char>(token.front())) &&
         absl::ascii_isupper(static_cast<unsigned char>(token.front()));
}

std::string AllTypeNames() {
  std::vector<absl::string_view> names;
  for (int i = 0; i <= static_cast<int>(VtkDataType::kDouble); ++i) {
    names.push_back(DataTypeInfo(static_cast<VtkDataType>(i)).name);
  }
  return absl::StrJoin(names, ", ");
}

// Which part of the file the section keywords belong to.
enum class Block { kDataset, kPointData, kCellData };

class Parser {
 public:
  explicit Parser(absl::string_view bytes) : scanner_(bytes) {}

  absl::StatusOr<UnstructuredGrid> Parse() {
    if (absl::Status status = ParseHeader(); !status.ok()) return status;
    if (absl::Status status = ParseSections(); !status.ok()) return status;
    if (absl::Status status = Finish(); !status.ok()) return status;
    return std::move(file_);
  }

 private:
  absl::Status Error(VtkLocation where, absl::string_view message) const {
    return absl::InvalidArgumentError(absl::StrCat(where.ToString(), ": ", message));
  }

  // ---- Header: version line, title, ASCII/BINARY, DATASET ----

  absl::Status ParseHeader() {
    const std::optional<absl::string_view> first = scanner_.ReadRawLine();
    if (!first) {
      return Error({false, 1}, absl::StrCat("the file is empty; expected '", kHeaderPrefix,
                                            " <major>.<minor>'"));
    }
    if (!absl::StartsWithIgnoreCase(*first, kHeaderPrefix)) {
      return Error(scanner_.location(),
                   absl::StrCat("expected '", kHeaderPrefix, " <major>.<minor>', found ",
                                Quote(*first), "; this is not a VTK legacy file"));
    }
    const absl::string_view version =
        absl::StripAsciiWhitespace(first->substr(kHeaderPrefix.size()));
    const std::size_t dot = version.find('.');
    if (dot == absl::string_view::npos ||
        !absl::SimpleAtoi(version.substr(0, dot), &file_.version_major) ||
        !absl::SimpleAtoi(version.substr(dot + 1), &file_.version_minor) ||
        file_.version_major < 0 || file_.version_minor < 0) {
      return Error(scanner_.location(), absl::StrCat("expected a version '<major>.<minor>' after '",
                                                     kHeaderPrefix, "', found ", Quote(version)));
    }
    const std::optional<absl::string_view> title = scanner_.ReadRawLine();
    if (!title) return Error(scanner_.here(), "the file ends before the title line (line 2)");
    // A carriage return left after the line ending's: the writer could not write it back (a
    // VTK reader would end the line there), so the file is refused rather than half-kept.
    if (title->find('\r') != absl::string_view::npos) {
      return Error(scanner_.location(),
                   "the title holds a carriage return that is not part of the line ending");
    }
    file_.title = std::string(*title);

    const std::vector<absl::string_view> format = scanner_.ReadKeywordLine();
    if (format.empty()) return Error(scanner_.here(), "the file ends before 'ASCII' or 'BINARY'");
    if (format.size() == 1 && absl::EqualsIgnoreCase(format[0], "ASCII")) {
      file_.encoding = Encoding::kAscii;
    } else if (format.size() == 1 && absl::EqualsIgnoreCase(format[0], "BINARY")) {
      file_.encoding = Encoding::kBinary;
    } else {
      return Error(scanner_.location(), absl::StrCat("expected 'ASCII' or 'BINARY', found ",
                                                     Quote(absl::StrJoin(format, " "))));
    }

    const std::vector<absl::string_view> dataset = scanner_.ReadKeywordLine();
    if (dataset.empty()) {
      return Error(scanner_.here(), "the file ends before 'DATASET UNSTRUCTURED_GRID'");
    }
    if (!absl::EqualsIgnoreCase(dataset[0], "DATASET") || dataset.size() != 2) {
      return Error(scanner_.location(), absl::StrCat("expected 'DATASET UNSTRUCTURED_GRID', found ",
                                                     Quote(absl::StrJoin(dataset, " "))));
    }
    if (!absl::EqualsIgnoreCase(dataset[1], "UNSTRUCTURED_GRID")) {
      return Error(scanner_.location(),
                   absl::StrCat("DATASET ", dataset[1],
                                " is not supported; getme reads DATASET UNSTRUCTURED_GRID"));
    }
    scanner_.set_binary(file_.encoding == Encoding::kBinary);
    return absl::OkStatus();
  }

  // ---- Section loop ----

  absl::Status ParseSections() {
    Block block = Block::kDataset;
    for (;;) {
      const std::vector<absl::string_view> words = scanner_.ReadKeywordLine();
      if (words.empty()) return absl::OkStatus();
      const VtkLocation where = scanner_.location();
      const std::string keyword = absl::AsciiStrToUpper(words[0]);
      absl::Status status;
      if (keyword == "METADATA") {
        SkipMetadata();
        continue;
      }
      if (keyword == "POINT_DATA" || keyword == "CELL_DATA") {
        const bool points = keyword == "POINT_DATA";
        if (words.size() != 2) return ExpectedForm(where, keyword + " <count>", words);
        std::int64_t& count = points ? point_data_count_ : cell_data_count_;
        if (count >= 0) return Error(where, absl::StrCat("a second ", keyword, " section"));
        absl::StatusOr<std::int64_t> parsed = ParseCount(words[1], keyword, where);
        if (!parsed.ok()) return parsed.status();
        count = *parsed;
        // Dataset sections cannot follow POINT_DATA / CELL_DATA, so the sizes are final.
        const std::int64_t actual = points ? file_.points.tuple_count() : cell_count_;
        if (count != actual) {
          return Error(
              where,
              absl::StrCat(keyword, " declares ", count,
                           points ? " points, but POINTS has " : " cells, but CELLS has ", actual));
        }
        block = points ? Block::kPointData : Block::kCellData;
        continue;
      }
      if (block == Block::kDataset) {
        if (keyword == "POINTS") {
          status = ParsePoints(words, where);
        } else if (keyword == "CELLS") {
          status = file_.uses_offsets_layout() ? ParseOffsetCells(words, where)
                                               : ParseLegacyCells(words, where);
        } else if (keyword == "CELL_TYPES") {
          status = ParseCellTypes(words, where);
        } else if (keyword == "FIELD") {
          status = ParseField(words, where, /*tuples=*/-1, file_.field_data);
        } else {
          return UnexpectedKeyword(words[0], where,
                                   "POINTS, CELLS, CELL_TYPES, FIELD, POINT_DATA, CELL_DATA");
        }
      } else {
        const bool points = block == Block::kPointData;
        status = ParseAttribute(words, where, points ? point_data_count_ : cell_data_count_,
                                points ? file_.point_data : file_.cell_data);
      }
      if (!status.ok()) return status;
    }
  }

  // VTK 9 writes METADATA blocks (component names, information keys) after arrays; they end
  // at a blank line. getme does not keep them.
  void SkipMetadata() {
    while (const std::optional<absl::string_view> line = scanner_.ReadRawLine()) {
      if (absl::StripAsciiWhitespace(*line).empty()) return;
    }
  }

  absl::Status ExpectedForm(VtkLocation where, absl::string_view form,
                            const std::vector<absl::string_view>& words) const {
    return Error(where,
                 absl::StrCat("expected '", form, "', found ", Quote(absl::StrJoin(words, " "))));
  }

  absl::Status UnexpectedKeyword(absl::string_view word, VtkLocation where,
                                 absl::string_view expected) const {
    std::string message =
        absl::StrCat("expected a section keyword (", expected, "), found ", Quote(word));
    if (ParseRealToken(word).has_value()) {
      absl::StrAppend(&message,
                      "; the section before it holds more values than its header declares");
    }
    return Error(where, message);
  }

  absl::StatusOr<std::int64_t> ParseCount(absl::string_view word, absl::string_view what,
                                          VtkLocation where) const {
    std::int64_t count = 0;
    if (!absl::SimpleAtoi(word, &count) || count < 0) {
      return Error(
          where, absl::StrCat(what, ": the count ", Quote(word), " is not a non-negative integer"));
    }
    return count;
  }

  absl::StatusOr<VtkDataType> ParseType(absl::string_view word, absl::string_view what,
                                        VtkLocation where) const {
    const std::optional<VtkDataType> type = ParseDataTypeName(word);
    if (!type) {
      return Error(where, absl::StrCat(what, ": unsupported data type ", Quote(word),
                                       "; expected one of ", AllTypeNames()));
    }
    return *type;
  }

  // ---- Values ----

  // Refuses counts the rest of the file cannot hold before anything is allocated for them.
  // bytes_per_value 0: packed bits.
  absl::Status CheckRoom(std::int64_t values, int bytes_per_value, absl::string_view what,
                         VtkLocation where) const {
    const auto remaining = static_cast<std::int64_t>(scanner_.remaining());
    if (scanner_.binary()) {
      if (bytes_per_value == 0 && values / 8 + (values % 8 != 0 ? 1 : 0) > remaining) {
        return Error(where, absl::StrCat(what, ": declares ", values, " bits, but only ", remaining,
                                         " bytes remain in the file"));
      }
      if (bytes_per_value > 0 && values > remaining / bytes_per_value) {
        return Error(
            where, absl::StrCat(what, ": declares ", values, " values of ", bytes_per_value,
                                " bytes each, but only ", remaining, " bytes remain in the file"));
      }
    } else if (values > remaining / 2 + 1) {
      // Each ASCII value takes at least one character and one separator.
      return Error(where,
                   absl::StrCat(what, ": declares ", values, " values, but the rest of the file (",
                                remaining, " bytes) cannot hold them"));
    }
    return absl::OkStatus();
  }

  absl::Status ValueError(absl::string_view what, std::int64_t index, std::int64_t count,
                          absl::string_view expected,
                          std::optional<absl::string_view> token) const {
    if (!token) {
      return Error(scanner_.here(), absl::StrCat(what, ": the file ends at value ", index + 1,
                                                 " of ", count, "; expected ", expected));
    }
    std::string message = absl::StrCat(what, ": value ", index + 1, " of ", count, " is ",
                                       Quote(*token), "; expected ", expected);
    if (LooksLikeKeyword(*token)) {
      absl::StrAppend(&message, " (the section holds fewer values than its header declares)");
    }
    return Error(scanner_.location(), message);
  }

  absl::StatusOr<std::int64_t> ReadInteger(VtkDataType type, absl::string_view what,
                                           std::int64_t index, std::int64_t count) {
    const VtkDataTypeInfo& info = DataTypeInfo(type);
    if (scanner_.binary()) {
      const std::optional<absl::string_view> bytes = scanner_.TakeBytes(info.binary_size);
      if (!bytes) {
        return Error(scanner_.here(),
                     absl::StrCat(what, ": the file ends at value ", index + 1, " of ", count, " (",
                                  info.name, ", ", info.binary_size, " bytes each)"));
      }
      const std::int64_t value = DecodeBigEndianInteger(bytes->data(), type);
      return value;
    }
    const std::int64_t max = info.max > static_cast<std::uint64_t>(kMaxInt64)
                                 ? kMaxInt64
                                 : static_cast<std::int64_t>(info.max);
    if (const std::optional<std::int64_t> plain = scanner_.NextPlainInteger(info.min, max)) {
      return *plain;
    }
    const std::optional<absl::string_view> token = scanner_.NextToken();
    std::optional<std::int64_t> value;
    if (token) value = ParseIntegerToken(*token, type);
    if (!value) {
      return ValueError(
          what, index, count,
          absl::StrCat("an integer of type ", info.name,
                       type == VtkDataType::kUnsignedLong || type == VtkDataType::kUInt64
                           ? ""
                           : absl::StrCat(" in [", info.min, ", ", info.max, "]")),
          token);
    }
    return *value;
  }

  absl::StatusOr<double> ReadReal(VtkDataType type, absl::string_view what, std::int64_t index,
                                  std::int64_t count) {
    const VtkDataTypeInfo& info = DataTypeInfo(type);
    if (scanner_.binary()) {
      const std::optional<absl::string_view> bytes = scanner_.TakeBytes(info.binary_size);
      if (!bytes) {
        return Error(scanner_.here(),
                     absl::StrCat(what, ": the file ends at value ", index + 1, " of ", count, " (",
                                  info.name, ", ", info.binary_size, " bytes each)"));
      }
      return DecodeBigEndianReal(bytes->data(), type);
    }
    if (const std::optional<double> plain = scanner_.NextPlainReal()) return *plain;
    const std::optional<absl::string_view> token = scanner_.NextToken();
    std::optional<double> value;
    if (token) value = ParseRealToken(*token);
    if (!value) return ValueError(what, index, count, "a number", token);
    return *value;
  }

  // Reads `count` values of array.type into the array.
  absl::Status ReadValues(DataArray& array, std::int64_t count, absl::string_view what,
                          VtkLocation header) {
    const VtkDataTypeInfo& info = DataTypeInfo(array.type);
    if (absl::Status status = CheckRoom(count, info.binary_size, what, header); !status.ok()) {
      return status;
    }
    if (array.type == VtkDataType::kBit) return ReadBits(array, count, what);
    if (info.is_integer) {
      array.integers.reserve(count);
      for (std::int64_t i = 0; i < count; ++i) {
        absl::StatusOr<std::int64_t> value = ReadInteger(array.type, what, i, count);
        if (!value.ok()) return value.status();
        array.integers.push_back(*value);
      }
    } else {
      array.reals.reserve(count);
      for (std::int64_t i = 0; i < count; ++i) {
        absl::StatusOr<double> value = ReadReal(array.type, what, i, count);
        if (!value.ok()) return value.status();
        array.reals.push_back(*value);
      }
    }
    return absl::OkStatus();
  }

  // bit arrays: 0/1 tokens in ASCII, packed eight to a byte (most significant first) in BINARY.
  absl::Status ReadBits(DataArray& array, std::int64_t count, absl::string_view what) {
    array.integers.reserve(count);
    if (scanner_.binary()) {
      const std::optional<absl::string_view> bytes = scanner_.TakeBytes((count + 7) / 8);
      if (!bytes) {
        return Error(scanner_.here(),
                     absl::StrCat(what, ": the file ends before the ", (count + 7) / 8,
                                  " bytes of ", count, " packed bits"));
      }
      for (std::int64_t i = 0; i < count; ++i) {
        const auto byte = static_cast<unsigned char>((*bytes)[i / 8]);
        array.integers.push_back((byte >> (7 - i % 8)) & 1);
      }
      return absl::OkStatus();
    }
    for (std::int64_t i = 0; i < count; ++i) {
      absl::StatusOr<std::int64_t> value = ReadInteger(VtkDataType::kLong, what, i, count);
      if (!value.ok()) return value.status();
      array.integers.push_back(*value != 0 ? 1 : 0);
    }
    return absl::OkStatus();
  }

  // COLOR_SCALARS and LOOKUP_TABLE values: floats in [0, 1] in ASCII, unsigned bytes in BINARY
  // (stored as byte / 255).
  absl::Status ReadColorValues(DataArray& array, std::int64_t count, absl::string_view what,
                               VtkLocation header) {
    array.type = VtkDataType::kFloat;
    if (!scanner_.binary()) return ReadValues(array, count, what, header);
    if (absl::Status status = CheckRoom(count, 1, what, header); !status.ok()) return status;
    const std::optional<absl::string_view> bytes = scanner_.TakeBytes(count);
    if (!bytes) return Error(scanner_.here(), absl::StrCat(what, ": the file ends early"));
    array.reals.reserve(count);
    for (const char byte : *bytes) {
      array.reals.push_back(static_cast<unsigned char>(byte) / 255.0);
    }
    return absl::OkStatus();
  }

  // ---- Dataset sections ----

  absl::Status ParsePoints(const std::vector<absl::string_view>& words, VtkLocation where) {
    if (words.size() != 3) return ExpectedForm(where, "POINTS <count> <type>", words);
    if (points_location_) {
      return Error(where, absl::StrCat("a second POINTS section (the first is at ",
                                       points_location_->ToString(), ")"));
    }
    points_location_ = where;
    absl::StatusOr<std::int64_t> count = ParseCount(words[1], "POINTS", where);
    if (!count.ok()) return count.status();
    absl::StatusOr<VtkDataType> type = ParseType(words[2], "POINTS", where);
    if (!type.ok()) return type.status();
    if (*type == VtkDataType::kBit) {
      return Error(where, "POINTS: coordinates cannot have data type bit");
    }
    if (*count > std::numeric_limits<std::int64_t>::max() / 3) {
      return Error(where, "POINTS: the count is too large");
    }
    file_.points.type = *type;
    file_.points.components = 3;
    return ReadValues(file_.points, *count * 3, "POINTS", where);
  }

  // Classic layout: "CELLS n size", then n rows "k id_1 … id_k" holding size integers in all.
  absl::Status ParseLegacyCells(const std::vector<absl::string_view>& words, VtkLocation where) {
    if (words.size() != 3) return ExpectedForm(where, "CELLS <cell count> <total size>", words);
    if (absl::Status status = BeginCells(where); !status.ok()) return status;
    absl::StatusOr<std::int64_t> cell_count = ParseCount(words[1], "CELLS", where);
    if (!cell_count.ok()) return cell_count.status();
    absl::StatusOr<std::int64_t> size = ParseCount(words[2], "CELLS", where);
    if (!size.ok()) return size.status();
    if (*cell_count > *size) {
      return Error(where,
                   absl::StrCat("CELLS: ", *cell_count, " cells cannot fit in a total size of ",
                                *size, " (each cell needs at least its node count)"));
    }
    if (absl::Status status = CheckRoom(*size, 4, "CELLS", where); !status.ok()) return status;
    GridCells& cells = file_.cells;
    cells.offsets.reserve(*cell_count + 1);
    cells.connectivity.reserve(*size - *cell_count);
    cell_locations_.reserve(*cell_count);
    std::int64_t consumed = 0;
    for (std::int64_t cell = 0; cell < *cell_count; ++cell) {
      absl::StatusOr<std::int64_t> node_count =
          ReadInteger(VtkDataType::kInt, "CELLS", consumed, *size);
      if (!node_count.ok()) return node_count.status();
      const VtkLocation cell_location = scanner_.location();
      cell_locations_.push_back(cell_location.value);
      ++consumed;
      if (*node_count < 0 || *node_count > *size - consumed) {
        return Error(cell_location, absl::StrCat("CELLS: cell ", cell, " declares ", *node_count,
                                                 " node ids, but only ", *size - consumed,
                                                 " values remain of the total size ", *size,
                                                 " declared at ", where.ToString()));
      }
      for (std::int64_t k = 0; k < *node_count; ++k) {
        absl::StatusOr<std::int64_t> id = ReadInteger(VtkDataType::kInt, "CELLS", consumed, *size);
        if (!id.ok()) return id.status();
        cells.connectivity.push_back(*id);
        ++consumed;
      }
      cells.offsets.push_back(static_cast<std::int64_t>(cells.connectivity.size()));
    }
    if (consumed != *size) {
      return Error(where, absl::StrCat("CELLS: declares a total size of ", *size, ", but its ",
                                       *cell_count, " cells hold ", consumed, " values"));
    }
    cell_count_ = *cell_count;
    return absl::OkStatus();
  }

  // File version 5.1: "CELLS <offset count> <connectivity size>", then "OFFSETS <type>" with
  // cell count + 1 offsets and "CONNECTIVITY <type>" with the node ids.
  absl::Status ParseOffsetCells(const std::vector<absl::string_view>& words, VtkLocation where) {
    if (words.size() != 3) {
      return ExpectedForm(where, "CELLS <offset count> <connectivity size>", words);
    }
    if (absl::Status status = BeginCells(where); !status.ok()) return status;
    absl::StatusOr<std::int64_t> offset_count = ParseCount(words[1], "CELLS", where);
    if (!offset_count.ok()) return offset_count.status();
    absl::StatusOr<std::int64_t> connectivity_size = ParseCount(words[2], "CELLS", where);
    if (!connectivity_size.ok()) return connectivity_size.status();

    DataArray offsets;
    if (absl::Status status = ReadCellArray("OFFSETS", *offset_count, offsets); !status.ok()) {
      return status;
    }
    const VtkLocation offsets_location = offset_array_location_;
    DataArray connectivity;
    if (absl::Status status = ReadCellArray("CONNECTIVITY", *connectivity_size, connectivity);
        !status.ok()) {
      return status;
    }
    GridCells& cells = file_.cells;
    if (*offset_count == 0) {
      if (*connectivity_size != 0) {
        return Error(where, "CELLS: no offsets but a non-empty CONNECTIVITY array");
      }
      cell_count_ = 0;
      return absl::OkStatus();
    }
    if (offsets.integers.front() != 0) {
      return Error(offsets_location, absl::StrCat("OFFSETS: the first offset is ",
                                                  offsets.integers.front(), "; expected 0"));
    }
    for (std::size_t i = 1; i < offsets.integers.size(); ++i) {
      if (offsets.integers[i] < offsets.integers[i - 1]) {
        return Error(
            offsets_location,
            absl::StrCat("OFFSETS: offset ", i, " (", offsets.integers[i],
                         ") is smaller than offset ", i - 1, " (", offsets.integers[i - 1], ")"));
      }
    }
    if (offsets.integers.back() != *connectivity_size) {
      return Error(offsets_location,
                   absl::StrCat("OFFSETS: the last offset is ", offsets.integers.back(),
                                ", but CONNECTIVITY has ", *connectivity_size, " entries"));
    }
    cells.offsets = std::move(offsets.integers);
    cells.connectivity = std::move(connectivity.integers);
    cell_count_ = *offset_count - 1;
    // Without per-row lines, errors about a cell point at the OFFSETS array and name the cell.
    cell_locations_.assign(cell_count_, offsets_location.value);
    return absl::OkStatus();
  }

  absl::Status BeginCells(VtkLocation where) {
    if (cells_location_) {
      return Error(where, absl::StrCat("a second CELLS section (the first is at ",
                                       cells_location_->ToString(), ")"));
    }
    cells_location_ = where;
    return absl::OkStatus();
  }

  absl::Status ReadCellArray(absl::string_view keyword, std::int64_t count, DataArray& array) {
    const std::vector<absl::string_view> words = scanner_.ReadKeywordLine();
    const VtkLocation where = words.empty() ? scanner_.here() : scanner_.location();
    if (words.size() != 2 || !absl::EqualsIgnoreCase(words[0], keyword)) {
      return ExpectedForm(where, absl::StrCat(keyword, " <integer type>"), words);
    }
    absl::StatusOr<VtkDataType> type = ParseType(words[1], keyword, where);
    if (!type.ok()) return type.status();
    if (!IsIntegerType(*type) || *type == VtkDataType::kBit) {
      return Error(
          where, absl::StrCat(keyword, ": the data type must be an integer type, not ", words[1]));
    }
    offset_array_location_ = where;
    array.type = *type;
    return ReadValues(array, count, keyword, where);
  }

  absl::Status ParseCellTypes(const std::vector<absl::string_view>& words, VtkLocation where) {
    if (words.size() != 2) return ExpectedForm(where, "CELL_TYPES <count>", words);
    if (cell_types_location_) {
      return Error(where, absl::StrCat("a second CELL_TYPES section (the first is at ",
                                       cell_types_location_->ToString(), ")"));
    }
    cell_types_location_ = where;
    absl::StatusOr<std::int64_t> count = ParseCount(words[1], "CELL_TYPES", where);
    if (!count.ok()) return count.status();
    if (absl::Status status = CheckRoom(*count, 4, "CELL_TYPES", where); !status.ok()) {
      return status;
    }
    file_.cells.types.reserve(*count);
    for (std::int64_t cell = 0; cell < *count; ++cell) {
      absl::StatusOr<std::int64_t> type =
          ReadInteger(VtkDataType::kInt, "CELL_TYPES", cell, *count);
      if (!type.ok()) return type.status();
      if (!CellTypeInfo(static_cast<int>(*type))) {
        return Error(scanner_.location(),
                     absl::StrCat("CELL_TYPES: cell ", cell, " has unknown VTK cell type ", *type));
      }
      file_.cells.types.push_back(static_cast<std::uint8_t>(*type));
    }
    cell_types_count_ = *count;
    return absl::OkStatus();
  }

  // ---- Attributes ----

  absl::Status ParseAttribute(const std::vector<absl::string_view>& words, VtkLocation where,
                              std::int64_t tuples, std::vector<VtkAttribute>& attributes) {
    const std::string keyword = absl::AsciiStrToUpper(words[0]);
    const std::string section =
        absl::StrCat(keyword, words.size() > 1 ? " " : "", words.size() > 1 ? words[1] : "");
    VtkAttribute attribute;
    attribute.arrays.emplace_back();
    DataArray& array = attribute.arrays.back();
    if (words.size() > 1) array.name = DecodeName(words[1]);
    attribute.name = array.name;

    // Attributes whose header is "KEYWORD name type" and whose tuples have a fixed width.
    struct TypedKind {
      absl::string_view keyword;
      VtkAttributeKind kind;
      int components;
    };
    constexpr TypedKind kTyped[] = {{"VECTORS", VtkAttributeKind::kVectors, 3},
                                    {"NORMALS", VtkAttributeKind::kNormals, 3},
                                    {"TENSORS", VtkAttributeKind::kTensors, 9},
                                    {"GLOBAL_IDS", VtkAttributeKind::kGlobalIds, 1}};
    for (const TypedKind& typed : kTyped) {
      if (keyword != typed.keyword) continue;
      if (words.size() != 3)
        return ExpectedForm(where, absl::StrCat(keyword, " <name> <type>"), words);
      attribute.kind = typed.kind;
      absl::StatusOr<VtkDataType> type = ParseType(words[2], section, where);
      if (!type.ok()) return type.status();
      array.type = *type;
      array.components = typed.components;
      return FinishAttribute(std::move(attribute), tuples, where, section, attributes);
    }
    if (keyword == "SCALARS") {
      if (words.size() != 3 && words.size() != 4) {
        return ExpectedForm(where, "SCALARS <name> <type> [<components>]", words);
      }
      attribute.kind = VtkAttributeKind::kScalars;
      absl::StatusOr<VtkDataType> type = ParseType(words[2], section, where);
      if (!type.ok()) return type.status();
      array.type = *type;
      if (words.size() == 4) {
        absl::StatusOr<int> components = ParseComponents(words[3], section, where);
        if (!components.ok()) return components.status();
        array.components = *components;
      }
      if (absl::Status status = ParseScalarsLookupTable(attribute, where); !status.ok()) {
        return status;
      }
      return FinishAttribute(std::move(attribute), tuples, where, section, attributes);
    }
    if (keyword == "TEXTURE_COORDINATES") {
      if (words.size() != 4) {
        return ExpectedForm(where, "TEXTURE_COORDINATES <name> <dimension> <type>", words);
      }
      attribute.kind = VtkAttributeKind::kTextureCoordinates;
      absl::StatusOr<int> components = ParseComponents(words[2], section, where);
      if (!components.ok()) return components.status();
      array.components = *components;
      absl::StatusOr<VtkDataType> type = ParseType(words[3], section, where);
      if (!type.ok()) return type.status();
      array.type = *type;
      return FinishAttribute(std::move(attribute), tuples, where, section, attributes);
    }
    if (keyword == "COLOR_SCALARS") {
      if (words.size() != 3) return ExpectedForm(where, "COLOR_SCALARS <name> <components>", words);
      attribute.kind = VtkAttributeKind::kColorScalars;
      absl::StatusOr<int> components = ParseComponents(words[2], section, where);
      if (!components.ok()) return components.status();
      array.components = *components;
      return FinishAttribute(std::move(attribute), tuples, where, section, attributes);
    }
    if (keyword == "LOOKUP_TABLE") {
      if (words.size() != 3) return ExpectedForm(where, "LOOKUP_TABLE <name> <size>", words);
      attribute.kind = VtkAttributeKind::kLookupTable;
      array.components = 4;
      absl::StatusOr<std::int64_t> size = ParseCount(words[2], section, where);
      if (!size.ok()) return size.status();
      return FinishAttribute(std::move(attribute), *size, where, section, attributes);
    }
    if (keyword == "FIELD") return ParseField(words, where, tuples, attributes);
    return UnexpectedKeyword(words[0], where,
                             "SCALARS, COLOR_SCALARS, LOOKUP_TABLE, VECTORS, NORMALS, "
                             "TEXTURE_COORDINATES, TENSORS, GLOBAL_IDS, FIELD, POINT_DATA, "
                             "CELL_DATA");
  }

  absl::StatusOr<int> ParseComponents(absl::string_view word, absl::string_view what,
                                      VtkLocation where) const {
    constexpr int kMaxComponents = 1 << 16;
    int components = 0;
    if (!absl::SimpleAtoi(word, &components) || components < 1 || components > kMaxComponents) {
      return Error(where, absl::StrCat(what, ": the component count ", Quote(word),
                                       " is not an integer in [1, ", kMaxComponents, "]"));
    }
    return components;
  }

  // SCALARS is followed by "LOOKUP_TABLE <name>". VTK insists on it; ASCII files that leave it
  // out are read with the default table, BINARY ones cannot be (the data would be taken as a
  // keyword line).
  absl::Status ParseScalarsLookupTable(VtkAttribute& attribute, VtkLocation scalars_location) {
    const VtkScanner::State before = scanner_.Save();
    const std::vector<absl::string_view> words = scanner_.ReadKeywordLine();
    if (!words.empty() && absl::EqualsIgnoreCase(words[0], "LOOKUP_TABLE")) {
      if (words.size() != 2) return ExpectedForm(scanner_.location(), "LOOKUP_TABLE <name>", words);
      attribute.lookup_table = DecodeName(words[1]);
      return absl::OkStatus();
    }
    if (scanner_.binary()) {
      return Error(scalars_location,
                   "SCALARS: expected a 'LOOKUP_TABLE <name>' line after the SCALARS line");
    }
    scanner_.Restore(before);
    attribute.lookup_table = "default";
    return absl::OkStatus();
  }

  // Reads the values of a one-array attribute and appends it.
  absl::Status FinishAttribute(VtkAttribute attribute, std::int64_t tuples, VtkLocation where,
                               absl::string_view section, std::vector<VtkAttribute>& attributes) {
    DataArray& array = attribute.arrays.back();
    if (tuples > std::numeric_limits<std::int64_t>::max() / array.components) {
      return Error(where, absl::StrCat(section, ": too many values"));
    }
    const std::int64_t count = tuples * array.components;
    const bool color = attribute.kind == VtkAttributeKind::kColorScalars ||
                       attribute.kind == VtkAttributeKind::kLookupTable;
    absl::Status status = color ? ReadColorValues(array, count, section, where)
                                : ReadValues(array, count, section, where);
    if (!status.ok()) return status;
    attributes.push_back(std::move(attribute));
    return absl::OkStatus();
  }

  // "FIELD <name> <array count>", then per array "<name> <components> <tuples> <type>" and its
  // values. `tuples` < 0: dataset-level field data, whose arrays may have any length.
  absl::Status ParseField(const std::vector<absl::string_view>& words, VtkLocation where,
                          std::int64_t tuples, std::vector<VtkAttribute>& attributes) {
    if (words.size() != 3) return ExpectedForm(where, "FIELD <name> <array count>", words);
    VtkAttribute field;
    field.kind = VtkAttributeKind::kField;
    field.name = DecodeName(words[1]);
    absl::StatusOr<std::int64_t> array_count = ParseCount(words[2], "FIELD", where);
    if (!array_count.ok()) return array_count.status();
    if (absl::Status status = CheckRoom(*array_count, 1, "FIELD", where); !status.ok()) {
      return status;
    }
    for (std::int64_t i = 0; i < *array_count; ++i) {
      std::vector<absl::string_view> header = scanner_.ReadKeywordLine();
      while (!header.empty() && absl::EqualsIgnoreCase(header[0], "METADATA")) {
        SkipMetadata();
        header = scanner_.ReadKeywordLine();
      }
      const VtkLocation header_location = header.empty() ? scanner_.here() : scanner_.location();
      if (header.size() == 1 && absl::EqualsIgnoreCase(header[0], "NULL_ARRAY")) continue;
      const std::string section = absl::StrCat("FIELD ", field.name, " array ", i);
      if (header.size() != 4) {
        return ExpectedForm(header_location,
                            absl::StrCat("<array name> <components> <tuples> <type> (array ", i,
                                         " of FIELD ", field.name, ")"),
                            header);
      }
      DataArray array;
      array.name = DecodeName(header[0]);
      const std::string array_section = absl::StrCat("FIELD ", field.name, " array ", array.name);
      absl::StatusOr<int> components = ParseComponents(header[1], array_section, header_location);
      if (!components.ok()) return components.status();
      array.components = *components;
      absl::StatusOr<std::int64_t> array_tuples =
          ParseCount(header[2], array_section, header_location);
      if (!array_tuples.ok()) return array_tuples.status();
      if (tuples >= 0 && *array_tuples != tuples) {
        return Error(
            header_location,
            absl::StrCat(array_section, ": has ", *array_tuples,
                         " tuples, but the POINT_DATA/CELL_DATA section declares ", tuples));
      }
      absl::StatusOr<VtkDataType> type = ParseType(header[3], array_section, header_location);
      if (!type.ok()) return type.status();
      array.type = *type;
      if (*array_tuples > std::numeric_limits<std::int64_t>::max() / array.components) {
        return Error(header_location, absl::StrCat(array_section, ": too many values"));
      }
      if (absl::Status status =
              ReadValues(array, *array_tuples * array.components, array_section, header_location);
          !status.ok()) {
        return status;
      }
      field.arrays.push_back(std::move(array));
    }
    attributes.push_back(std::move(field));
    return absl::OkStatus();
  }

  // ---- Whole-file checks ----

  absl::Status Finish() {
    if (!points_location_) return Error(scanner_.here(), "the file has no POINTS section");
    const std::int64_t point_count = file_.points.tuple_count();
    if (cells_location_.has_value() != cell_types_location_.has_value()) {
      return cells_location_ ? Error(*cells_location_, "CELLS without a CELL_TYPES section")
                             : Error(*cell_types_location_, "CELL_TYPES without a CELLS section");
    }
    if (cells_location_ && cell_count_ != cell_types_count_) {
      return Error(*cell_types_location_,
                   absl::StrCat("CELL_TYPES lists ", cell_types_count_, " cells, but CELLS at ",
                                cells_location_->ToString(), " lists ", cell_count_));
    }
    const GridCells& cells = file_.cells;
    for (std::int64_t cell = 0; cell < cells.size(); ++cell) {
      const VtkLocation where{scanner_.binary(), cell_locations_[cell]};
      const VtkCellTypeInfo info = *CellTypeInfo(cells.types[cell]);
      const std::int64_t node_count = cells.node_count(cell);
      if (info.node_count >= 0 && node_count != info.node_count) {
        return Error(
            where, absl::StrCat("CELLS: cell ", cell, " is a ", info.name, " (VTK type ", info.code,
                                ") with ", node_count, " node ids; expected ", info.node_count));
      }
      if (info.code == kVtkPolyhedron) continue;  // a face stream, not only point ids
      const std::int64_t* nodes = cells.nodes(cell);
      for (std::int64_t k = 0; k < node_count; ++k) {
        if (nodes[k] < 0 || nodes[k] >= point_count) {
          return Error(
              where, absl::StrCat("CELLS: cell ", cell, " (", info.name, ") refers to point ",
                                  nodes[k], ", but POINTS has ", point_count, " points (ids 0 to ",
                                  point_count - 1, ")"));
        }
      }
    }
    return absl::OkStatus();
  }

  VtkScanner scanner_;
  UnstructuredGrid file_;
  std::optional<VtkLocation> points_location_;
  std::optional<VtkLocation> cells_location_;
  std::optional<VtkLocation> cell_types_location_;
  VtkLocation offset_array_location_;
  std::int64_t cell_count_ = 0;
  std::int64_t cell_types_count_ = 0;
  std::int64_t point_data_count_ = -1;
  std::int64_t cell_data_count_ = -1;
  // Where each cell's row (or offset) starts: a line number or byte offset.
  std::vector<std::int64_t> cell_locations_;
};

}  // namespace

absl::StatusOr<UnstructuredGrid> ParseVtk(absl::string_view bytes) { return Parser(bytes).Parse(); }

absl::StatusOr<UnstructuredGrid> ReadVtkFile(const std::string& path) {
  absl::StatusOr<std::string> contents = ReadFileBytes(path);
  if (!contents.ok()) return contents.status();
  absl::StatusOr<UnstructuredGrid> file = ParseVtk(*contents);
  if (!file.ok()) {
    return absl::Status(file.status().code(), absl::StrCat(path, ": ", file.status().message()));
  }
  return file;
}

}  // namespace getme::formats
