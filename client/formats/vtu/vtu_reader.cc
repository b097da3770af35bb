#include "formats/vtu/vtu_reader.h"

#include <algorithm>
#include <cstring>
#include <limits>
#include <optional>
#include <pugixml.hpp>
#include <string>
#include <utility>
#include <vector>

#include "absl/status/status.h"
#include "absl/strings/ascii.h"
#include "absl/strings/numbers.h"
#include "absl/strings/str_cat.h"
#include "formats/quote.h"
#include "formats/vtk_cell_type.h"
#include "formats/vtk_values.h"
#include "formats/vtu/vtu_binary.h"
#include "formats/vtu/vtu_names.h"

namespace getme::formats {
namespace {

using vtu::BinaryFraming;
using vtu::ByteOrder;

constexpr int kMaxComponents = 1 << 16;
constexpr absl::string_view kZlibCompressor = "vtkZLibDataCompressor";
// VTK's name for the arrays of a dataset that carry no attribute role.
constexpr absl::string_view kFieldDataName = "FieldData";

absl::string_view NameOf(pugi::xml_node node) { return node.name(); }

bool IsAsciiSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

// What a DataArray must hold, and who says so (for the error message).
struct Expected {
  std::int64_t tuples = -1;  // -1: any number (connectivity; field data without NumberOfTuples)
  std::string source;        // "NumberOfPoints=\"4\" of <Piece> (line 3)"
  int components = 0;        // 0: any
  bool integers_only = false;
};

// One <Piece> before the pieces are merged.
struct Piece {
  pugi::xml_node node;
  DataArray points;
  GridCells cells;
  std::vector<VtkAttribute> point_data;
  std::vector<VtkAttribute> cell_data;
};

class Reader {
 public:
  explicit Reader(absl::string_view bytes) : bytes_(bytes) {}

  absl::StatusOr<MeshDocument> Read() {
    if (absl::Status status = SplitAppendedData(); !status.ok()) return status;
    const pugi::xml_parse_result parsed =
        document_.load_buffer(xml_.data(), xml_.size(), pugi::parse_default, pugi::encoding_utf8);
    if (!parsed) {
      return absl::InvalidArgumentError(absl::StrCat(
          "line ", LineOf(parsed.offset), ": not well-formed XML (", parsed.description(), ")"));
    }
    if (absl::Status status = ReadFileAttributes(); !status.ok()) return status;
    const pugi::xml_node root = document_.document_element();
    const pugi::xml_node grid = root.child("UnstructuredGrid");
    if (!grid) return Error(root, "has no <UnstructuredGrid> element");
    if (absl::Status status = ReadAppendedElement(root); !status.ok()) return status;

    MeshDocument document;
    document.format = FileFormat::kVtkXml;
    UnstructuredGrid& file = document.grid;
    if (const pugi::xml_node field = grid.child("FieldData")) {
      if (absl::Status status = ReadFieldData(field, file.field_data); !status.ok()) return status;
    }
    std::vector<Piece> pieces;
    for (const pugi::xml_node node : grid.children("Piece")) {
      absl::StatusOr<Piece> piece = ReadPiece(node);
      if (!piece.ok()) return piece.status();
      pieces.push_back(std::move(*piece));
    }
    if (pieces.empty()) return Error(grid, "has no <Piece> element");
    if (absl::Status status = Merge(pieces, file); !status.ok()) return status;

    document.as_read.encoding = any_binary_ ? Encoding::kBinary : Encoding::kAscii;
    document.as_read.vtu_layout = any_appended_ ? VtuLayout::kAppended : VtuLayout::kInline;
    document.as_read.vtu_compress = any_binary_ && framing_.zlib;
    file.encoding = document.as_read.encoding;
    return document;
  }

 private:
  // ---- Locations and errors ----

  std::int64_t LineOf(std::ptrdiff_t offset) const {
    const auto end = static_cast<std::size_t>(
        std::clamp<std::ptrdiff_t>(offset, 0, static_cast<std::ptrdiff_t>(xml_.size())));
    return 1 + std::count(xml_.begin(), xml_.begin() + end, '\n');
  }
  std::int64_t LineOf(pugi::xml_node node) const { return LineOf(node.offset_debug()); }

