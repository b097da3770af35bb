#include "formats/vtk_writer.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>

#include "absl/strings/str_cat.h"
#include "formats/file_io.h"
#include "formats/parallel_text.h"
#include "formats/vtk_array_checks.h"
#include "formats/vtk_cell_type.h"
#include "formats/vtk_values.h"

namespace getme::formats {
namespace {

// VTK's reader splits lines at whitespace and decodes %XX, so names carry their spaces, '%'
// and non-printable bytes as %XX.
std::string EncodeName(absl::string_view name) {
  std::string encoded;
  for (const char c : name) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte <= ' ' || byte == '%' || byte >= 0x7f) {
      constexpr char kHex[] = "0123456789ABCDEF";
      encoded.push_back('%');
      encoded.push_back(kHex[byte >> 4]);
      encoded.push_back(kHex[byte & 0xf]);
    } else {
      encoded.push_back(c);
    }
  }
  return encoded;
}

bool IsColorKind(VtkAttributeKind kind) {
  return kind == VtkAttributeKind::kColorScalars || kind == VtkAttributeKind::kLookupTable;
}

class Writer {
 public:
  Writer(const UnstructuredGrid& file, Encoding encoding, int threads)
      : file_(file), binary_(encoding == Encoding::kBinary), threads_(threads) {}

  absl::StatusOr<std::string> Write() {
    if (file_.title.find_first_of("\r\n") != std::string::npos) {
      return absl::InvalidArgumentError("the title contains a line break");
    }
    out_.reserve(SizeEstimate());
    absl::StrAppend(&out_, "# vtk DataFile Version ", file_.version_major, ".", file_.version_minor,
                    "\n", file_.title, "\n", binary_ ? "BINARY" : "ASCII",
                    "\nDATASET UNSTRUCTURED_GRID\n");
    for (const VtkAttribute& field : file_.field_data) {
      if (absl::Status status = WriteAttribute(field, -1, "dataset FIELD"); !status.ok()) {
        return status;
      }
    }
    if (absl::Status status = WritePoints(); !status.ok()) return status;
    if (absl::Status status = WriteCells(); !status.ok()) return status;
    if (!file_.point_data.empty()) {
      absl::StrAppend(&out_, "POINT_DATA ", file_.point_count(), "\n");
      for (const VtkAttribute& attribute : file_.point_data) {
        if (absl::Status status = WriteAttribute(attribute, file_.point_count(), "POINT_DATA");
            !status.ok()) {
          return status;
        }
      }
    }
    if (!file_.cell_data.empty()) {
      absl::StrAppend(&out_, "CELL_DATA ", file_.cells.size(), "\n");
      for (const VtkAttribute& attribute : file_.cell_data) {
        if (absl::Status status = WriteAttribute(attribute, file_.cells.size(), "CELL_DATA");
            !status.ok()) {
          return status;
        }
      }
    }
    return std::move(out_);
  }

 private:
  absl::Status WritePoints() {
    const DataArray& points = file_.points;
    if (points.components != 3 || points.type == VtkDataType::kBit) {
      return absl::InvalidArgumentError("POINTS: expected 3 components of a numeric type");
    }
    if (absl::Status status = CheckArrayForWriting(points, -1, "POINTS"); !status.ok())
      return status;
    const VtkDataType type = TypeKeepingEveryValue(points);
    absl::StrAppend(&out_, "POINTS ", points.tuple_count(), " ", DataTypeInfo(type).name, "\n");
    AppendValues(points, type);
    return absl::OkStatus();
  }

  absl::Status CheckCells() const {
    const GridCells& cells = file_.cells;
    if (cells.offsets.size() != cells.types.size() + 1 || cells.offsets.front() != 0 ||
        cells.offsets.back() != static_cast<std::int64_t>(cells.connectivity.size())) {
      return absl::InvalidArgumentError(
          absl::StrCat("CELLS: ", cells.types.size(), " cell types need ", cells.types.size() + 1,
                       " offsets from 0 to the connectivity size ", cells.connectivity.size()));
    }
    for (std::int64_t cell = 0; cell < cells.size(); ++cell) {
      const std::optional<VtkCellTypeInfo> info = CellTypeInfo(cells.types[cell]);
      if (!info) {
        return absl::InvalidArgumentError(absl::StrCat("CELLS: cell ", cell,
                                                       " has unknown VTK cell type ",
                                                       static_cast<int>(cells.types[cell])));
      }
      if (cells.offsets[cell + 1] < cells.offsets[cell]) {
        return absl::InvalidArgumentError(absl::StrCat("CELLS: offsets decrease at cell ", cell));
      }
      if (info->code == kVtkPolyhedron) continue;
      for (std::int64_t k = cells.offsets[cell]; k < cells.offsets[cell + 1]; ++k) {
        if (cells.connectivity[k] < 0 || cells.connectivity[k] >= file_.point_count()) {
          return absl::InvalidArgumentError(absl::StrCat("CELLS: cell ", cell, " refers to point ",
                                                         cells.connectivity[k], ", but there are ",
                                                         file_.point_count(), " points"));
        }
      }
    }
    return absl::OkStatus();
  }

