#include "formats/exodus/exodus_netcdf_header.h"

#include <netcdf.h>

#include <cstdint>
#include <fstream>
#include <optional>

#include "absl/status/statusor.h"
#include "absl/strings/str_cat.h"

namespace getme::formats {
namespace {

constexpr std::uint32_t kAbsent = 0;
constexpr std::uint32_t kDimensionTag = 0x0A;
constexpr std::uint32_t kVariableTag = 0x0B;
constexpr std::uint32_t kAttributeTag = 0x0C;
// As in the Exodus reader: no real file needs more than 16 values per byte of file.
constexpr std::uint64_t kHeaderValuesPerFileByte = 16;

// Reads the header big-endian, as the specification writes it, never past the file's end.
class HeaderCursor {
 public:
  HeaderCursor(std::ifstream& in, std::uint64_t size, int version)
      : in_(in), size_(size), version_(version) {}

  std::uint64_t offset() const { return offset_; }
  std::uint64_t left() const { return size_ - offset_; }

  std::optional<std::uint64_t> Unsigned(int bytes) {
    if (left() < static_cast<std::uint64_t>(bytes)) return std::nullopt;
    unsigned char buffer[8] = {};
    in_.read(reinterpret_cast<char*>(buffer), bytes);
    if (!in_) return std::nullopt;
    offset_ += bytes;
    std::uint64_t value = 0;
    for (int k = 0; k < bytes; ++k) value = (value << 8) | buffer[k];
    return value;
  }
  // NON_NEG and nelems: 4 bytes, 8 in CDF-5.
  std::optional<std::uint64_t> Count() { return Unsigned(version_ == 5 ? 8 : 4); }
  bool Skip(std::uint64_t bytes) {
    if (bytes > left()) return false;
    in_.seekg(static_cast<std::streamoff>(bytes), std::ios::cur);
    offset_ += bytes;
    return static_cast<bool>(in_);
  }
  int version() const { return version_; }

