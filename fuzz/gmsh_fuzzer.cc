// libFuzzer target: the Gmsh MSH 2.2 / 4.1 reader (ASCII and binary), and the writer in every
// version and encoding on what it accepts.
#include <cstddef>
#include <cstdint>

#include "absl/strings/str_cat.h"
#include "formats/gmsh/gmsh_reader.h"
#include "formats/gmsh/gmsh_writer.h"
#include "fuzz_check.h"

namespace getme::fuzz {
namespace {

std::string Describe(const formats::WriteOptions& options) {
  return absl::StrCat(options.gmsh_version == formats::GmshVersion::k22 ? "2.2" : "4.1",
                      options.encoding == formats::Encoding::kAscii ? " ASCII" : " binary");
}

// In the version and encoding read, the write must succeed; in another one it may refuse what
// that variant cannot hold (e.g. a tag beyond a binary field's 32 bits), with InvalidArgument.
void CheckRoundTrip(const formats::MeshDocument& document, const formats::WriteOptions& options,
                    bool as_read) {
  CheckWriteReadFixedPoint(
      document, [&](const formats::MeshDocument& d) { return formats::SerializeGmsh(d, options); },
      [](const std::string& text) { return formats::ParseGmsh(text); },
      [](const formats::MeshDocument& a, const formats::MeshDocument& b, absl::string_view what) {
        CheckSameGeometry(a.grid, b.grid, what);
      },
      absl::StrCat("MSH ", Describe(options)), /*may_refuse=*/!as_read);
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
      formats::ParseGmsh(absl::string_view(reinterpret_cast<const char*>(data), size));
  if (!fuzz::Accepted(document.status(), "ParseGmsh")) return 0;
  for (const formats::GmshVersion version :
       {formats::GmshVersion::k22, formats::GmshVersion::k41}) {
    for (const formats::Encoding encoding :
         {formats::Encoding::kAscii, formats::Encoding::kBinary}) {
      formats::WriteOptions options = document->as_read;
      options.gmsh_version = version;
      options.encoding = encoding;
      const bool as_read =
          version == document->as_read.gmsh_version && encoding == document->as_read.encoding;
      fuzz::CheckRoundTrip(*document, options, as_read);
    }
  }
  return 0;
}
