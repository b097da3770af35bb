#include "formats/vtk_values.h"

#include <bit>
#include <charconv>
#include <cstring>

namespace getme::formats {
namespace {

bool IsUnsigned64(VtkDataType type) {
  return type == VtkDataType::kUnsignedLong || type == VtkDataType::kUInt64;
}

std::uint64_t ReadBigEndian(const char* bytes, int size) {
  std::uint64_t value = 0;
  for (int i = 0; i < size; ++i) {
    value = (value << 8) | static_cast<unsigned char>(bytes[i]);
  }
  return value;
}

void AppendBigEndian(std::string& out, std::uint64_t value, int size) {
  for (int i = size - 1; i >= 0; --i) {
    out.push_back(static_cast<char>((value >> (8 * i)) & 0xff));
  }
}

}  // namespace

bool IntegerFits(std::int64_t value, VtkDataType type) {
  const VtkDataTypeInfo& info = DataTypeInfo(type);
  if (IsUnsigned64(type)) return true;
  return value >= info.min && (value < 0 || static_cast<std::uint64_t>(value) <= info.max);
}

std::optional<std::int64_t> ParseIntegerToken(absl::string_view token, VtkDataType type) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  if (token.empty()) return std::nullopt;
  const char* end = token.data() + token.size();
  if (IsUnsigned64(type)) {
    std::uint64_t value = 0;
    const auto [ptr, ec] = std::from_chars(token.data(), end, value);
    if (ec != std::errc() || ptr != end) return std::nullopt;
    return std::bit_cast<std::int64_t>(value);
  }
  std::int64_t value = 0;
  const auto [ptr, ec] = std::from_chars(token.data(), end, value);
  if (ec != std::errc() || ptr != end || !IntegerFits(value, type)) return std::nullopt;
  return value;
}

std::optional<double> ParseRealToken(absl::string_view token) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  if (token.empty()) return std::nullopt;
  const char* end = token.data() + token.size();
  double value = 0.0;
  const auto [ptr, ec] = std::from_chars(token.data(), end, value);
  // result_out_of_range: a denormal or overflowing literal; from_chars leaves value untouched,
  // so it is refused rather than silently read as 0.
  if (ec != std::errc() || ptr != end) return std::nullopt;
  return value;
}

std::int64_t DecodeBigEndianInteger(const char* bytes, VtkDataType type) {
  const VtkDataTypeInfo& info = DataTypeInfo(type);
  const std::uint64_t raw = ReadBigEndian(bytes, info.binary_size);
  if (!info.is_signed || info.binary_size == 8) return static_cast<std::int64_t>(raw);
  // Sign-extend from binary_size bytes.
  const int shift = 64 - 8 * info.binary_size;
  return static_cast<std::int64_t>(raw << shift) >> shift;
}

double DecodeBigEndianReal(const char* bytes, VtkDataType type) {
  if (type == VtkDataType::kFloat) {
    return std::bit_cast<float>(static_cast<std::uint32_t>(ReadBigEndian(bytes, 4)));
  }
  return std::bit_cast<double>(ReadBigEndian(bytes, 8));
}

void AppendBigEndianInteger(std::string& out, std::int64_t value, VtkDataType type) {
  AppendBigEndian(out, static_cast<std::uint64_t>(value), DataTypeInfo(type).binary_size);
}

void AppendBigEndianReal(std::string& out, double value, VtkDataType type) {
  if (type == VtkDataType::kFloat) {
    AppendBigEndian(out, std::bit_cast<std::uint32_t>(static_cast<float>(value)), 4);
  } else {
    AppendBigEndian(out, std::bit_cast<std::uint64_t>(value), 8);
  }
}

void AppendReal(std::string& out, double value) {
  char buffer[32];
  const auto [ptr, ec] = std::to_chars(buffer, buffer + sizeof(buffer), value);
  out.append(buffer, ec == std::errc() ? ptr : buffer);
}

void AppendInteger(std::string& out, std::int64_t value, VtkDataType type) {
  char buffer[24];
  const auto [ptr, ec] = IsUnsigned64(type) ? std::to_chars(buffer, buffer + sizeof(buffer),
                                                            std::bit_cast<std::uint64_t>(value))
                                            : std::to_chars(buffer, buffer + sizeof(buffer), value);
  out.append(buffer, ec == std::errc() ? ptr : buffer);
}

}  // namespace getme::formats