  absl::Status WriteCells() {
    if (absl::Status status = CheckCells(); !status.ok()) return status;
    const GridCells& cells = file_.cells;
    if (cells.size() == 0) return absl::OkStatus();
    if (file_.uses_offsets_layout()) {
      absl::StrAppend(&out_, "CELLS ", cells.offsets.size(), " ", cells.connectivity.size(),
                      "\nOFFSETS vtktypeint64\n");
      AppendIntegers(cells.offsets, VtkDataType::kInt64, 1);
      absl::StrAppend(&out_, "CONNECTIVITY vtktypeint64\n");
      if (binary_) {
        AppendIntegers(cells.connectivity, VtkDataType::kInt64, 1);
      } else {
        AppendInParallel(out_, cells.size(), 1, threads_,
                         [&](std::string& text, std::int64_t begin, std::int64_t end) {
                           for (std::int64_t cell = begin; cell < end; ++cell) {
                             AppendRow(text, cells.nodes(cell), cells.node_count(cell));
                           }
                         });
      }
    } else {
      // Classic rows are 32-bit in BINARY files.
      constexpr std::int64_t kMaxInt = std::numeric_limits<std::int32_t>::max();
      if (binary_ &&
          static_cast<std::int64_t>(cells.connectivity.size() + cells.types.size()) > kMaxInt) {
        return absl::InvalidArgumentError(
            "CELLS: more than 2^31-1 values; write file version 5.1 (OFFSETS/CONNECTIVITY)");
      }
      absl::StrAppend(&out_, "CELLS ", cells.size(), " ",
                      cells.connectivity.size() + cells.types.size(), "\n");
      if (binary_) {
        for (std::int64_t cell = 0; cell < cells.size(); ++cell) {
          const std::int64_t count = cells.node_count(cell);
          AppendBigEndianInteger(out_, count, VtkDataType::kInt);
          for (std::int64_t k = 0; k < count; ++k) {
            AppendBigEndianInteger(out_, cells.nodes(cell)[k], VtkDataType::kInt);
          }
        }
      } else {
        AppendInParallel(out_, cells.size(), 1, threads_,
                         [&](std::string& text, std::int64_t begin, std::int64_t end) {
                           for (std::int64_t cell = begin; cell < end; ++cell) {
                             const std::int64_t count = cells.node_count(cell);
                             absl::StrAppend(&text, count, count > 0 ? " " : "");
                             AppendRow(text, cells.nodes(cell), count);
                           }
                         });
      }
      if (binary_) out_.push_back('\n');
    }
    absl::StrAppend(&out_, "CELL_TYPES ", cells.size(), "\n");
    for (const std::uint8_t type : cells.types) {
      if (binary_) {
        AppendBigEndianInteger(out_, type, VtkDataType::kInt);
      } else {
        absl::StrAppend(&out_, type, "\n");
      }
    }
    if (binary_) out_.push_back('\n');
    return absl::OkStatus();
  }

  // About the file's length, reserved up front: the text then does not move while it grows (each
  // doubling of a multi-megabyte string copied it and touched fresh pages). An estimate, not a
  // bound: a longer file grows the string once more, and reserved pages it does not reach are
  // never touched. Kept near the real length all the same, so a 10M-element file does not ask
  // for gigabytes it will not use.
  std::size_t SizeEstimate() const {
    std::size_t reals = file_.points.reals.size();
    std::size_t integers = file_.points.integers.size() + file_.cells.connectivity.size() +
                           3 * file_.cells.types.size();
    for (const auto* attributes : {&file_.field_data, &file_.point_data, &file_.cell_data}) {
      for (const VtkAttribute& attribute : *attributes) {
        for (const DataArray& array : attribute.arrays) {
          reals += array.reals.size();
          integers += array.integers.size();
        }
      }
    }
    // ASCII: a shortest round-trip double is up to 24 characters (most of a mesh's are 17–20),
    // a node id or count a few; BINARY: 8 bytes at most each.
    const std::size_t per_real = binary_ ? 8 : 20;
    const std::size_t per_integer = binary_ ? 8 : 6;
    constexpr std::size_t kHeaders = 1 << 16;  // titles, keywords, counts, array names
    return reals * per_real + integers * per_integer + kHeaders;
  }