  // "DataArray 'offsets' of <Cells>" or "<Piece>".
  static std::string Describe(pugi::xml_node node) {
    if (NameOf(node) != "DataArray") return absl::StrCat("<", NameOf(node), ">");
    std::string text = "DataArray";
    const absl::string_view name = node.attribute("Name").value();
    if (!name.empty()) absl::StrAppend(&text, " '", name, "'");
    absl::StrAppend(&text, " of <", NameOf(node.parent()), ">");
    return text;
  }

  absl::Status ErrorAtLine(std::int64_t line, pugi::xml_node node,
                           absl::string_view message) const {
    return absl::InvalidArgumentError(
        absl::StrCat("line ", line, ": ", Describe(node), ": ", message));
  }
  absl::Status Error(pugi::xml_node node, absl::string_view message) const {
    return ErrorAtLine(LineOf(node), node, message);
  }

  // ---- File layout ----

  // Raw appended data is not XML (any byte may occur in it), so it is cut out before the XML is
  // parsed: everything from the '_' that starts it to </AppendedData>. <AppendedData> is the
  // last element of the file, so the line numbers of everything else stay those of the file.
  // Base64 appended data is cut out the same way, which keeps one code path for both.
  absl::Status SplitAppendedData() {
    const std::size_t tag = bytes_.find("<AppendedData");
    const std::size_t tag_end = tag == absl::string_view::npos ? tag : bytes_.find('>', tag);
    if (tag_end == absl::string_view::npos || bytes_[tag_end - 1] == '/') {
      xml_ = std::string(bytes_);
      return absl::OkStatus();
    }
    xml_ = std::string(bytes_.substr(0, tag_end + 1));
    const std::int64_t line = LineOf(static_cast<std::ptrdiff_t>(tag));
    const std::size_t close = bytes_.rfind("</AppendedData>");
    if (close == absl::string_view::npos || close < tag_end) {
      return absl::InvalidArgumentError(absl::StrCat(
          "line ", line, ": <AppendedData>: no closing </AppendedData>; the file is truncated"));
    }
    std::size_t underscore = tag_end + 1;
    while (underscore < close && IsAsciiSpace(bytes_[underscore])) ++underscore;
    if (underscore == close) {
      xml_ = std::string(bytes_);  // an empty section
      return absl::OkStatus();
    }
    if (bytes_[underscore] != '_') {
      return absl::InvalidArgumentError(
          absl::StrCat("line ", line, ": <AppendedData>: the data must start with '_', found ",
                       Quote(bytes_.substr(underscore, 1))));
    }
    appended_ = bytes_.substr(underscore + 1, close - underscore - 1);
    has_appended_ = true;
    appended_line_ = line;
    xml_ = absl::StrCat(bytes_.substr(0, underscore), bytes_.substr(close));
    return absl::OkStatus();
  }

  absl::Status ReadFileAttributes() {
    const pugi::xml_node root = document_.document_element();
    if (NameOf(root) != "VTKFile") {
      return Error(root, "expected the root element <VTKFile>; this is not a VTK XML file");
    }
    const absl::string_view type = root.attribute("type").value();
    if (type != "UnstructuredGrid") {
      return Error(root, absl::StrCat("type ", Quote(type),
                                      " is not supported; getme reads type \"UnstructuredGrid\""));
    }
    if (const pugi::xml_attribute version = root.attribute("version")) {
      const absl::string_view text = version.value();
      const std::size_t dot = text.find('.');
      int major = -1;
      int minor = -1;
      if (dot == absl::string_view::npos || !absl::SimpleAtoi(text.substr(0, dot), &major) ||
          !absl::SimpleAtoi(text.substr(dot + 1), &minor) || major < 0 || major > 2 || minor < 0) {
        return Error(root, absl::StrCat("version ", Quote(text),
                                        " is not supported; expected 0.1, 1.0 or 2.x"));
      }
    }
    if (const pugi::xml_attribute order = root.attribute("byte_order")) {
      const absl::string_view text = order.value();
      if (text == "BigEndian") {
        framing_.byte_order = ByteOrder::kBigEndian;
      } else if (text != "LittleEndian") {
        return Error(root, absl::StrCat("byte_order ", Quote(text),
                                        " is not supported; expected LittleEndian or BigEndian"));
      }
    }
    if (const pugi::xml_attribute header = root.attribute("header_type")) {
      const absl::string_view text = header.value();
      if (text == "UInt64") {
        framing_.header_bytes = 8;
      } else if (text != "UInt32") {
        return Error(root, absl::StrCat("header_type ", Quote(text),
                                        " is not supported; expected UInt32 or UInt64"));
      }
    }
    // Only binary arrays are compressed, so an unsupported compressor is reported at the first
    // binary array: an ASCII file naming one still reads.
    compressor_ = root.attribute("compressor").value();
    framing_.zlib = compressor_ == kZlibCompressor;
    return absl::OkStatus();
  }

