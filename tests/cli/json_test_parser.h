#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace getme::cli::testing {

// A strict RFC 8259 JSON parser for checking the CLI's output independently of its writer.
struct JsonValue {
  enum class Kind { kNull, kBool, kNumber, kString, kArray, kObject };
  Kind kind = Kind::kNull;
  bool boolean = false;
  double number = 0.0;
  std::string string;
  std::vector<JsonValue> array;
  std::vector<std::pair<std::string, JsonValue>> object;  // in document order

  // The member `key` of an object, or null if absent.
  const JsonValue* Find(const std::string& key) const;
  bool Has(const std::string& key) const { return Find(key) != nullptr; }
};

// nullopt on any syntax error, including trailing characters after the value.
std::optional<JsonValue> ParseJson(const std::string& text);

}  // namespace getme::cli::testing
