// libFuzzer target: the Exodus II reader (bytes → temporary file → Exodus library → netCDF-3 or
// netCDF-4/HDF5), and the writer on what it accepts. The bytes reach Debian's Exodus, netCDF and
// HDF5 libraries unchecked: this target fuzzes them as much as getme's reader (which checks every
// count and index before it is used), and a crash inside them is reported like any other.
#include <cstddef>
#include <cstdint>

#include "formats/exodus/exodus_reader.h"
#include "formats/exodus/exodus_writer.h"
#include "fuzz_check.h"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  getme::fuzz::QuietLogging();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace getme;
  absl::StatusOr<formats::MeshDocument> document =
      formats::ParseExodus(absl::string_view(reinterpret_cast<const char*>(data), size));
  if (!fuzz::Accepted(document.status(), "ParseExodus")) return 0;
  // What the reader accepted, the writer writes (it may refuse only with InvalidArgument, e.g. a
  // side set face that two blocks' elements share in a way it cannot place), and that reads back
  // with the same points, cells, blocks and sets. The bytes are not compared: netCDF pads
  // and orders its header as it likes.
  absl::StatusOr<std::string> bytes = formats::SerializeExodus(*document, document->as_read);
  if (!fuzz::Accepted(bytes.status(), "SerializeExodus of a parsed file")) return 0;
  absl::StatusOr<formats::MeshDocument> again = formats::ParseExodus(*bytes);
  fuzz::CheckOk(again.status(), "reading the written Exodus file");
  fuzz::CheckSameGeometry(document->grid, again->grid, "Exodus round trip");
  fuzz::Check(again->exodus->node_sets == document->exodus->node_sets &&
                  again->exodus->side_sets == document->exodus->side_sets,
              "Exodus round trip: node sets or side sets changed");
  return 0;
}