  absl::Status ReadAppendedElement(pugi::xml_node root) {
    if (!has_appended_) return absl::OkStatus();
    const pugi::xml_node appended = root.child("AppendedData");
    if (!appended) {
      return absl::InvalidArgumentError(absl::StrCat(
          "line ", appended_line_, ": <AppendedData> must be a child element of <VTKFile>"));
    }
    const absl::string_view encoding = appended.attribute("encoding").value();
    if (encoding == "base64") {
      appended_raw_ = false;
      CollectAppendedOffsets(root);
      std::sort(appended_offsets_.begin(), appended_offsets_.end());
    } else if (encoding != "raw") {
      return Error(appended, absl::StrCat("encoding ", Quote(encoding),
                                          " is not supported; expected raw or "
                                          "base64"));
    }
    return absl::OkStatus();
  }

  // In base64 appended data an array's text ends where the next array's begins.
  void CollectAppendedOffsets(pugi::xml_node node) {
    for (const pugi::xml_node child : node.children()) {
      std::int64_t offset = 0;
      if (NameOf(child) == "DataArray" &&
          absl::string_view(child.attribute("format").value()) == "appended" &&
          absl::SimpleAtoi(child.attribute("offset").value(), &offset)) {
        appended_offsets_.push_back(offset);
      }
      CollectAppendedOffsets(child);
    }
  }

  // ---- Attributes of elements ----

  absl::StatusOr<std::int64_t> CountAttribute(pugi::xml_node node, const char* name) const {
    const pugi::xml_attribute attribute = node.attribute(name);
    if (!attribute) return Error(node, absl::StrCat("has no ", name, " attribute"));
    std::int64_t count = 0;
    if (!absl::SimpleAtoi(attribute.value(), &count) || count < 0) {
      return Error(node, absl::StrCat(name, "=", Quote(attribute.value()),
                                      " is not a non-negative integer"));
    }
    return count;
  }

  std::string CountSource(pugi::xml_node node, const char* name) const {
    return absl::StrCat(name, "=\"", node.attribute(name).value(), "\" of <", NameOf(node),
                        "> (line ", LineOf(node), ")");
  }

  // ---- DataArrays ----

