#include "events/json_output.h"

#include <charconv>
#include <cmath>

#include "absl/strings/str_cat.h"

namespace getme::events {

std::string JsonNumber(double value) {
  if (!std::isfinite(value)) return "null";
  char buffer[32];
  const auto [end, error] = std::to_chars(buffer, buffer + sizeof(buffer), value);
  return std::string(buffer, error == std::errc() ? end : buffer);
}

std::string JsonIntArray(std::span<const std::int64_t> values) {
  std::string out = "[";
  for (std::size_t i = 0; i < values.size(); ++i) {
    absl::StrAppend(&out, i > 0 ? "," : "", values[i]);
  }
  return out + "]";
}

void JsonObject::AddKey(absl::string_view key) {
  if (text_.size() > 1) text_.push_back(',');
  absl::StrAppend(&text_, JsonString(key), ":");
}

JsonObject& JsonObject::AddString(absl::string_view key, absl::string_view value) {
  AddKey(key);
  text_ += JsonString(value);
  return *this;
}

JsonObject& JsonObject::AddInt(absl::string_view key, std::int64_t value) {
  AddKey(key);
  absl::StrAppend(&text_, value);
  return *this;
}

JsonObject& JsonObject::AddDouble(absl::string_view key, double value) {
  AddKey(key);
  text_ += JsonNumber(value);
  return *this;
}

JsonObject& JsonObject::AddBool(absl::string_view key, bool value) {
  AddKey(key);
  text_ += value ? "true" : "false";
  return *this;
}

JsonObject& JsonObject::AddRaw(absl::string_view key, absl::string_view json) {
  AddKey(key);
  absl::StrAppend(&text_, json);
  return *this;
}

}  // namespace getme::events