 private:
  std::ifstream& in_;
  std::uint64_t size_;
  int version_;
  std::uint64_t offset_ = 4;
};

int TypeSize(std::uint64_t type, int version) {
  switch (type) {
    case 1:  // NC_BYTE
    case 2:  // NC_CHAR
      return 1;
    case 3:  // NC_SHORT
      return 2;
    case 4:  // NC_INT
    case 5:  // NC_FLOAT
      return 4;
    case 6:  // NC_DOUBLE
      return 8;
    case 7:  // NC_UBYTE (CDF-5)
      return version == 5 ? 1 : 0;
    case 8:  // NC_USHORT
      return version == 5 ? 2 : 0;
    case 9:  // NC_UINT
      return version == 5 ? 4 : 0;
    case 10:  // NC_INT64
    case 11:  // NC_UINT64
      return version == 5 ? 8 : 0;
    default:
      return 0;
  }
}

absl::Status Malformed(const HeaderCursor& cursor, absl::string_view what) {
  return absl::InvalidArgumentError(
      absl::StrCat("netCDF header, byte ", cursor.offset(), ": ", what, " does not fit the file"));
}

// A name: its length, then the characters padded to 4 bytes. netCDF 4.9.0 reads a name of any
// length from the header, but nc_inq_attname, nc_inq_dimname and nc_inq_varname copy it whole
// into the caller's buffer, which every caller (getme's header checks, the Exodus library) sizes
// NC_MAX_NAME + 1: a 517-byte attribute name overflowed getme's (found by the exodus fuzz target
// on 2026-11-28).
absl::Status SkipName(HeaderCursor& cursor, absl::string_view what) {
  const std::optional<std::uint64_t> length = cursor.Count();
  if (!length.has_value()) return Malformed(cursor, absl::StrCat(what, " name"));
  if (*length > NC_MAX_NAME) {
    return absl::InvalidArgumentError(
        absl::StrCat("netCDF header, byte ", cursor.offset(), ": ", what, " name is ", *length,
                     " bytes long; netCDF names have at most ", NC_MAX_NAME, " (NC_MAX_NAME)"));
  }
  if (!cursor.Skip((*length + 3) / 4 * 4)) return Malformed(cursor, absl::StrCat(what, " name"));
  return absl::OkStatus();
}

// A list's tag and count: ABSENT (0, 0) or `tag` and a count of entries each at least
// `smallest_entry` bytes long.
absl::StatusOr<std::uint64_t> ListCount(HeaderCursor& cursor, std::uint32_t tag,
                                        std::uint64_t smallest_entry, absl::string_view what) {
  const std::optional<std::uint64_t> found = cursor.Unsigned(4);
  const std::optional<std::uint64_t> count = cursor.Count();
  if (!found.has_value() || !count.has_value()) return Malformed(cursor, what);
  if (*found == kAbsent && *count == 0) return 0;
  if (*found != tag) {
    return absl::InvalidArgumentError(absl::StrCat("netCDF header, byte ", cursor.offset(), ": ",
                                                   what, " has tag ", *found, ", expected ", tag));
  }
  if (*count > cursor.left() / smallest_entry) return Malformed(cursor, what);
  return *count;
}

absl::Status SkipAttributes(HeaderCursor& cursor, absl::string_view owner) {
  const std::string what = absl::StrCat(owner, " attribute list");
  absl::StatusOr<std::uint64_t> count = ListCount(cursor, kAttributeTag, 12, what);
  if (!count.ok()) return count.status();
  for (std::uint64_t k = 0; k < *count; ++k) {
    if (absl::Status status = SkipName(cursor, absl::StrCat(owner, " attribute ", k));
        !status.ok()) {
      return status;
    }
    const std::optional<std::uint64_t> type = cursor.Unsigned(4);
    const std::optional<std::uint64_t> values = cursor.Count();
    if (!type.has_value() || !values.has_value()) return Malformed(cursor, what);
    const int size = TypeSize(*type, cursor.version());
    if (size == 0) {
      return absl::InvalidArgumentError(absl::StrCat("netCDF header, byte ", cursor.offset(), ": ",
                                                     what, ": unknown type ", *type));
    }
    if (*values > cursor.left() / size || !cursor.Skip((*values * size + 3) / 4 * 4)) {
      return Malformed(cursor, absl::StrCat(what, " values"));
    }
  }
  return absl::OkStatus();
}

}  // namespace

absl::Status CheckNetcdfClassicHeader(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return absl::OkStatus();
  char magic[4] = {};
  in.read(magic, 4);
  if (!in || magic[0] != 'C' || magic[1] != 'D' || magic[2] != 'F' ||
      (magic[3] != 1 && magic[3] != 2 && magic[3] != 5)) {
    return absl::OkStatus();
  }
  in.seekg(0, std::ios::end);
  const std::uint64_t size = static_cast<std::uint64_t>(in.tellg());
  in.seekg(4, std::ios::beg);
  HeaderCursor cursor(in, size, magic[3]);
  if (!cursor.Count().has_value()) return Malformed(cursor, "numrecs");

  absl::StatusOr<std::uint64_t> dimensions = ListCount(cursor, kDimensionTag, 8, "dimension list");
  if (!dimensions.ok()) return dimensions.status();
  for (std::uint64_t k = 0; k < *dimensions; ++k) {
    if (absl::Status status = SkipName(cursor, absl::StrCat("dimension ", k)); !status.ok()) {
      return status;
    }
    const std::optional<std::uint64_t> length = cursor.Count();
    if (!length.has_value()) return Malformed(cursor, "dimension length");
    if (*length > kHeaderValuesPerFileByte * size) {
      return absl::InvalidArgumentError(
          absl::StrCat("netCDF header, byte ", cursor.offset(), ": dimension ", k, " has length ",
                       *length, ", more than this ", size, "-byte file can hold"));
    }
  }
  if (absl::Status status = SkipAttributes(cursor, "global"); !status.ok()) return status;

  absl::StatusOr<std::uint64_t> variables = ListCount(cursor, kVariableTag, 24, "variable list");
  if (!variables.ok()) return variables.status();
  const int begin_bytes = cursor.version() == 1 ? 4 : 8;
  for (std::uint64_t k = 0; k < *variables; ++k) {
    const std::string what = absl::StrCat("variable ", k);
    if (absl::Status status = SkipName(cursor, what); !status.ok()) return status;
    const std::optional<std::uint64_t> rank = cursor.Count();
    if (!rank.has_value() || *rank > cursor.left() / 4) return Malformed(cursor, what);
    for (std::uint64_t d = 0; d < *rank; ++d) {
      const std::optional<std::uint64_t> id = cursor.Count();
      if (!id.has_value()) return Malformed(cursor, what);
      if (*id >= *dimensions) {
        return absl::InvalidArgumentError(absl::StrCat("netCDF header, byte ", cursor.offset(),
                                                       ": ", what, " uses dimension ", *id, " of ",
                                                       *dimensions));
      }
    }
    if (absl::Status status = SkipAttributes(cursor, what); !status.ok()) return status;
    const std::optional<std::uint64_t> type = cursor.Unsigned(4);
    if (!type.has_value() || TypeSize(*type, cursor.version()) == 0) {
      return Malformed(cursor, absl::StrCat(what, " type"));
    }
    if (!cursor.Count().has_value() || !cursor.Unsigned(begin_bytes).has_value()) {
      return Malformed(cursor, absl::StrCat(what, " size and offset"));
    }
  }
  return absl::OkStatus();
}

}  // namespace getme::formats
