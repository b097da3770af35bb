#pragma once

#include <string>

#include "absl/strings/string_view.h"

namespace getme::formats {

// `text` in single quotes for an error message, cut to its first 40 bytes (then "…'") so that a
// message about a runaway token stays readable: Quote("Hexahedra") is "'Hexahedra'".
std::string Quote(absl::string_view text);

}  // namespace getme::formats
