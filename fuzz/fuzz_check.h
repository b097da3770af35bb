#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "absl/status/status.h"
#include "absl/status/statusor.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/string_view.h"
#include "formats/mesh_document.h"
#include "formats/unstructured_grid.h"

namespace getme::fuzz {

// Reports a violated invariant and stops with a trap, so libFuzzer saves the input as a crash.
// Malformed input is not a violation: the readers must reject it with a Status; only what the
// code promises about accepted input (round trips, consistency of what it returns) is checked.
[[noreturn]] void Fail(absl::string_view what);

inline void Check(bool condition, absl::string_view what) {
  if (!condition) Fail(what);
}
// A step that must succeed on what an earlier step accepted.
void CheckOk(const absl::Status& status, absl::string_view step);

// A step on fuzzed input: true when it accepted the input; a refusal must be InvalidArgument.
bool Accepted(const absl::Status& status, absl::string_view step);

// What a reader accepted, the writer writes, the reader reads back with the same content (`same`
// compares and reports, naming `what`), and writing that again gives the same bytes. With
// `may_refuse`, the first write may refuse (InvalidArgument only) what the variant cannot hold.
template <class Document, class Serialize, class Parse, class Same>
void CheckWriteReadFixedPoint(const Document& document, Serialize serialize, Parse parse, Same same,
                              absl::string_view what, bool may_refuse = false) {
  absl::StatusOr<std::string> text = serialize(document);
  if (may_refuse && !Accepted(text.status(), absl::StrCat("writing ", what))) return;
  CheckOk(text.status(), absl::StrCat("writing ", what, " of a parsed file"));
  absl::StatusOr<Document> again = parse(*text);
  CheckOk(again.status(), absl::StrCat("reading the written ", what));
  same(document, *again, absl::StrCat(what, " round trip"));
  absl::StatusOr<std::string> text_again = serialize(*again);
  CheckOk(text_again.status(), absl::StrCat("writing ", what, " of a round trip"));
  Check(*text_again == *text, absl::StrCat(what, " output is not a fixed point"));
}

// Silences the writers' spdlog warnings (what a format cannot hold), which would otherwise cost
// more than the parsing and flood the fuzzer's output.
void QuietLogging();

// Bit-identical points (NaN equals NaN: "nan" reads back as the canonical NaN) and identical
// cells. `what` names the round trip in the failure message.
void CheckSameGeometry(const formats::UnstructuredGrid& expected,
                       const formats::UnstructuredGrid& actual, absl::string_view what);

// The volume cells (tetra, hexahedron, wedge, pyramid) with their nodes, sorted: what every
// format keeps, whatever it does with lower-dimensional cells (MEDIT also regroups cells by kind).
std::vector<std::string> VolumeCellSignature(const formats::GridCells& cells);

// Points bit-identical and the same volume cells: what a conversion to another format keeps.
void CheckSameVolumeMesh(const formats::UnstructuredGrid& expected,
                         const formats::UnstructuredGrid& actual, absl::string_view what);

const char* FormatName(formats::FileFormat format);

}  // namespace getme::fuzz
