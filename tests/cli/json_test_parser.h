#pragma once

#include <optional>
#include <string>
#include <vector>

namespace getme::cli::testing {

struct JsonMember;

// A strict RFC 8259 JSON parser for checking the CLI's output independently of its writer.
struct JsonValue {
  enum class Kind { kNull, kBool, kNumber, kString, kArray, kObject };
  Kind kind = Kind::kNull;
  bool boolean = false;
  double number = 0.0;
  std::string string;
  std::vector<JsonValue> array;
  // In document order. Members are their own type: std::pair may not hold the incomplete JsonValue.
  std::vector<JsonMember> object;

  // The member `key` of an object, or null if absent.
  const JsonValue* Find(const std::string& key) const;
  bool Has(const std::string& key) const { return Find(key) != nullptr; }
};

struct JsonMember {
  std::string key;
  JsonValue value;
};

// nullopt on any syntax error, including trailing characters after the value.
std::optional<JsonValue> ParseJson(const std::string& text);

}  // namespace getme::cli::testing