  static void AppendRow(std::string& text, const std::int64_t* values, std::int64_t count) {
    for (std::int64_t k = 0; k < count; ++k) {
      if (k > 0) text.push_back(' ');
      absl::StrAppend(&text, values[k]);
    }
    text.push_back('\n');
  }

  // `tuples` < 0: dataset-level FIELD data, whose arrays may have any length.
  absl::Status WriteAttribute(const VtkAttribute& attribute, std::int64_t tuples,
                              absl::string_view block) {
    const std::string what =
        absl::StrCat(block, " ", AttributeKindKeyword(attribute.kind), " ", attribute.name);
    if (attribute.kind == VtkAttributeKind::kField) {
      if (attribute.name.empty()) {
        return absl::InvalidArgumentError(absl::StrCat(block, ": a FIELD without a name"));
      }
      absl::StrAppend(&out_, "FIELD ", EncodeName(attribute.name), " ", attribute.arrays.size(),
                      "\n");
      for (const DataArray& array : attribute.arrays) {
        const std::string array_what = absl::StrCat(what, " array ", array.name);
        if (absl::Status status = CheckAttributeArray(array, tuples, array_what); !status.ok()) {
          return status;
        }
        const VtkDataType type = TypeKeepingEveryValue(array);
        absl::StrAppend(&out_, EncodeName(array.name), " ", array.components, " ",
                        array.tuple_count(), " ", DataTypeInfo(type).name, "\n");
        AppendValues(array, type);
      }
      return absl::OkStatus();
    }
    if (attribute.arrays.size() != 1) {
      return absl::InvalidArgumentError(
          absl::StrCat(what, ": holds ", attribute.arrays.size(), " arrays; expected 1"));
    }
    const DataArray& array = attribute.arrays.front();
    const bool lookup_table = attribute.kind == VtkAttributeKind::kLookupTable;
    if (absl::Status status = CheckAttributeArray(array, lookup_table ? -1 : tuples, what);
        !status.ok()) {
      return status;
    }
    if (IsColorKind(attribute.kind) && IsIntegerType(array.type)) {
      return absl::InvalidArgumentError(absl::StrCat(what, ": colours must be stored as reals"));
    }
    const std::string name = EncodeName(array.name);
    const VtkDataType type = TypeKeepingEveryValue(array);
    const absl::string_view type_name = DataTypeInfo(type).name;
    const absl::string_view keyword = AttributeKindKeyword(attribute.kind);
    auto expect_components = [&](int expected) -> absl::Status {
      if (array.components == expected) return absl::OkStatus();
      return absl::InvalidArgumentError(absl::StrCat(what, ": has ", array.components,
                                                     " components; ", keyword, " have ", expected));
    };
    switch (attribute.kind) {
      case VtkAttributeKind::kScalars:
        absl::StrAppend(
            &out_, "SCALARS ", name, " ", type_name, " ", array.components, "\nLOOKUP_TABLE ",
            attribute.lookup_table.empty() ? "default" : EncodeName(attribute.lookup_table), "\n");
        break;
      case VtkAttributeKind::kColorScalars:
        absl::StrAppend(&out_, "COLOR_SCALARS ", name, " ", array.components, "\n");
        AppendColors(array);
        return absl::OkStatus();
      case VtkAttributeKind::kLookupTable:
        if (absl::Status status = expect_components(4); !status.ok()) return status;
        absl::StrAppend(&out_, "LOOKUP_TABLE ", name, " ", array.tuple_count(), "\n");
        AppendColors(array);
        return absl::OkStatus();
      case VtkAttributeKind::kVectors:
      case VtkAttributeKind::kNormals:
        if (absl::Status status = expect_components(3); !status.ok()) return status;
        absl::StrAppend(&out_, keyword, " ", name, " ", type_name, "\n");
        break;
      case VtkAttributeKind::kTensors:
        if (absl::Status status = expect_components(9); !status.ok()) return status;
        absl::StrAppend(&out_, keyword, " ", name, " ", type_name, "\n");
        break;
      case VtkAttributeKind::kGlobalIds:
        if (absl::Status status = expect_components(1); !status.ok()) return status;
        absl::StrAppend(&out_, keyword, " ", name, " ", type_name, "\n");
        break;
      case VtkAttributeKind::kTextureCoordinates:
        absl::StrAppend(&out_, "TEXTURE_COORDINATES ", name, " ", array.components, " ", type_name,
                        "\n");
        break;
      case VtkAttributeKind::kField:
        break;  // handled above
    }
    AppendValues(array, type);
    return absl::OkStatus();
  }

