#include "formats/vtu/vtu_binary.h"

#include <zlib.h>

#include <bit>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "absl/status/status.h"
#include "absl/strings/escaping.h"
#include "absl/strings/str_cat.h"

namespace getme::formats::vtu {
namespace {

// zlib's deflate never compresses by more than 1032:1 (zlib technical details, "maximum
// compression factor"), so a block header claiming more is corrupt and is refused before
// anything is allocated for it.
constexpr std::int64_t kMaxZlibRatio = 1032;
constexpr std::int64_t kBlockSize = 32768;

std::uint64_t ReadUnsigned(const char* bytes, int size, ByteOrder order) {
  std::uint64_t value = 0;
  for (int i = 0; i < size; ++i) {
    const int index = order == ByteOrder::kBigEndian ? i : size - 1 - i;
    value = (value << 8) | static_cast<unsigned char>(bytes[index]);
  }
  return value;
}

void AppendUnsigned(std::string& out, std::uint64_t value, int size) {
  for (int i = 0; i < size; ++i) out.push_back(static_cast<char>((value >> (8 * i)) & 0xff));
}

// Reads header integer `index`; the caller has checked that it is inside `payload`.
absl::StatusOr<std::int64_t> HeaderValue(absl::string_view payload, const BinaryFraming& framing,
                                         std::int64_t index, absl::string_view what) {
  const std::uint64_t value = ReadUnsigned(payload.data() + index * framing.header_bytes,
                                           framing.header_bytes, framing.byte_order);
  if (value > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max())) {
    return absl::InvalidArgumentError(
        absl::StrCat("the header's ", what, " (", value, ") is impossibly large"));
  }
  return static_cast<std::int64_t>(value);
}

absl::StatusOr<std::string> DecodeUncompressed(absl::string_view payload,
                                               const BinaryFraming& framing,
                                               std::int64_t expected_bytes) {
  absl::StatusOr<std::int64_t> size = HeaderValue(payload, framing, 0, "byte count");
  if (!size.ok()) return size.status();
  if (expected_bytes >= 0 && *size != expected_bytes) {
    return absl::InvalidArgumentError(
        absl::StrCat("the header declares ", *size, " data bytes; expected ", expected_bytes));
  }
  const auto available = static_cast<std::int64_t>(payload.size()) - framing.header_bytes;
  if (*size > available) {
    return absl::InvalidArgumentError(absl::StrCat("the header declares ", *size,
                                                   " data bytes, but only ", available, " follow"));
  }
  return std::string(payload.substr(framing.header_bytes, *size));
}

absl::StatusOr<std::string> DecodeZlib(absl::string_view payload, const BinaryFraming& framing,
                                       std::int64_t expected_bytes) {
  const auto header_count = static_cast<std::int64_t>(payload.size()) / framing.header_bytes;
  if (header_count < 3) {
    return absl::InvalidArgumentError(
        absl::StrCat("the data ends inside its compression header (", payload.size(),
                     " bytes; the header alone takes ", 3 * framing.header_bytes, ")"));
  }
  absl::StatusOr<std::int64_t> blocks = HeaderValue(payload, framing, 0, "block count");
  if (!blocks.ok()) return blocks.status();
  absl::StatusOr<std::int64_t> block_size = HeaderValue(payload, framing, 1, "block size");
  if (!block_size.ok()) return block_size.status();
  absl::StatusOr<std::int64_t> last_size = HeaderValue(payload, framing, 2, "last block size");
  if (!last_size.ok()) return last_size.status();
  if (*blocks > header_count - 3) {
    return absl::InvalidArgumentError(absl::StrCat(
        "the compression header declares ", *blocks, " blocks, but the data (", payload.size(),
        " bytes) cannot hold their ", *blocks, " sizes of ", framing.header_bytes, " bytes"));
  }
  if (*last_size > *block_size) {
    return absl::InvalidArgumentError(absl::StrCat("the compression header's last block size (",
                                                   *last_size, ") exceeds its block size (",
                                                   *block_size, ")"));
  }
  auto uncompressed_size = [&](std::int64_t block) {
    return block == *blocks - 1 && *last_size != 0 ? *last_size : *block_size;
  };
  // Sizes first, all checked, so nothing is allocated for a header the file cannot back.
  const std::int64_t data_start = (3 + *blocks) * framing.header_bytes;
  std::int64_t compressed_total = 0;
  std::int64_t uncompressed_total = 0;
  std::vector<std::int64_t> compressed_sizes;
  compressed_sizes.reserve(*blocks);
  for (std::int64_t block = 0; block < *blocks; ++block) {
    absl::StatusOr<std::int64_t> compressed =
        HeaderValue(payload, framing, 3 + block, "compressed block size");
    if (!compressed.ok()) return compressed.status();
    const std::int64_t available =
        static_cast<std::int64_t>(payload.size()) - data_start - compressed_total;
    if (*compressed > available) {
      return absl::InvalidArgumentError(absl::StrCat("compressed block ", block, " of ", *blocks,
                                                     " declares ", *compressed, " bytes, but only ",
                                                     available, " follow"));
    }
    if (uncompressed_size(block) > kMaxZlibRatio * *compressed + 64) {
      return absl::InvalidArgumentError(absl::StrCat(
          "compressed block ", block, " of ", *blocks, " cannot hold ", uncompressed_size(block),
          " bytes in ", *compressed, " (zlib compresses at most ", kMaxZlibRatio, ":1)"));
    }
    compressed_total += *compressed;
    uncompressed_total += uncompressed_size(block);
    compressed_sizes.push_back(*compressed);
  }
  if (expected_bytes >= 0 && uncompressed_total != expected_bytes) {
    return absl::InvalidArgumentError(absl::StrCat("the compression header declares ",
                                                   uncompressed_total, " data bytes; expected ",
                                                   expected_bytes));
  }
  std::string data(static_cast<std::size_t>(uncompressed_total), '\0');
  std::int64_t in = data_start;
  std::int64_t out = 0;
  for (std::int64_t block = 0; block < *blocks; ++block) {
    uLongf produced = static_cast<uLongf>(uncompressed_size(block));
    const int result = uncompress(reinterpret_cast<Bytef*>(data.data() + out), &produced,
                                  reinterpret_cast<const Bytef*>(payload.data() + in),
                                  static_cast<uLong>(compressed_sizes[block]));
    if (result != Z_OK) {
      return absl::InvalidArgumentError(absl::StrCat(
          "compressed block ", block, " of ", *blocks, " is not valid zlib data (",
          result == Z_BUF_ERROR ? "truncated, or larger than its declared size" : zError(result),
          ")"));
    }
    if (static_cast<std::int64_t>(produced) != uncompressed_size(block)) {
      return absl::InvalidArgumentError(
          absl::StrCat("compressed block ", block, " of ", *blocks, " decompresses to ", produced,
                       " bytes; the header declares ", uncompressed_size(block)));
    }
    in += compressed_sizes[block];
    out += uncompressed_size(block);
  }
  return data;
}

}  // namespace

