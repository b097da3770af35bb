#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "absl/status/status.h"
#include "absl/strings/string_view.h"
#include "formats/mesh_document.h"
#include "formats/vtk_file.h"

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

// Silences the writers' spdlog warnings (what a format cannot hold), which would otherwise cost
// more than the parsing and flood the fuzzer's output.
void QuietLogging();

// Bit-identical points (NaN equals NaN: "nan" reads back as the canonical NaN) and identical
// cells. `what` names the round trip in the failure message.
void CheckSameGeometry(const formats::VtkFile& expected, const formats::VtkFile& actual,
                       absl::string_view what);

// The volume cells (tetra, hexahedron, wedge, pyramid) with their nodes, sorted: what every
// format keeps, whatever it does with lower-dimensional cells (MEDIT also regroups cells by kind).
std::vector<std::string> VolumeCellSignature(const formats::VtkCells& cells);

// Points bit-identical and the same volume cells: what a conversion to another format keeps.
void CheckSameVolumeMesh(const formats::VtkFile& expected, const formats::VtkFile& actual,
                         absl::string_view what);

const char* FormatName(formats::FileFormat format);

}  // namespace getme::fuzz