  absl::StatusOr<DataArray> ReadArray(pugi::xml_node node, Expected expected) {
    DataArray array;
    array.name = node.attribute("Name").value();
    // Not well-formed XML 1.0, which pugixml does not check: such a name could not be written back.
    for (const char c : array.name) {
      if (static_cast<unsigned char>(c) < 0x20 && c != '\t' && c != '\n' && c != '\r') {
        return Error(node, "Name holds a control character, which XML cannot carry");
      }
    }
    const absl::string_view type_name = node.attribute("type").value();
    const std::optional<VtkDataType> type = vtu::ParseXmlTypeName(type_name);
    if (!type) {
      return Error(node, absl::StrCat("type ", Quote(type_name), " is not supported; expected ",
                                      vtu::XmlTypeNames()));
    }
    array.type = *type;
    if (expected.integers_only && !IsIntegerType(array.type)) {
      return Error(node, absl::StrCat("must have an integer type, not ", type_name));
    }
    // Firedrake writes NumberOfComponents="" for one component.
    const absl::string_view components_text = node.attribute("NumberOfComponents").value();
    if (!components_text.empty() && (!absl::SimpleAtoi(components_text, &array.components) ||
                                     array.components < 1 || array.components > kMaxComponents)) {
      return Error(node, absl::StrCat("NumberOfComponents=", Quote(components_text),
                                      " is not an integer in [1, ", kMaxComponents, "]"));
    }
    if (expected.components > 0 && array.components != expected.components) {
      return Error(node, absl::StrCat("has ", array.components, " components; expected ",
                                      expected.components));
    }
    if (node.attribute("NumberOfTuples")) {
      absl::StatusOr<std::int64_t> tuples = CountAttribute(node, "NumberOfTuples");
      if (!tuples.ok()) return tuples.status();
      if (expected.tuples >= 0 && *tuples != expected.tuples) {
        return Error(node, absl::StrCat("NumberOfTuples=\"", *tuples, "\" disagrees with ",
                                        expected.source));
      }
      if (expected.tuples < 0) {
        expected.tuples = *tuples;
        expected.source = absl::StrCat("its NumberOfTuples=\"", *tuples, "\"");
      }
    }
    std::int64_t expected_values = -1;
    if (expected.tuples >= 0) {
      if (expected.tuples > std::numeric_limits<std::int64_t>::max() / 8 / array.components) {
        return Error(node, absl::StrCat(expected.source, " is impossibly large"));
      }
      expected_values = expected.tuples * array.components;
    }

    const absl::string_view format =
        node.attribute("format") ? node.attribute("format").value() : "ascii";
    absl::Status status;
    if (format == "ascii") {
      status = ReadAscii(node, expected_values, array);
    } else if (format == "binary" || format == "appended") {
      status = ReadBinary(node, format == "appended", expected_values, array);
    } else {
      return Error(node, absl::StrCat("format ", Quote(format),
                                      " is not supported; expected ascii, binary or appended"));
    }
    if (!status.ok()) return status;

    const std::int64_t count = array.value_count();
    if (expected_values >= 0 && count != expected_values) {
      return Error(node, absl::StrCat("holds ", count, " values, but ", expected.source, " needs ",
                                      expected_values, " (", expected.tuples, " tuples of ",
                                      array.components, " components)"));
    }
    if (count % array.components != 0) {
      return Error(node, absl::StrCat("holds ", count, " values, not a whole number of ",
                                      array.components, "-component tuples"));
    }
    return array;
  }

  // The data text of a DataArray: its first text child (VTK writes <InformationKey> elements
  // before it) and where that starts.
  static pugi::xml_node TextChild(pugi::xml_node node) {
    for (const pugi::xml_node child : node.children()) {
      if (child.type() == pugi::node_pcdata || child.type() == pugi::node_cdata) return child;
    }
    return {};
  }

  absl::Status ReadAscii(pugi::xml_node node, std::int64_t expected_values, DataArray& array) {
    const pugi::xml_node text_node = TextChild(node);
    const absl::string_view text = text_node ? text_node.value() : "";
    const bool integer = IsIntegerType(array.type);
    // Each value takes at least one character and a separator.
    const auto room = static_cast<std::int64_t>(text.size() / 2 + 1);
    const std::int64_t reserve = expected_values >= 0 ? std::min(expected_values, room) : 0;
    if (integer) {
      array.integers.reserve(reserve);
    } else {
      array.reals.reserve(reserve);
    }
    std::size_t at = 0;
    std::int64_t index = 0;
    while (true) {
      while (at < text.size() && IsAsciiSpace(text[at])) ++at;
      if (at == text.size()) break;
      std::size_t end = at;
      while (end < text.size() && !IsAsciiSpace(text[end])) ++end;
      const absl::string_view token = text.substr(at, end - at);
      if (expected_values >= 0 && index == expected_values) {
        return ErrorAtLine(
            TokenLine(text_node, at), node,
            absl::StrCat("holds more than the ", expected_values, " values expected"));
      }
      bool ok = false;
      if (integer) {
        const std::optional<std::int64_t> value = ParseIntegerToken(token, array.type);
        if (value) array.integers.push_back(*value);
        ok = value.has_value();
      } else {
        const std::optional<double> value = ParseRealToken(token);
        if (value) array.reals.push_back(*value);
        ok = value.has_value();
      }
      if (!ok) {
        const VtkDataTypeInfo& info = DataTypeInfo(array.type);
        const std::string wanted =
            !integer ? std::string("a number")
            : info.is_signed || info.binary_size < 8
                ? absl::StrCat("an integer of type ", node.attribute("type").value(), " in [",
                               info.min, ", ", info.max, "]")
                : absl::StrCat("an integer of type ", node.attribute("type").value());
        return ErrorAtLine(
            TokenLine(text_node, at), node,
            absl::StrCat("value ", index + 1, " is ", Quote(token), "; expected ", wanted));
      }
      ++index;
      at = end;
    }
    return absl::OkStatus();
  }