absl::StatusOr<std::string> DecodeBase64(absl::string_view text) {
  std::string decoded;
  std::string piece;
  std::size_t start = 0;
  while (start < text.size()) {
    // A piece ends after its padding.
    std::size_t end = text.find('=', start);
    if (end != absl::string_view::npos) end = text.find_first_not_of('=', end);
    if (end == absl::string_view::npos) end = text.size();
    if (!absl::Base64Unescape(text.substr(start, end - start), &piece)) {
      return absl::InvalidArgumentError(absl::StrCat("invalid base64 in characters ", start, " to ",
                                                     end - 1, " of the encoded data"));
    }
    decoded += piece;
    start = end;
  }
  return decoded;
}

absl::StatusOr<std::string> DecodePayload(absl::string_view payload, const BinaryFraming& framing,
                                          std::int64_t expected_bytes) {
  if (static_cast<std::int64_t>(payload.size()) < framing.header_bytes) {
    return absl::InvalidArgumentError(absl::StrCat("the data ends inside its header (",
                                                   payload.size(), " of ", framing.header_bytes,
                                                   " bytes)"));
  }
  return framing.zlib ? DecodeZlib(payload, framing, expected_bytes)
                      : DecodeUncompressed(payload, framing, expected_bytes);
}

void DecodeValues(absl::string_view data, VtkDataType type, ByteOrder order, DataArray& array) {
  const VtkDataTypeInfo& info = DataTypeInfo(type);
  const int size = info.binary_size;
  const std::size_t count = data.size() / size;
  if (info.is_integer) {
    array.integers.reserve(array.integers.size() + count);
    for (std::size_t i = 0; i < count; ++i) {
      const std::uint64_t raw = ReadUnsigned(data.data() + i * size, size, order);
      std::int64_t value = static_cast<std::int64_t>(raw);
      if (info.is_signed && size < 8) {
        const int shift = 64 - 8 * size;
        value = static_cast<std::int64_t>(raw << shift) >> shift;
      }
      array.integers.push_back(value);
    }
    return;
  }
  array.reals.reserve(array.reals.size() + count);
  for (std::size_t i = 0; i < count; ++i) {
    const std::uint64_t raw = ReadUnsigned(data.data() + i * size, size, order);
    array.reals.push_back(
        size == 4 ? static_cast<double>(std::bit_cast<float>(static_cast<std::uint32_t>(raw)))
                  : std::bit_cast<double>(raw));
  }
}

