#include "getme/smoothing/result_check.h"

#include <bit>
#include <cmath>
#include <limits>
#include <string>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_join.h"
#include "getme/elements/vec3.h"

namespace getme {
namespace {

// Bit equality: -0.0 differs from 0.0 and a NaN from itself is caught by the finiteness check.
bool SameBits(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

std::string Coordinates(double x, double y, double z) {
  return absl::StrCat("(", x, ", ", y, ", ", z, ")");
}

}  // namespace

ResultCheck::ResultCheck(const Mesh& mesh, std::span<const std::uint8_t> movable,
                         const BoundarySlide* slide, std::span<const std::uint8_t> sliding)
    : slide_(slide) {
  if (slide != nullptr) {
    Vec3 low = Vec3::Constant(std::numeric_limits<double>::infinity());
    Vec3 high = -low;
    for (std::int64_t i = 0; i < mesh.node_count(); ++i) {
      const Vec3 p(mesh.x()[i], mesh.y()[i], mesh.z()[i]);
      low = low.cwiseMin(p);
      high = high.cwiseMax(p);
      if (!sliding.empty() && sliding[i] && mesh.is_boundary(static_cast<NodeId>(i)))
        sliding_.push_back(static_cast<NodeId>(i));
    }
    surface_tolerance_ = 1e-9 * (high - low).norm();
  }
  for (std::int64_t i = 0; i < mesh.node_count(); ++i) {
    if (movable[i]) continue;
    immovable_.push_back(static_cast<NodeId>(i));
    x_.push_back(mesh.x()[i]);
    y_.push_back(mesh.y()[i]);
    z_.push_back(mesh.z()[i]);
  }
}

absl::Status ResultCheck::Check(const Mesh& mesh, const MeshQuality& after) const {
  const auto x = mesh.x();
  const auto y = mesh.y();
  const auto z = mesh.z();
  for (std::int64_t i = 0; i < mesh.node_count(); ++i) {
    if (!std::isfinite(x[i]) || !std::isfinite(y[i]) || !std::isfinite(z[i])) {
      return absl::InternalError(absl::StrCat("result check: node ", i,
                                              " has a non-finite coordinate ",
                                              Coordinates(x[i], y[i], z[i])));
    }
  }
  for (std::size_t k = 0; k < immovable_.size(); ++k) {
    const NodeId node = immovable_[k];
    if (!SameBits(x[node], x_[k]) || !SameBits(y[node], y_[k]) || !SameBits(z[node], z_[k])) {
      return absl::InternalError(absl::StrCat("result check: fixed node ", node, " moved from ",
                                              Coordinates(x_[k], y_[k], z_[k]), " to ",
                                              Coordinates(x[node], y[node], z[node])));
    }
  }
  for (NodeId node : sliding_) {
    const Vec3 p(x[node], y[node], z[node]);
    const double distance = slide_->DistanceToSurface(node, p);
    if (!(distance <= surface_tolerance_)) {
      return absl::InternalError(absl::StrCat(
          "result check: sliding boundary node ", node, " at ", Coordinates(p[0], p[1], p[2]),
          " is ", distance,
          " from its own surface group or feature curve of the input's boundary (allowed: ",
          surface_tolerance_, ")"));
    }
  }
  if (after.invalid > 0) {
    return absl::InternalError(absl::StrCat(
        "result check: ", after.invalid,
        " invalid element(s) in the result, first: ", absl::StrJoin(after.first_invalid, ", ")));
  }
  // Not q_min <= q_mean: for equal qualities the rounded mean may fall one ulp below them.
  const bool in_range =
      after.q_min >= 0.0 && after.q_min <= 1.0 && after.q_mean >= 0.0 && after.q_mean <= 1.0;
  if (!in_range) {  // also false for NaN
    return absl::InternalError(absl::StrCat("result check: reported quality q_min ", after.q_min,
                                            ", q_mean ", after.q_mean, " is not within [0, 1]"));
  }
  return absl::OkStatus();
}

}  // namespace getme
