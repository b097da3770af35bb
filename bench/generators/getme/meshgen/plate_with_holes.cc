#include "getme/meshgen/plate_with_holes.h"

#include <algorithm>
#include <cmath>

#include "absl/strings/str_cat.h"
#include "getme/meshgen/element_count_search.h"

namespace getme::meshgen {
namespace {

constexpr int kMargin = 1;  // cubes of tetrahedra around the plate on every side
constexpr int kMinWidth = 6;
// Up to about 300M elements, beyond the 2^31 node-id limit of the largest meshes we can index.
constexpr double kMaxWidth = 3000.0;

// Holes as fractions of the plate: centre along the length, radius relative to the width. The
// minimum radii keep both holes at any size: a grid-point centre and radius 1 take the 4 cubes
// around it, radius 1.6 the 12 cubes of a plus-shaped hole.
struct HoleSpec {
  double along, radius_per_width, min_radius;
};
constexpr HoleSpec kLargeHole = {0.30, 0.12, 1.6};
constexpr HoleSpec kSmallHole = {0.72, 0.07, 1.0};

DrillHole PlaceHole(const PlateLayout& layout, const HoleSpec& spec) {
  const int length = layout.x1 - layout.x0;
  const int width = layout.y1 - layout.y0;
  return DrillHole{static_cast<double>(layout.x0 + std::lround(spec.along * length)),
                   static_cast<double>(layout.y0 + width / 2),
                   std::max(spec.min_radius, spec.radius_per_width * width)};
}

}  // namespace

bool PlateLayout::IsPlateCube(int i, int j, int k) const {
  if (i < x0 || i >= x1 || j < y0 || j >= y1 || k < z0 || k >= z1) return false;
  for (const DrillHole& hole : holes) {
    const double dx = i + 0.5 - hole.x, dy = j + 0.5 - hole.y;
    if (dx * dx + dy * dy < hole.radius * hole.radius) return false;
  }
  return true;
}

PlateLayout PlateLayoutForWidth(double width) {
  const int plate_width = std::max(kMinWidth, static_cast<int>(std::lround(width)));
  const int plate_length = static_cast<int>(std::lround(kPlateAspect * plate_width));
  PlateLayout layout;
  layout.nx = plate_length + 2 * kMargin;
  layout.ny = plate_width + 2 * kMargin;
  layout.nz = kPlateThickness + 2 * kMargin;
  layout.x0 = layout.y0 = layout.z0 = kMargin;
  layout.x1 = kMargin + plate_length;
  layout.y1 = kMargin + plate_width;
  layout.z1 = kMargin + kPlateThickness;
  layout.holes = {PlaceHole(layout, kLargeHole), PlaceHole(layout, kSmallHole)};
  return layout;
}

CubeFillGrid FillPlate(const PlateLayout& layout) {
  CubeFillGrid grid(layout.nx, layout.ny, layout.nz, CubeFill::kCentredTets);
  for (int k = layout.z0; k < layout.z1; ++k) {
    for (int j = layout.y0; j < layout.y1; ++j) {
      for (int i = layout.x0; i < layout.x1; ++i) {
        if (layout.IsPlateCube(i, j, k)) grid.set(i, j, k, CubeFill::kHexahedron);
      }
    }
  }
  return grid;
}

absl::StatusOr<PlateLayout> PlateLayoutFor(std::int64_t target_elements) {
  const auto count = [](double width) {
    return CountCubeFill(FillPlate(PlateLayoutForWidth(width))).elements();
  };
  const double width = SizeParameterForCount(target_elements, kMinWidth, kMaxWidth, count);
  const std::int64_t elements = count(width);
  if (std::llabs(elements - target_elements) * 10 > target_elements) {
    return absl::InvalidArgumentError(absl::StrCat("PlateWithHoles: no plate comes within 10 % of ",
                                                   target_elements, " elements (the nearest has ",
                                                   elements, ")"));
  }
  return PlateLayoutForWidth(width);
}

absl::StatusOr<Mesh> PlateWithHoles(const PlateWithHolesOptions& options) {
  absl::StatusOr<PlateLayout> layout = PlateLayoutFor(options.target_elements);
  if (!layout.ok()) return layout.status();
  return MeshCubeFill(FillPlate(*layout), options.distortion, options.seed);
}

}  // namespace getme::meshgen
