#include "getme/meshgen/ring_in_block.h"

#include <algorithm>
#include <cmath>

#include "absl/strings/str_cat.h"
#include "getme/meshgen/element_count_search.h"

namespace getme::meshgen {
namespace {

constexpr double kMinResolution = 0.5;
// About 260M elements: beyond the 2^31 limits of the largest meshes we can index.
constexpr double kMaxResolution = 12.0;

int CubesAlong(double length, double cubes_per_unit) {
  return std::max(1, static_cast<int>(std::lround(length * cubes_per_unit)));
}

}  // namespace

double RingLayout::DistanceFromCentreCircle(double x, double y, double z) const {
  const double radial = std::hypot(x - centre_x, y - centre_y) - major_radius;
  return std::hypot(radial, z - centre_z);
}

RingLayout RingLayoutForResolution(double cubes_per_unit) {
  RingLayout layout;
  layout.cubes_per_unit = std::max(kMinResolution, cubes_per_unit);
  layout.nx = CubesAlong(kRingBlockX, layout.cubes_per_unit);
  layout.ny = CubesAlong(kRingBlockY, layout.cubes_per_unit);
  layout.nz = CubesAlong(kRingBlockZ, layout.cubes_per_unit);
  layout.centre_x = 0.5 * layout.nx;
  layout.centre_y = 0.5 * layout.ny;
  layout.centre_z = 0.5 * layout.nz;
  layout.major_radius = kRingMajorRadius * layout.cubes_per_unit;
  layout.tube_radius = kRingTubeRadius * layout.cubes_per_unit;
  layout.band_radius = (kRingTubeRadius + kRingBandWidth) * layout.cubes_per_unit;
  return layout;
}

CubeFillGrid FillRing(const RingLayout& layout) {
  CubeFillGrid grid(layout.nx, layout.ny, layout.nz, CubeFill::kHexahedron);
  for (int k = 0; k < layout.nz; ++k) {
    for (int j = 0; j < layout.ny; ++j) {
      for (int i = 0; i < layout.nx; ++i) {
        const double distance = layout.DistanceFromCentreCircle(i + 0.5, j + 0.5, k + 0.5);
        if (distance < layout.tube_radius) {
          grid.set(i, j, k, CubeFill::kEmpty);
        } else if (distance < layout.band_radius) {
          grid.set(i, j, k, CubeFill::kCentredTets);
        }
      }
    }
  }
  return grid;
}

absl::StatusOr<RingLayout> RingLayoutFor(std::int64_t target_elements) {
  const auto count = [](double resolution) {
    return CountCubeFill(FillRing(RingLayoutForResolution(resolution))).elements();
  };
  const double resolution =
      SizeParameterForCount(target_elements, kMinResolution, kMaxResolution, count);
  const std::int64_t elements = count(resolution);
  if (std::llabs(elements - target_elements) * 10 > target_elements) {
    return absl::InvalidArgumentError(
        absl::StrCat("RingInBlock: no ring mesh comes within 10 % of ", target_elements,
                     " elements (the nearest has ", elements, ")"));
  }
  return RingLayoutForResolution(resolution);
}

absl::StatusOr<Mesh> RingInBlock(const RingInBlockOptions& options) {
  absl::StatusOr<RingLayout> layout = RingLayoutFor(options.target_elements);
  if (!layout.ok()) return layout.status();
  return MeshCubeFill(FillRing(*layout), options.distortion, options.seed);
}

}  // namespace getme::meshgen
