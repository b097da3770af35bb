#pragma once

#include <cstdint>
#include <span>
#include <string>

#include "absl/strings/string_view.h"
#include "getme_support/json_string.h"

namespace getme::events {

// One flat JSON object, written on one line. There is no JSON library in the stack (Debian
// packages only) and the output is a handful of flat objects, so this is a small writer: keys in
// insertion order, strings escaped per RFC 8259, doubles in the shortest form that reads back
// to the same double (std::to_chars — as exact as %.17g, and shorter), non-finite doubles as
// null because JSON has no number for them.
class JsonObject {
 public:
  JsonObject& AddString(absl::string_view key, absl::string_view value);
  JsonObject& AddInt(absl::string_view key, std::int64_t value);
  JsonObject& AddDouble(absl::string_view key, double value);
  JsonObject& AddBool(absl::string_view key, bool value);
  // `json` must already be valid JSON (a nested object or array).
  JsonObject& AddRaw(absl::string_view key, absl::string_view json);

  std::string Build() const { return text_ + "}"; }

 private:
  void AddKey(absl::string_view key);
  std::string text_ = "{";
};

std::string JsonNumber(double value);
std::string JsonIntArray(std::span<const std::int64_t> values);

}  // namespace getme::events
