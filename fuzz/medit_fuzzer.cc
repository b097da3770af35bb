// libFuzzer target: the MEDIT .mesh reader, and the .mesh and .sol writers on what it accepts.
#include <cstddef>
#include <cstdint>

#include "absl/strings/str_cat.h"
#include "formats/medit/medit_reader.h"
#include "formats/medit/medit_writer.h"
#include "fuzz_check.h"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  getme::fuzz::QuietLogging();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace getme;
  absl::StatusOr<formats::MeshDocument> document =
      formats::ParseMedit(absl::string_view(reinterpret_cast<const char*>(data), size));
  if (!fuzz::Accepted(document.status(), "ParseMedit")) return 0;
  // The writer regroups cells by kind (and drops vertex cells, which a parsed file has none of).
  fuzz::CheckWriteReadFixedPoint(
      *document,
      [](const formats::MeshDocument& d) { return formats::SerializeMedit(d, d.as_read); },
      [](const std::string& text) { return formats::ParseMedit(text); },
      [](const formats::MeshDocument& a, const formats::MeshDocument& b, absl::string_view what) {
        fuzz::CheckSameVolumeMesh(a.grid, b.grid, what);
      },
      "MEDIT");
  // The .sol beside the .mesh holds the cell arrays: a parsed file's are the refs (not written
  // there), so the solution must at least be writable.
  fuzz::CheckOk(formats::SerializeMeditSolution(*document).status(), "SerializeMeditSolution");
  return 0;
}
