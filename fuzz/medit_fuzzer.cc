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
  if (!document.ok()) {
    fuzz::Check(
        document.status().code() == absl::StatusCode::kInvalidArgument,
        absl::StrCat("ParseMedit error is not InvalidArgument: ", document.status().ToString()));
    return 0;
  }
  absl::StatusOr<std::string> text = formats::SerializeMedit(*document, document->as_read);
  fuzz::CheckOk(text.status(), "SerializeMedit of a parsed file");
  absl::StatusOr<formats::MeshDocument> again = formats::ParseMedit(*text);
  fuzz::CheckOk(again.status(), "ParseMedit of SerializeMedit's output");
  // The writer regroups cells by kind (and drops vertex cells, which a parsed file has none of).
  fuzz::CheckSameVolumeMesh(document->grid, again->grid, "MEDIT round trip");
  absl::StatusOr<std::string> text_again = formats::SerializeMedit(*again, again->as_read);
  fuzz::CheckOk(text_again.status(), "SerializeMedit of a round trip");
  fuzz::Check(*text_again == *text, "MEDIT output is not a fixed point");
  // The .sol beside the .mesh holds the cell arrays: a parsed file's are the refs (not written
  // there), so the solution must at least be writable.
  fuzz::CheckOk(formats::SerializeMeditSolution(*document).status(), "SerializeMeditSolution");
  return 0;
}