  std::int64_t TokenLine(pugi::xml_node text_node, std::size_t at) const {
    const absl::string_view text = text_node.value();
    return LineOf(text_node) + std::count(text.begin(), text.begin() + at, '\n');
  }

  absl::Status ReadBinary(pugi::xml_node node, bool appended, std::int64_t expected_values,
                          DataArray& array) {
    any_binary_ = true;
    any_appended_ = any_appended_ || appended;
    if (!compressor_.empty() && !framing_.zlib) {
      return Error(node, absl::StrCat("the file's compressor ", Quote(compressor_), " (line ",
                                      LineOf(document_.document_element()),
                                      ") is not supported; getme reads uncompressed data and ",
                                      kZlibCompressor));
    }
    const int size = DataTypeInfo(array.type).binary_size;
    const std::int64_t expected_bytes = expected_values >= 0 ? expected_values * size : -1;
    absl::string_view payload;
    std::string decoded;
    if (appended) {
      absl::StatusOr<absl::string_view> found = AppendedPayload(node);
      if (!found.ok()) return found.status();
      payload = *found;
    } else {
      const pugi::xml_node text_node = TextChild(node);
      payload = text_node ? text_node.value() : "";
    }
    if (!appended || !appended_raw_) {
      absl::StatusOr<std::string> bytes = vtu::DecodeBase64(payload);
      if (!bytes.ok()) return Error(node, bytes.status().message());
      decoded = std::move(*bytes);
      payload = decoded;
    }
    absl::StatusOr<std::string> data = vtu::DecodePayload(payload, framing_, expected_bytes);
    if (!data.ok()) return Error(node, absl::StrCat("binary data: ", data.status().message()));
    if (data->size() % size != 0) {
      return Error(node, absl::StrCat("holds ", data->size(), " bytes, not a whole number of ",
                                      size, "-byte ", node.attribute("type").value(), " values"));
    }
    vtu::DecodeValues(*data, array.type, framing_.byte_order, array);
    return absl::OkStatus();
  }

  absl::StatusOr<absl::string_view> AppendedPayload(pugi::xml_node node) const {
    absl::StatusOr<std::int64_t> offset = CountAttribute(node, "offset");
    if (!offset.ok()) return offset.status();
    if (!has_appended_) {
      return Error(node, "format=\"appended\", but the file has no <AppendedData> section");
    }
    const auto size = static_cast<std::int64_t>(appended_.size());
    if (*offset >= size) {
      return Error(node, absl::StrCat("offset ", *offset, " is beyond the ", size,
                                      " bytes of <AppendedData> (line ", appended_line_, ")"));
    }
    if (appended_raw_) return appended_.substr(*offset);
    const auto next = std::upper_bound(appended_offsets_.begin(), appended_offsets_.end(), *offset);
    const std::int64_t end = next == appended_offsets_.end() ? size : std::min(*next, size);
    return appended_.substr(*offset, end - *offset);
  }

  // ---- Pieces ----

