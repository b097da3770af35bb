#pragma once

#include <string>

#include "absl/strings/string_view.h"

namespace getme {

// `text` as a JSON string literal, quotes included: what the CLI's --json lines and the HTTP
// gateway's error bodies write by hand. Messages may quote a file's or a client's bytes, so bytes
// that are not well-formed UTF-8 become U+FFFD and the document stays JSON (RFC 8259 requires
// UTF-8); control characters and DEL are escaped.
std::string JsonString(absl::string_view text);

}  // namespace getme
