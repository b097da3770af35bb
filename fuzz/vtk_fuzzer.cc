// libFuzzer target: the VTK legacy reader (ASCII and BINARY), and the writer on what it accepts.
#include <cstddef>
#include <cstdint>

#include "absl/strings/str_cat.h"
#include "formats/vtk_reader.h"
#include "formats/vtk_writer.h"
#include "fuzz_check.h"

namespace getme::fuzz {
namespace {

// What the reader accepted, the writer writes back (in either encoding) and the reader reads
// again unchanged; writing that again gives the same bytes.
void CheckRoundTrip(const formats::VtkFile& file, formats::VtkEncoding encoding) {
  const char* name = encoding == formats::VtkEncoding::kAscii ? "ASCII" : "BINARY";
  absl::StatusOr<std::string> text = formats::SerializeVtk(file, encoding);
  CheckOk(text.status(), absl::StrCat("SerializeVtk ", name, " of a parsed file"));
  absl::StatusOr<formats::VtkFile> again = formats::ParseVtk(*text);
  CheckOk(again.status(), absl::StrCat("ParseVtk of SerializeVtk's ", name, " output"));
  CheckSameGeometry(file, *again, absl::StrCat("VTK ", name, " round trip"));
  absl::StatusOr<std::string> text_again = formats::SerializeVtk(*again, encoding);
  CheckOk(text_again.status(), absl::StrCat("SerializeVtk ", name, " of a round trip"));
  Check(*text_again == *text, absl::StrCat("VTK ", name, " output is not a fixed point"));
}

}  // namespace
}  // namespace getme::fuzz

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  getme::fuzz::QuietLogging();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace getme;
  absl::StatusOr<formats::VtkFile> file =
      formats::ParseVtk(absl::string_view(reinterpret_cast<const char*>(data), size));
  if (!file.ok()) {
    fuzz::Check(file.status().code() == absl::StatusCode::kInvalidArgument,
                absl::StrCat("ParseVtk error is not InvalidArgument: ", file.status().ToString()));
    return 0;
  }
  fuzz::CheckRoundTrip(*file, formats::VtkEncoding::kAscii);
  fuzz::CheckRoundTrip(*file, formats::VtkEncoding::kBinary);
  return 0;
}
