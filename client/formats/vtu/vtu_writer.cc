#include "formats/vtu/vtu_writer.h"

#include <cmath>
#include <optional>
#include <span>
#include <vector>

#include "absl/status/status.h"
#include "absl/strings/escaping.h"
#include "absl/strings/str_cat.h"
#include "formats/vtk_array_checks.h"
#include "formats/vtk_cell_type.h"
#include "formats/vtk_values.h"
#include "formats/vtu/vtu_binary.h"
#include "formats/vtu/vtu_names.h"

namespace getme::formats {
namespace {

// The XML storage type of an array: float promoted to double as the legacy writer does.
VtkDataType WrittenType(const DataArray& array) {
  return vtu::XmlStorageType(TypeKeepingEveryValue(array));
}

// The values of one DataArray: integers or reals. In ASCII, a line per tuple, or per row when
// `row_ends` (where each row ends, as cell offsets) is given.
struct Values {
  std::span<const std::int64_t> integers;
  std::span<const double> reals;
  std::span<const std::int64_t> row_ends = {};
};

class Writer {
 public:
  Writer(const UnstructuredGrid& file, const WriteOptions& options)
      : file_(file),
        binary_(options.encoding == Encoding::kBinary),
        appended_(binary_ && options.vtu_layout == VtuLayout::kAppended),
        zlib_(binary_ && options.vtu_compress) {}

  absl::StatusOr<std::string> Write() {
    if (absl::Status status = CheckPoints(); !status.ok()) return status;
    if (absl::Status status = CheckCells(); !status.ok()) return status;
    absl::StrAppend(&out_,
                    "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" "
                    "byte_order=\"LittleEndian\" header_type=\"UInt64\"",
                    zlib_ ? " compressor=\"vtkZLibDataCompressor\"" : "",
                    ">\n  <UnstructuredGrid>\n");
    if (absl::Status status = WriteFieldData(); !status.ok()) return status;
    absl::StrAppend(&out_, "    <Piece NumberOfPoints=\"", file_.point_count(),
                    "\" NumberOfCells=\"", file_.cells.size(), "\">\n");
    if (absl::Status status = WriteAttributes(file_.point_data, file_.point_count(), "PointData");
        !status.ok()) {
      return status;
    }
    if (absl::Status status = WriteAttributes(file_.cell_data, file_.cells.size(), "CellData");
        !status.ok()) {
      return status;
    }
    absl::StrAppend(&out_, "      <Points>\n");
    const DataArray& points = file_.points;
    if (absl::Status status =
            WriteArray("Points", WrittenType(points), 3, -1, {points.integers, points.reals});
        !status.ok()) {
      return status;
    }
    absl::StrAppend(&out_, "      </Points>\n      <Cells>\n");
    if (absl::Status status = WriteCells(); !status.ok()) return status;
    absl::StrAppend(&out_, "      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n");
    if (appended_) {
      // meshio's reader drops everything after the last newline before </AppendedData>.
      out_.reserve(out_.size() + appended_data_.size() + 64);
      absl::StrAppend(&out_, "  <AppendedData encoding=\"raw\">\n   _", appended_data_,
                      "\n  </AppendedData>\n");
    }
    absl::StrAppend(&out_, "</VTKFile>\n");
    return std::move(out_);
  }

 private:
  // ---- Checks ----

  absl::Status CheckPoints() const {
    const DataArray& points = file_.points;
    if (points.components != 3 || points.type == VtkDataType::kBit) {
      return absl::InvalidArgumentError("Points: expected 3 components of a numeric type");
    }
    return CheckArrayForWriting(points, -1, "Points");
  }

  absl::Status CheckCells() const {
    const GridCells& cells = file_.cells;
    if (cells.offsets.size() != cells.types.size() + 1 || cells.offsets.front() != 0 ||
        cells.offsets.back() != static_cast<std::int64_t>(cells.connectivity.size())) {
      return absl::InvalidArgumentError(
          absl::StrCat("Cells: ", cells.types.size(), " cell types need ", cells.types.size() + 1,
                       " offsets from 0 to the connectivity size ", cells.connectivity.size()));
    }
    for (std::int64_t cell = 0; cell < cells.size(); ++cell) {
      const std::optional<VtkCellTypeInfo> info = CellTypeInfo(cells.types[cell]);
      if (!info) {
        return absl::InvalidArgumentError(absl::StrCat("Cells: cell ", cell,
                                                       " has unknown VTK cell type ",
                                                       static_cast<int>(cells.types[cell])));
      }
      if (info->code == kVtkPolyhedron) {
        return absl::InvalidArgumentError(
            absl::StrCat("Cells: cell ", cell,
                         " is a polyhedron (VTK type 42); getme does not write polyhedra to .vtu "
                         "(their faces need the faces / faceoffsets arrays)"));
      }
      if (cells.offsets[cell + 1] < cells.offsets[cell]) {
        return absl::InvalidArgumentError(absl::StrCat("Cells: offsets decrease at cell ", cell));
      }
      for (std::int64_t k = cells.offsets[cell]; k < cells.offsets[cell + 1]; ++k) {
        if (cells.connectivity[k] < 0 || cells.connectivity[k] >= file_.point_count()) {
          return absl::InvalidArgumentError(absl::StrCat("Cells: cell ", cell, " refers to point ",
                                                         cells.connectivity[k], ", but there are ",
                                                         file_.point_count(), " points"));
        }
      }
    }
    return absl::OkStatus();
  }

