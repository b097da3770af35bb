#include "fuzz_check.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "absl/strings/str_cat.h"
#include "spdlog/spdlog.h"

namespace getme::fuzz {
namespace {

bool SameBits(double a, double b) {
  if (std::isnan(a) && std::isnan(b)) return true;
  return std::memcmp(&a, &b, sizeof a) == 0;
}

bool IsVolumeCell(std::uint8_t type) {
  return type == 10 || type == 12 || type == 13 || type == 14;
}

void CheckSamePoints(const formats::UnstructuredGrid& expected,
                     const formats::UnstructuredGrid& actual, absl::string_view what) {
  Check(expected.point_count() == actual.point_count(),
        absl::StrCat(what, ": ", expected.point_count(), " points became ", actual.point_count()));
  const std::int64_t values = 3 * expected.point_count();
  for (std::int64_t i = 0; i < values; ++i) {
    const double a = expected.points.AsDouble(i);
    const double b = actual.points.AsDouble(i);
    if (!SameBits(a, b)) {
      Fail(absl::StrCat(what, ": coordinate ", i, " changed from ", a, " to ", b));
    }
  }
}

}  // namespace

void Fail(absl::string_view what) {
  std::fprintf(stderr, "getme fuzz invariant violated: %.*s\n", static_cast<int>(what.size()),
               what.data());
  __builtin_trap();
}

void CheckOk(const absl::Status& status, absl::string_view step) {
  if (!status.ok()) Fail(absl::StrCat(step, " failed: ", status.ToString()));
}

bool Accepted(const absl::Status& status, absl::string_view step) {
  if (status.ok()) return true;
  Check(status.code() == absl::StatusCode::kInvalidArgument,
        absl::StrCat(step, ": a refusal other than InvalidArgument: ", status.ToString()));
  return false;
}

void QuietLogging() { spdlog::set_level(spdlog::level::off); }

void CheckSameGeometry(const formats::UnstructuredGrid& expected,
                       const formats::UnstructuredGrid& actual, absl::string_view what) {
  CheckSamePoints(expected, actual, what);
  Check(expected.cells.types == actual.cells.types, absl::StrCat(what, ": cell types changed"));
  Check(expected.cells.offsets == actual.cells.offsets,
        absl::StrCat(what, ": cell offsets changed"));
  Check(expected.cells.connectivity == actual.cells.connectivity,
        absl::StrCat(what, ": cell connectivity changed"));
}

std::vector<std::string> VolumeCellSignature(const formats::GridCells& cells) {
  std::vector<std::string> signature;
  for (std::int64_t cell = 0; cell < cells.size(); ++cell) {
    if (!IsVolumeCell(cells.types[cell])) continue;
    std::string& entry = signature.emplace_back(absl::StrCat(cells.types[cell], ":"));
    for (std::int64_t k = 0; k < cells.node_count(cell); ++k) {
      absl::StrAppend(&entry, cells.nodes(cell)[k], ",");
    }
  }
  std::sort(signature.begin(), signature.end());
  return signature;
}

void CheckSameVolumeMesh(const formats::UnstructuredGrid& expected,
                         const formats::UnstructuredGrid& actual, absl::string_view what) {
  CheckSamePoints(expected, actual, what);
  Check(VolumeCellSignature(expected.cells) == VolumeCellSignature(actual.cells),
        absl::StrCat(what, ": volume cells changed"));
}

const char* FormatName(formats::FileFormat format) {
  switch (format) {
    case formats::FileFormat::kVtkLegacy:
      return "vtk";
    case formats::FileFormat::kVtkXml:
      return "vtu";
    case formats::FileFormat::kGmsh:
      return "msh";
    case formats::FileFormat::kMedit:
      return "mesh";
    case formats::FileFormat::kSu2:
      return "su2";
    case formats::FileFormat::kCgns:
      return "cgns";
    case formats::FileFormat::kExodus:
      return "exo";
    case formats::FileFormat::kOpenFoam:
      return "openfoam";
  }
  return "?";
}

}  // namespace getme::fuzz
