// libFuzzer target: the VTK XML (.vtu) reader, and the writer in every layout on what it accepts.
#include <cstddef>
#include <cstdint>

#include "absl/strings/str_cat.h"
#include "formats/vtu/vtu_reader.h"
#include "formats/vtu/vtu_writer.h"
#include "fuzz_check.h"

namespace getme::fuzz {
namespace {

std::string Describe(const formats::WriteOptions& options) {
  if (options.encoding == formats::Encoding::kAscii) return "ascii";
  return absl::StrCat(options.vtu_layout == formats::VtuLayout::kInline ? "inline" : "appended",
                      options.vtu_compress ? " compressed" : "");
}

void CheckRoundTrip(const formats::MeshDocument& document, const formats::WriteOptions& options) {
  CheckWriteReadFixedPoint(
      document, [&](const formats::MeshDocument& d) { return formats::SerializeVtu(d, options); },
      [](const std::string& text) { return formats::ParseVtu(text); },
      [](const formats::MeshDocument& a, const formats::MeshDocument& b, absl::string_view what) {
        CheckSameGeometry(a.grid, b.grid, what);
      },
      absl::StrCat("VTU ", Describe(options)));
}

}  // namespace
}  // namespace getme::fuzz

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  getme::fuzz::QuietLogging();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace getme;
  absl::StatusOr<formats::MeshDocument> document =
      formats::ParseVtu(absl::string_view(reinterpret_cast<const char*>(data), size));
  if (!fuzz::Accepted(document.status(), "ParseVtu")) return 0;
  fuzz::CheckRoundTrip(*document, document->as_read);
  formats::WriteOptions options;
  options.encoding = formats::Encoding::kAscii;
  fuzz::CheckRoundTrip(*document, options);
  options.encoding = formats::Encoding::kBinary;
  options.vtu_layout = formats::VtuLayout::kInline;
  fuzz::CheckRoundTrip(*document, options);
  options.vtu_layout = formats::VtuLayout::kAppended;
  options.vtu_compress = true;
  fuzz::CheckRoundTrip(*document, options);
  return 0;
}