  // ---- Sections ----

  absl::Status WriteCells() {
    const GridCells& cells = file_.cells;
    // VTK XML offsets are where each cell ends.
    const std::span<const std::int64_t> ends = std::span(cells.offsets).subspan(1);
    // A line per cell, as the legacy writer's rows.
    if (absl::Status status =
            WriteArray("connectivity", VtkDataType::kLong, 1, -1, {cells.connectivity, {}, ends});
        !status.ok()) {
      return status;
    }
    if (absl::Status status = WriteArray("offsets", VtkDataType::kLong, 1, -1, {ends, {}});
        !status.ok()) {
      return status;
    }
    const std::vector<std::int64_t> types(cells.types.begin(), cells.types.end());
    return WriteArray("types", VtkDataType::kUnsignedChar, 1, -1, {types, {}});
  }

  // Every array of the grid's field data, and the lookup tables of the point and cell data.
  absl::Status WriteFieldData() {
    std::vector<std::pair<const DataArray*, std::string>> arrays;
    for (const VtkAttribute& attribute : file_.field_data) {
      for (const DataArray& array : attribute.arrays) {
        arrays.emplace_back(&array,
                            absl::StrCat("FieldData ", attribute.name, " array ", array.name));
      }
    }
    for (const auto* data : {&file_.point_data, &file_.cell_data}) {
      for (const VtkAttribute& attribute : *data) {
        if (attribute.kind != VtkAttributeKind::kLookupTable) continue;
        for (const DataArray& array : attribute.arrays) {
          arrays.emplace_back(&array, absl::StrCat("LOOKUP_TABLE ", attribute.name));
        }
      }
    }
    if (arrays.empty()) return absl::OkStatus();
    absl::StrAppend(&out_, "    <FieldData>\n");
    for (const auto& [array, what] : arrays) {
      if (absl::Status status = CheckNamedArray(*array, -1, what); !status.ok()) return status;
      if (absl::Status status = WriteArray(array->name, WrittenType(*array), array->components,
                                           array->tuple_count(), {array->integers, array->reals});
          !status.ok()) {
        return status;
      }
    }
    absl::StrAppend(&out_, "    </FieldData>\n");
    return absl::OkStatus();
  }

  absl::Status CheckNamedArray(const DataArray& array, std::int64_t tuples,
                               absl::string_view what) const {
    if (array.name.empty()) return absl::InvalidArgumentError(absl::StrCat(what, ": no name"));
    return CheckArrayForWriting(array, tuples, what);
  }

  absl::Status WriteAttributes(const std::vector<VtkAttribute>& attributes, std::int64_t tuples,
                               absl::string_view element) {
    // The section each role names, if any.
    const std::span<const vtu::XmlRole> roles = vtu::XmlRoles();
    std::vector<const VtkAttribute*> role_targets(roles.size(), nullptr);
    bool any = false;
    for (const VtkAttribute& attribute : attributes) {
      if (attribute.kind == VtkAttributeKind::kLookupTable) continue;
      any = any || !attribute.arrays.empty();
      if (attribute.arrays.size() != 1) continue;
      const VtkAttributeKind kind = attribute.kind == VtkAttributeKind::kColorScalars
                                        ? VtkAttributeKind::kScalars
                                        : attribute.kind;
      for (std::size_t r = 0; r < roles.size(); ++r) {
        if (roles[r].kind == kind && !role_targets[r] &&
            vtu::RoleFits(kind, attribute.arrays.front().components)) {
          role_targets[r] = &attribute;
        }
      }
    }
    if (!any) return absl::OkStatus();
    absl::StrAppend(&out_, "      <", element);
    for (std::size_t r = 0; r < roles.size(); ++r) {
      if (!role_targets[r]) continue;
      absl::StrAppend(&out_, " ", roles[r].attribute, "=\"");
      if (absl::Status status = AppendEscaped(role_targets[r]->arrays.front().name); !status.ok()) {
        return status;
      }
      out_.push_back('"');
    }
    absl::StrAppend(&out_, ">\n");
    for (const VtkAttribute& attribute : attributes) {
      if (attribute.kind == VtkAttributeKind::kLookupTable) continue;
      for (const DataArray& array : attribute.arrays) {
        const std::string what = absl::StrCat(element, " ", AttributeKindKeyword(attribute.kind),
                                              " ", attribute.name, " array ", array.name);
        if (absl::Status status = CheckNamedArray(array, tuples, what); !status.ok()) {
          return status;
        }
        if (absl::Status status = WriteArray(array.name, WrittenType(array), array.components, -1,
                                             {array.integers, array.reals});
            !status.ok()) {
          return status;
        }
      }
    }
    absl::StrAppend(&out_, "      </", element, ">\n");
    return absl::OkStatus();
  }

