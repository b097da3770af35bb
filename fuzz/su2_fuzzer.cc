// libFuzzer target: the SU2 native mesh reader, and the writer on what it accepts.
#include <cstddef>
#include <cstdint>

#include "absl/strings/str_cat.h"
#include "formats/su2/su2_reader.h"
#include "formats/su2/su2_writer.h"
#include "fuzz_check.h"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  getme::fuzz::QuietLogging();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace getme;
  absl::StatusOr<formats::MeshDocument> document =
      formats::ParseSu2(absl::string_view(reinterpret_cast<const char*>(data), size));
  if (!fuzz::Accepted(document.status(), "ParseSu2")) return 0;
  // A parsed file's cells are the elements, then each marker's cells: the order the writer
  // writes them in, so the same grid (the mirrored elements renumbered again), markers and tail
  // come back.
  fuzz::CheckWriteReadFixedPoint(
      *document, [](const formats::MeshDocument& d) { return formats::SerializeSu2(d, d.as_read); },
      [](const std::string& text) { return formats::ParseSu2(text); },
      [](const formats::MeshDocument& a, const formats::MeshDocument& b, absl::string_view what) {
        fuzz::CheckSameGeometry(a.grid, b.grid, what);
        fuzz::Check(a.su2 == b.su2, absl::StrCat(what,
                                                 ": SU2 markers, mirrored cells or tail "
                                                 "changed"));
      },
      "SU2");
  return 0;
}
