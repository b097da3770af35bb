#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "absl/strings/string_view.h"
#include "formats/vtk_data_type.h"

namespace getme::formats {

// Number encoding shared by the reader and the writer: ASCII tokens and big-endian BINARY
// values of every VtkDataType except bit (packed, handled by the callers).

// An integer token of `type` within the type's range (a leading '+' is accepted; 64-bit
// unsigned values above INT64_MAX come back bit-cast); nullopt otherwise.
std::optional<std::int64_t> ParseIntegerToken(absl::string_view token, VtkDataType type);
// A floating-point token ("1", "-2.5e-3", "nan", "inf"); nullopt if it is not one entirely.
std::optional<double> ParseRealToken(absl::string_view token);

// `bytes` holds DataTypeInfo(type).binary_size bytes.
std::int64_t DecodeBigEndianInteger(const char* bytes, VtkDataType type);
double DecodeBigEndianReal(const char* bytes, VtkDataType type);
void AppendBigEndianInteger(std::string& out, std::int64_t value, VtkDataType type);
void AppendBigEndianReal(std::string& out, double value, VtkDataType type);

// The shortest decimal that reads back as exactly `value` (std::to_chars): never longer than
// %.17g and just as exact, so coordinates round-trip bit for bit.
void AppendReal(std::string& out, double value);
void AppendInteger(std::string& out, std::int64_t value, VtkDataType type);

// Whether `value` is inside the range of integer `type` (for the unsigned 64-bit types every
// stored value is: they are bit-cast).
bool IntegerFits(std::int64_t value, VtkDataType type);

}  // namespace getme::formats