  absl::StatusOr<Piece> ReadPiece(pugi::xml_node node) {
    Piece piece;
    piece.node = node;
    absl::StatusOr<std::int64_t> point_count = CountAttribute(node, "NumberOfPoints");
    if (!point_count.ok()) return point_count.status();
    absl::StatusOr<std::int64_t> cell_count = CountAttribute(node, "NumberOfCells");
    if (!cell_count.ok()) return cell_count.status();

    piece.points.components = 3;
    if (const pugi::xml_node points = node.child("Points")) {
      const pugi::xml_node array = points.child("DataArray");
      if (!array) return Error(points, "holds no DataArray");
      absl::StatusOr<DataArray> read =
          ReadArray(array, {*point_count, CountSource(node, "NumberOfPoints"), 3, false});
      if (!read.ok()) return read.status();
      piece.points = std::move(*read);
      piece.points.name.clear();  // the model's points are unnamed, as the legacy reader's
    } else if (*point_count > 0) {
      return Error(
          node, absl::StrCat("has NumberOfPoints=\"", *point_count, "\" but no <Points> element"));
    }
    if (absl::Status status = ReadCells(node, *point_count, *cell_count, piece.cells);
        !status.ok()) {
      return status;
    }
    if (const pugi::xml_node data = node.child("PointData")) {
      if (absl::Status status = ReadAttributes(
              data, *point_count, CountSource(node, "NumberOfPoints"), piece.point_data);
          !status.ok()) {
        return status;
      }
    }
    if (const pugi::xml_node data = node.child("CellData")) {
      if (absl::Status status = ReadAttributes(data, *cell_count,
                                               CountSource(node, "NumberOfCells"), piece.cell_data);
          !status.ok()) {
        return status;
      }
    }
    return piece;
  }

  absl::Status ReadCells(pugi::xml_node piece, std::int64_t point_count, std::int64_t cell_count,
                         GridCells& cells) {
    const pugi::xml_node node = piece.child("Cells");
    if (!node) {
      if (cell_count == 0) return absl::OkStatus();
      return Error(piece,
                   absl::StrCat("has NumberOfCells=\"", cell_count, "\" but no <Cells> element"));
    }
    pugi::xml_node connectivity_node;
    pugi::xml_node offsets_node;
    pugi::xml_node types_node;
    for (const pugi::xml_node child : node.children("DataArray")) {
      const absl::string_view name = child.attribute("Name").value();
      if (name == "connectivity") connectivity_node = child;
      if (name == "offsets") offsets_node = child;
      if (name == "types") types_node = child;
      if (name == "faces" || name == "faceoffsets") {
        return Error(child,
                     "polyhedron cells (faces / faceoffsets) are not supported; getme reads "
                     "tetrahedra, hexahedra, wedges, pyramids and linear cells of dimension 0-2");
      }
    }
    for (const auto& [found, name] :
         {std::pair{connectivity_node, "connectivity"}, std::pair{offsets_node, "offsets"},
          std::pair{types_node, "types"}}) {
      if (!found) return Error(node, absl::StrCat("has no DataArray named '", name, "'"));
    }
    const std::string source = CountSource(piece, "NumberOfCells");
    absl::StatusOr<DataArray> connectivity = ReadArray(connectivity_node, {-1, "", 1, true});
    if (!connectivity.ok()) return connectivity.status();
    absl::StatusOr<DataArray> offsets = ReadArray(offsets_node, {cell_count, source, 1, true});
    if (!offsets.ok()) return offsets.status();
    absl::StatusOr<DataArray> types = ReadArray(types_node, {cell_count, source, 1, true});
    if (!types.ok()) return types.status();

    // VTK XML offsets are where each cell ends; the model's start with 0.
    const std::vector<std::int64_t>& ends = offsets->integers;
    const auto connectivity_size = static_cast<std::int64_t>(connectivity->integers.size());
    std::int64_t previous = 0;
    for (std::int64_t cell = 0; cell < cell_count; ++cell) {
      if (ends[cell] < previous) {
        return Error(offsets_node, cell == 0 ? absl::StrCat("offset 0 (", ends[0], ") is negative")
                                             : absl::StrCat("offset ", cell, " (", ends[cell],
                                                            ") is smaller than offset ", cell - 1,
                                                            " (", previous, ")"));
      }
      previous = ends[cell];
    }
    if (previous != connectivity_size) {
      return Error(offsets_node,
                   absl::StrCat(cell_count == 0 ? "there are no cells" : "the last offset is ",
                                cell_count == 0 ? "" : absl::StrCat(previous), ", but ",
                                Describe(connectivity_node), " (line ", LineOf(connectivity_node),
                                ") holds ", connectivity_size, " node ids"));
    }
    std::int64_t start = 0;
    for (std::int64_t cell = 0; cell < cell_count; ++cell) {
      const std::int64_t code = types->integers[cell];
      const std::optional<VtkCellTypeInfo> info =
          code >= 0 && code <= 255 ? CellTypeInfo(static_cast<int>(code)) : std::nullopt;
      if (!info) {
        return Error(types_node, absl::StrCat("cell ", cell, " has unknown VTK cell type ", code));
      }
      if (info->code == kVtkPolyhedron) {
        return Error(types_node,
                     absl::StrCat("cell ", cell,
                                  " is a polyhedron (VTK type 42), which getme does not read"));
      }
      const std::int64_t node_count = ends[cell] - start;
      if (info->node_count >= 0 && node_count != info->node_count) {
        return Error(offsets_node,
                     absl::StrCat("cell ", cell, " is a ", info->name, " (VTK type ", info->code,
                                  ") with ", node_count, " node ids; expected ", info->node_count));
      }
      for (std::int64_t k = start; k < ends[cell]; ++k) {
        const std::int64_t id = connectivity->integers[k];
        if (id < 0 || id >= point_count) {
          return Error(connectivity_node,
                       absl::StrCat("cell ", cell, " (", info->name, ") refers to point ", id,
                                    ", but the piece has ", point_count, " points (ids 0 to ",
                                    point_count - 1, ")"));
        }
      }
      start = ends[cell];
    }
    cells.connectivity = std::move(connectivity->integers);
    cells.offsets.reserve(cell_count + 1);
    cells.offsets.insert(cells.offsets.end(), ends.begin(), ends.end());
    cells.types.reserve(cell_count);
    for (const std::int64_t code : types->integers) {
      cells.types.push_back(static_cast<std::uint8_t>(code));
    }
    return absl::OkStatus();
  }

