// libFuzzer target: the VTK legacy reader (ASCII and BINARY), and the writer on what it accepts.
#include <cstddef>
#include <cstdint>

#include "absl/strings/str_cat.h"
#include "formats/vtk_reader.h"
#include "formats/vtk_writer.h"
#include "fuzz_check.h"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  getme::fuzz::QuietLogging();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace getme;
  absl::StatusOr<formats::UnstructuredGrid> file =
      formats::ParseVtk(absl::string_view(reinterpret_cast<const char*>(data), size));
  if (!fuzz::Accepted(file.status(), "ParseVtk")) return 0;
  for (const formats::Encoding encoding : {formats::Encoding::kAscii, formats::Encoding::kBinary}) {
    fuzz::CheckWriteReadFixedPoint(
        *file,
        [&](const formats::UnstructuredGrid& f) { return formats::SerializeVtk(f, encoding); },
        [](const std::string& text) { return formats::ParseVtk(text); }, fuzz::CheckSameGeometry,
        encoding == formats::Encoding::kAscii ? "VTK ASCII" : "VTK BINARY");
  }
  return 0;
}