  absl::Status CheckAttributeArray(const DataArray& array, std::int64_t tuples,
                                   absl::string_view what) const {
    if (array.name.empty()) return absl::InvalidArgumentError(absl::StrCat(what, ": no name"));
    if (absl::Status status = CheckArrayForWriting(array, -1, what); !status.ok()) return status;
    if (tuples >= 0 && array.tuple_count() != tuples) {
      return absl::InvalidArgumentError(
          absl::StrCat(what, ": has ", array.tuple_count(), " tuples; expected ", tuples));
    }
    return absl::OkStatus();
  }

  void AppendValues(const DataArray& array, VtkDataType type) {
    if (IsIntegerType(type)) {
      if (type == VtkDataType::kBit && binary_) {
        AppendBits(array.integers);
      } else {
        AppendIntegers(array.integers, type, array.components);
      }
      return;
    }
    if (binary_) {
      for (const double value : array.reals) AppendBigEndianReal(out_, value, type);
      out_.push_back('\n');
      return;
    }
    const std::vector<double>& reals = array.reals;
    const std::int64_t components = array.components;
    AppendInParallel(out_, static_cast<std::int64_t>(reals.size()), components, threads_,
                     [&](std::string& text, std::int64_t begin, std::int64_t end) {
                       for (std::int64_t i = begin; i < end; ++i) {
                         // A float array's values are exact floats here: printed as doubles, a
                         // double reader (ours) gets the same value back, not the decimal
                         // nearest to the float.
                         AppendReal(text, reals[i]);
                         text.push_back((i + 1) % components == 0 ? '\n' : ' ');
                       }
                     });
  }

  void AppendIntegers(const std::vector<std::int64_t>& values, VtkDataType type, int components) {
    if (binary_) {
      for (const std::int64_t value : values) AppendBigEndianInteger(out_, value, type);
      out_.push_back('\n');
      return;
    }
    AppendInParallel(out_, static_cast<std::int64_t>(values.size()), components, threads_,
                     [&](std::string& text, std::int64_t begin, std::int64_t end) {
                       for (std::int64_t i = begin; i < end; ++i) {
                         AppendInteger(text, values[i], type);
                         text.push_back((i + 1) % components == 0 ? '\n' : ' ');
                       }
                     });
  }

  void AppendBits(const std::vector<std::int64_t>& bits) {
    for (std::size_t i = 0; i < bits.size(); i += 8) {
      unsigned byte = 0;
      for (std::size_t k = 0; k < 8; ++k) {
        const bool set = i + k < bits.size() && bits[i + k] != 0;
        byte |= (set ? 1u : 0u) << (7 - k);
      }
      out_.push_back(static_cast<char>(byte));
    }
    out_.push_back('\n');
  }

  void AppendColors(const DataArray& array) {
    if (!binary_) {
      AppendValues(array, VtkDataType::kDouble);
      return;
    }
    for (const double value : array.reals) {
      const double clamped = std::isnan(value) ? 0.0 : std::clamp(value, 0.0, 1.0);
      out_.push_back(static_cast<char>(static_cast<unsigned char>(std::lround(clamped * 255.0))));
    }
    out_.push_back('\n');
  }

  const UnstructuredGrid& file_;
  const bool binary_;
  const int threads_;  // for the ASCII numbers (AppendInParallel): the bytes do not depend on it
  std::string out_;
};

}  // namespace

absl::StatusOr<std::string> SerializeVtk(const UnstructuredGrid& file, Encoding encoding,
                                         int threads) {
  return Writer(file, encoding, threads).Write();
}

absl::Status WriteVtkFile(const std::string& path, const UnstructuredGrid& file,
                          Encoding encoding) {
  absl::StatusOr<std::string> bytes = SerializeVtk(file, encoding);
  if (!bytes.ok()) {
    return absl::Status(bytes.status().code(),
                        absl::StrCat("cannot write '", path, "': ", bytes.status().message()));
  }
  return WriteFileAtomically(path, *bytes);
}

}  // namespace getme::formats