  // The arrays of <PointData> / <CellData>, as legacy attribute sections (see vtu_reader.h).
  absl::Status ReadAttributes(pugi::xml_node node, std::int64_t tuples, const std::string& source,
                              std::vector<VtkAttribute>& attributes) {
    std::vector<bool> role_taken(vtu::XmlRoles().size(), false);
    bool after_scalars = false;
    bool in_field_group = false;
    for (const pugi::xml_node child : node.children("DataArray")) {
      absl::StatusOr<DataArray> array = ReadArray(child, {tuples, source, 0, false});
      if (!array.ok()) return array.status();
      if (array->name.empty()) return Error(child, "has no Name");
      std::optional<VtkAttributeKind> kind;
      for (std::size_t r = 0; r < vtu::XmlRoles().size() && !kind; ++r) {
        const vtu::XmlRole& role = vtu::XmlRoles()[r];
        if (!role_taken[r] && node.attribute(role.attribute.data()).value() == array->name &&
            vtu::RoleFits(role.kind, array->components)) {
          role_taken[r] = true;
          kind = role.kind;
        }
      }
      if (!kind && after_scalars && vtu::RoleFits(VtkAttributeKind::kScalars, array->components)) {
        kind = VtkAttributeKind::kScalars;
      }
      if (kind == VtkAttributeKind::kScalars) after_scalars = true;
      if (!kind) {
        if (!in_field_group) {
          attributes.push_back({VtkAttributeKind::kField, std::string(kFieldDataName), "", {}});
        }
        attributes.back().arrays.push_back(std::move(*array));
        in_field_group = true;
        continue;
      }
      in_field_group = false;
      VtkAttribute attribute;
      attribute.kind = *kind;
      attribute.name = array->name;
      if (*kind == VtkAttributeKind::kScalars) attribute.lookup_table = "default";
      attribute.arrays.push_back(std::move(*array));
      attributes.push_back(std::move(attribute));
    }
    return absl::OkStatus();
  }

  absl::Status ReadFieldData(pugi::xml_node node, std::vector<VtkAttribute>& field_data) {
    VtkAttribute field{VtkAttributeKind::kField, std::string(kFieldDataName), "", {}};
    for (const pugi::xml_node child : node.children("DataArray")) {
      absl::StatusOr<DataArray> array = ReadArray(child, {});
      if (!array.ok()) return array.status();
      if (array->name.empty()) return Error(child, "has no Name");
      field.arrays.push_back(std::move(*array));
    }
    if (!field.arrays.empty()) field_data.push_back(std::move(field));
    return absl::OkStatus();
  }

  // ---- Merging pieces ----