absl::StatusOr<EncodedPayload> EncodePayload(std::string raw, bool zlib) {
  EncodedPayload encoded;
  if (!zlib) {
    AppendUnsigned(encoded.header, raw.size(), 8);
    encoded.data = std::move(raw);
    return encoded;
  }
  const auto size = static_cast<std::int64_t>(raw.size());
  const std::int64_t blocks = (size + kBlockSize - 1) / kBlockSize;
  AppendUnsigned(encoded.header, blocks, 8);
  AppendUnsigned(encoded.header, kBlockSize, 8);
  AppendUnsigned(encoded.header, size % kBlockSize, 8);
  for (std::int64_t block = 0; block < blocks; ++block) {
    const absl::string_view input = absl::string_view(raw).substr(block * kBlockSize, kBlockSize);
    uLongf length = compressBound(static_cast<uLong>(input.size()));
    const std::size_t at = encoded.data.size();
    encoded.data.resize(at + length);
    const int result = compress2(reinterpret_cast<Bytef*>(encoded.data.data() + at), &length,
                                 reinterpret_cast<const Bytef*>(input.data()), input.size(),
                                 Z_DEFAULT_COMPRESSION);
    if (result != Z_OK) {
      return absl::InternalError(absl::StrCat("zlib compression failed: ", zError(result)));
    }
    encoded.data.resize(at + length);
    AppendUnsigned(encoded.header, length, 8);
  }
  return encoded;
}

namespace {

// Writes `values` as kSize-byte little-endian integers into `out`, which has room for them: the
// whole array at once, not a byte per push_back (a 10M-element connectivity is 80M values).
template <int kSize, typename Value, typename ToBits>
void PutLittleEndian(char* out, std::span<const Value> values, ToBits to_bits) {
  for (const Value value : values) {
    const std::uint64_t bits = to_bits(value);
    for (int i = 0; i < kSize; ++i) *out++ = static_cast<char>((bits >> (8 * i)) & 0xff);
  }
}

// Grows `out` by values.size() × size bytes and returns where they go.
template <typename Value>
char* Grow(std::string& out, std::span<const Value> values, int size) {
  const std::size_t at = out.size();
  out.resize(at + values.size() * static_cast<std::size_t>(size));
  return out.data() + at;
}

}  // namespace

void AppendIntegers(std::string& out, std::span<const std::int64_t> values, VtkDataType type) {
  const int size = DataTypeInfo(type).binary_size;
  char* at = Grow(out, values, size);
  const auto bits = [](std::int64_t value) { return static_cast<std::uint64_t>(value); };
  switch (size) {
    case 1:
      return PutLittleEndian<1>(at, values, bits);
    case 2:
      return PutLittleEndian<2>(at, values, bits);
    case 4:
      return PutLittleEndian<4>(at, values, bits);
    default:
      return PutLittleEndian<8>(at, values, bits);
  }
}

void AppendReals(std::string& out, std::span<const double> values, VtkDataType type) {
  if (type == VtkDataType::kFloat) {
    PutLittleEndian<4>(Grow(out, values, 4), values, [](double value) {
      return static_cast<std::uint64_t>(std::bit_cast<std::uint32_t>(static_cast<float>(value)));
    });
    return;
  }
  PutLittleEndian<8>(Grow(out, values, 8), values,
                     [](double value) { return std::bit_cast<std::uint64_t>(value); });
}

}  // namespace getme::formats::vtu