  // ---- DataArrays ----

  // `tuples` >= 0: written as NumberOfTuples (field data, whose length nothing else gives).
  absl::Status WriteArray(absl::string_view name, VtkDataType type, int components,
                          std::int64_t tuples, Values values) {
    absl::StrAppend(&out_, "        <DataArray type=\"", vtu::XmlTypeName(type), "\" Name=\"");
    if (absl::Status status = AppendEscaped(name); !status.ok()) return status;
    out_.push_back('"');
    if (components != 1) absl::StrAppend(&out_, " NumberOfComponents=\"", components, "\"");
    if (tuples >= 0) absl::StrAppend(&out_, " NumberOfTuples=\"", tuples, "\"");
    if (!binary_) {
      absl::StrAppend(&out_, " format=\"ascii\">\n");
      AppendAscii(type, components, values);
      absl::StrAppend(&out_, "        </DataArray>\n");
      return absl::OkStatus();
    }
    std::string raw;
    if (IsIntegerType(type)) {
      vtu::AppendIntegers(raw, values.integers, type);
    } else {
      vtu::AppendReals(raw, values.reals, type);
    }
    absl::StatusOr<vtu::EncodedPayload> payload = vtu::EncodePayload(std::move(raw), zlib_);
    if (!payload.ok()) return payload.status();
    if (appended_) {
      absl::StrAppend(&out_, " format=\"appended\" offset=\"", appended_data_.size(), "\"/>\n");
      absl::StrAppend(&appended_data_, payload->header, payload->data);
      return absl::OkStatus();
    }
    // VTK and meshio encode a compressed array's header apart from its blocks, and an
    // uncompressed array's byte count together with its data; readers expect just that.
    absl::StrAppend(
        &out_, " format=\"binary\">\n          ",
        zlib_ ? absl::StrCat(absl::Base64Escape(payload->header), absl::Base64Escape(payload->data))
              : absl::Base64Escape(absl::StrCat(payload->header, payload->data)),
        "\n        </DataArray>\n");
    return absl::OkStatus();
  }

  // One tuple (or row) per line, as the legacy writer.
  void AppendAscii(VtkDataType type, int components, Values values) {
    const bool integer = IsIntegerType(type);
    const std::size_t count = integer ? values.integers.size() : values.reals.size();
    std::size_t row = 0;
    bool line_start = true;
    for (std::size_t i = 0; i < count; ++i) {
      out_.append(line_start ? "          " : " ");
      if (integer) {
        AppendInteger(out_, values.integers[i], type);
      } else {
        // Float32 values are exact floats here: printed as doubles, a double reader gets the
        // same value back, not the decimal nearest to the float.
        AppendReal(out_, values.reals[i]);
      }
      bool line_end = values.row_ends.empty() && (i + 1) % components == 0;
      while (row < values.row_ends.size() &&
             values.row_ends[row] <= static_cast<std::int64_t>(i + 1)) {
        ++row;
        line_end = true;
      }
      if (line_end) out_.push_back('\n');
      line_start = line_end;
    }
    if (!line_start) out_.push_back('\n');
  }

  // XML attribute text. XML 1.0 cannot carry control characters other than tab, CR and LF at
  // all, not even as character references.
  absl::Status AppendEscaped(absl::string_view text) {
    for (const char c : text) {
      switch (c) {
        case '&':
          out_.append("&amp;");
          break;
        case '<':
          out_.append("&lt;");
          break;
        case '>':
          out_.append("&gt;");
          break;
        case '"':
          out_.append("&quot;");
          break;
        case '\t':
          out_.append("&#9;");
          break;
        case '\n':
          out_.append("&#10;");
          break;
        case '\r':
          out_.append("&#13;");
          break;
        default:
          if (static_cast<unsigned char>(c) < 0x20) {
            return absl::InvalidArgumentError(
                absl::StrCat("the array name '", absl::CHexEscape(text),
                             "' holds a control character, which XML cannot carry"));
          }
          out_.push_back(c);
      }
    }
    return absl::OkStatus();
  }

  const UnstructuredGrid& file_;
  const bool binary_;
  const bool appended_;
  const bool zlib_;
  std::string out_;
  std::string appended_data_;
};

}  // namespace

absl::StatusOr<std::string> SerializeVtu(const MeshDocument& document,
                                         const WriteOptions& options) {
  return Writer(document.grid, options).Write();
}

}  // namespace getme::formats