  // Appends `from` to `to`; false if they cannot share one array.
  static bool AppendArray(const DataArray& from, DataArray& to) {
    if (from.components != to.components || from.name != to.name ||
        IsIntegerType(from.type) != IsIntegerType(to.type) ||
        (IsIntegerType(from.type) && from.type != to.type)) {
      return false;
    }
    if (from.type != to.type) to.type = VtkDataType::kDouble;  // Float32 and Float64 pieces
    to.integers.insert(to.integers.end(), from.integers.begin(), from.integers.end());
    to.reals.insert(to.reals.end(), from.reals.begin(), from.reals.end());
    return true;
  }

  absl::Status AppendAttributes(const std::vector<VtkAttribute>& from,
                                std::vector<VtkAttribute>& to, pugi::xml_node piece,
                                absl::string_view element) const {
    const auto mismatch = [&](absl::string_view what) {
      return Error(piece, absl::StrCat("its <", element, "> ", what,
                                       "; every piece must have the arrays of the first (line ",
                                       LineOf(first_piece_), ") to be merged into one grid"));
    };
    if (from.size() != to.size()) {
      return mismatch(
          absl::StrCat("has ", from.size(), " attribute sections, the first piece's ", to.size()));
    }
    for (std::size_t i = 0; i < from.size(); ++i) {
      if (from[i].kind != to[i].kind || from[i].arrays.size() != to[i].arrays.size()) {
        return mismatch(absl::StrCat("differs in section ", i, " (", from[i].name, ")"));
      }
      for (std::size_t a = 0; a < from[i].arrays.size(); ++a) {
        if (!AppendArray(from[i].arrays[a], to[i].arrays[a])) {
          return mismatch(absl::StrCat("array '", from[i].arrays[a].name,
                                       "' differs in name, type or components"));
        }
      }
    }
    return absl::OkStatus();
  }

  absl::Status Merge(std::vector<Piece>& pieces, UnstructuredGrid& file) {
    first_piece_ = pieces.front().node;
    file.points = std::move(pieces.front().points);
    file.cells = std::move(pieces.front().cells);
    file.point_data = std::move(pieces.front().point_data);
    file.cell_data = std::move(pieces.front().cell_data);
    for (std::size_t p = 1; p < pieces.size(); ++p) {
      Piece& piece = pieces[p];
      const std::int64_t point_offset = file.point_count();
      if (!AppendArray(piece.points, file.points)) {
        return Error(piece.node, absl::StrCat("its points (", DataTypeInfo(piece.points.type).name,
                                              ") cannot be merged with the first piece's (",
                                              DataTypeInfo(file.points.type).name, ")"));
      }
      const std::int64_t connectivity_offset = file.cells.offsets.back();
      for (std::size_t i = 1; i < piece.cells.offsets.size(); ++i) {
        file.cells.offsets.push_back(piece.cells.offsets[i] + connectivity_offset);
      }
      for (const std::int64_t id : piece.cells.connectivity) {
        file.cells.connectivity.push_back(id + point_offset);
      }
      file.cells.types.insert(file.cells.types.end(), piece.cells.types.begin(),
                              piece.cells.types.end());
      if (absl::Status status =
              AppendAttributes(piece.point_data, file.point_data, piece.node, "PointData");
          !status.ok()) {
        return status;
      }
      if (absl::Status status =
              AppendAttributes(piece.cell_data, file.cell_data, piece.node, "CellData");
          !status.ok()) {
        return status;
      }
    }
    return absl::OkStatus();
  }

  absl::string_view bytes_;
  std::string xml_;  // bytes_ without the appended data
  pugi::xml_document document_;
  BinaryFraming framing_;
  std::string compressor_;
  bool has_appended_ = false;
  bool appended_raw_ = true;
  absl::string_view appended_;  // after the '_'
  std::int64_t appended_line_ = 0;
  std::vector<std::int64_t> appended_offsets_;  // sorted, base64 appended data only
  bool any_binary_ = false;
  bool any_appended_ = false;
  pugi::xml_node first_piece_;
};

}  // namespace

absl::StatusOr<MeshDocument> ParseVtu(absl::string_view bytes) { return Reader(bytes).Read(); }

}  // namespace getme::formats
