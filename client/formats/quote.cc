#include "formats/quote.h"

#include "absl/strings/str_cat.h"

namespace getme::formats {

std::string Quote(absl::string_view text) {
  constexpr std::size_t kMaxShown = 40;
  if (text.size() > kMaxShown) return absl::StrCat("'", text.substr(0, kMaxShown), "…'");
  return absl::StrCat("'", text, "'");
}

}  // namespace getme::formats
