// libFuzzer target: the CGNS reader (bytes → temporary file → CGNS library → HDF5 or ADF), and
// the writer on what it accepts. The bytes reach the CGNS library and HDF5 (or its ADF core)
// unchecked: this target fuzzes those libraries as much as getme's reader, and a crash inside
// them is reported like any other.
#include <cstddef>
#include <cstdint>

#include "absl/strings/str_cat.h"
#include "formats/cgns/cgns_reader.h"
#include "formats/cgns/cgns_writer.h"
#include "fuzz_check.h"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  getme::fuzz::QuietLogging();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace getme;
  absl::StatusOr<formats::MeshDocument> document =
      formats::ParseCgns(absl::string_view(reinterpret_cast<const char*>(data), size));
  if (!fuzz::Accepted(document.status(), "ParseCgns")) return 0;
  // The writer refuses (InvalidArgument) a zone without volume cells; what it writes must read
  // back with the same points, volume cells and boundary conditions. HDF5 files are not compared
  // byte for byte: the library may store object times.
  absl::StatusOr<std::string> bytes = formats::SerializeCgns(*document);
  if (!fuzz::Accepted(bytes.status(), "SerializeCgns of a parsed file")) return 0;
  absl::StatusOr<formats::MeshDocument> again = formats::ParseCgns(*bytes);
  fuzz::CheckOk(again.status(), "reading the written CGNS file");
  fuzz::CheckSameVolumeMesh(document->grid, again->grid, "CGNS round trip");
  fuzz::Check(again->cgns->boundary_conditions == document->cgns->boundary_conditions &&
                  again->cgns->families == document->cgns->families,
              "CGNS round trip: boundary conditions or families changed");
  return 0;
}
