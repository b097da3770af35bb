// libFuzzer target: the format sniffer and the generic reader (what `getme` does with a file whose
// extension names no format), then the conversion of what it accepts to every format.
#include <cstddef>
#include <cstdint>
#include <optional>

#include "absl/strings/str_cat.h"
#include "formats/mesh_file.h"
#include "formats/su2/su2_mirrored_elements.h"
#include "fuzz_check.h"

namespace getme::fuzz {
namespace {

constexpr formats::FileFormat kFormats[] = {
    formats::FileFormat::kVtkLegacy, formats::FileFormat::kVtkXml, formats::FileFormat::kGmsh,
    formats::FileFormat::kMedit,     formats::FileFormat::kSu2,    formats::FileFormat::kCgns,
    formats::FileFormat::kExodus};

// Another format may refuse what it cannot hold (MSH: polyhedra, quadratic cells; MEDIT: voxels),
// naming it; what it writes, the sniffer recognises and the reader reads back with the same
// points and volume cells.
void CheckConversion(const formats::MeshDocument& document, formats::FileFormat format) {
  const std::string name = absl::StrCat(FormatName(document.format), " → ", FormatName(format));
  absl::StatusOr<std::string> bytes = formats::SerializeMeshDocument(
      document, format, formats::DefaultWriteOptions(document, format));
  if (!Accepted(bytes.status(), absl::StrCat(name, ": write"))) {
    Check(format != document.format,
          absl::StrCat(name, ": cannot write back what was read: ", bytes.status().ToString()));
    return;
  }
  Check(formats::SniffFormat(*bytes) == format,
        absl::StrCat(name, ": the sniffer does not recognise the written file"));
  absl::StatusOr<formats::MeshDocument> again = formats::ParseMeshDocument(*bytes, format);
  CheckOk(again.status(), absl::StrCat(name, ": reading the written file"));
  // The SU2 reader renumbers an element whose every corner is negative (a file from another
  // format may hold such inverted elements); an SU2 document's own were renumbered on reading.
  formats::UnstructuredGrid expected = document.grid;
  if (format == formats::FileFormat::kSu2) formats::RenumberMirroredCells(expected);
  CheckSameVolumeMesh(expected, again->grid, name);
}

}  // namespace
}  // namespace getme::fuzz

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  getme::fuzz::QuietLogging();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace getme;
  const absl::string_view bytes(reinterpret_cast<const char*>(data), size);
  const std::optional<formats::FileFormat> format = formats::SniffFormat(bytes);
  if (!format.has_value()) return 0;
  absl::StatusOr<formats::MeshDocument> document = formats::ParseMeshDocument(bytes, *format);
  if (!fuzz::Accepted(document.status(), "ParseMeshDocument")) return 0;
  fuzz::Check(document->format == *format, "ParseMeshDocument: document format is not the file's");
  for (const formats::FileFormat to : fuzz::kFormats) fuzz::CheckConversion(*document, to);
  return 0;
}
