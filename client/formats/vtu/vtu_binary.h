#pragma once

#include <cstdint>
#include <span>
#include <string>

#include "absl/status/statusor.h"
#include "absl/strings/string_view.h"
#include "formats/unstructured_grid.h"

namespace getme::formats::vtu {

// The framing of a file's binary arrays, from the <VTKFile> attributes (VTK file formats
// documentation, "Binary data"). Every binary array is a header and its data: uncompressed, the
// header is the data's byte count; compressed (vtkZLibDataCompressor), it is the block count,
// the uncompressed block size, the size of the last block (0: a full block) and each block's
// compressed size, followed by the zlib streams of the blocks.
enum class ByteOrder { kLittleEndian, kBigEndian };
struct BinaryFraming {
  ByteOrder byte_order = ByteOrder::kLittleEndian;
  int header_bytes = 4;  // header_type UInt32 (the default, and all VTK wrote before 6.3) or UInt64
  bool zlib = false;
};

// Base64 text that may be several padded pieces one after another: VTK and meshio encode a
// compressed array's header and its blocks separately, so padding can appear mid-text.
// Whitespace is skipped. The error names the character offset of the piece that is not base64.
absl::StatusOr<std::string> DecodeBase64(absl::string_view text);

// The data bytes of the binary array whose header starts at payload[0]; bytes after the array
// are ignored. `expected_bytes` >= 0 is checked against the header before anything is copied or
// decompressed, so a corrupt header cannot make the reader allocate more than the file holds.
absl::StatusOr<std::string> DecodePayload(absl::string_view payload, const BinaryFraming& framing,
                                          std::int64_t expected_bytes);

// Appends the values in `data` (a whole number of `type` values, `type` one of the ten XML
// storage types of vtu_names.h) to array.integers or array.reals.
void DecodeValues(absl::string_view data, VtkDataType type, ByteOrder order, DataArray& array);

// What the writer emits: UInt64 little-endian headers, blocks of 32 KiB when compressing (VTK's
// default block size).
struct EncodedPayload {
  std::string header;
  std::string data;  // the raw values, or the zlib streams of their blocks
};
// Takes `raw` by value: uncompressed, it becomes the payload's data without a copy.
absl::StatusOr<EncodedPayload> EncodePayload(std::string raw, bool zlib);

// Append values as little-endian `type` (an XML storage type; integers of it, reals of Float32
// or Float64).
void AppendIntegers(std::string& out, std::span<const std::int64_t> values, VtkDataType type);
void AppendReals(std::string& out, std::span<const double> values, VtkDataType type);

}  // namespace getme::formats::vtu
