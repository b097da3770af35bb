#include "getme_surface/triangle_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace getme::surface {
namespace {

// A cell's key packs its level (5 bits) and its position (19 bits an axis).
constexpr int kAxisBits = 19;
constexpr std::int64_t kAxisCells = std::int64_t{1} << kAxisBits;
constexpr int kLevels = 32;
// A triangle goes to the finest level where its box touches at most this many cells.
constexpr std::int64_t kCellsATriangle = 8;

std::int64_t CellCount(const std::array<std::array<std::int64_t, 3>, 2>& range) {
  return (range[1][0] - range[0][0] + 1) * (range[1][1] - range[0][1] + 1) *
         (range[1][2] - range[0][2] + 1);
}

// Spreads 19 bits two apart: bit b goes to bit 3b (the usual shift-and-mask ladder).
std::uint64_t SpreadBits(std::uint64_t v) {
  v &= 0x1fffff;
  v = (v | v << 32) & 0x1f00000000ffffULL;
  v = (v | v << 16) & 0x1f0000ff0000ffULL;
  v = (v | v << 8) & 0x100f00f00f00f00fULL;
  v = (v | v << 4) & 0x10c30c30c30c30c3ULL;
  v = (v | v << 2) & 0x1249249249249249ULL;
  return v;
}

// Floats at or below, and at or above, a double. Beyond the float range they saturate (to the
// largest float or an infinity, whichever keeps the bound on its side), since converting such a
// double is undefined.
float RoundedDown(double value) {
  constexpr double kLargest = std::numeric_limits<float>::max();
  if (value > kLargest) return std::numeric_limits<float>::max();
  if (!(value >= -kLargest)) return -std::numeric_limits<float>::infinity();
  const float rounded = static_cast<float>(value);
  return rounded > value ? std::nextafter(rounded, -std::numeric_limits<float>::infinity())
                         : rounded;
}

float RoundedUp(double value) { return -RoundedDown(-value); }

}  // namespace

TriangleGrid::TriangleGrid(std::span<const std::array<Vec3, 3>> triangles) {
  if (triangles.empty()) return;
  triangles_.reserve(triangles.size());
  std::vector<std::pair<Vec3, Vec3>> boxes;
  boxes.reserve(triangles.size());
  Vec3 low = Vec3::Constant(std::numeric_limits<double>::infinity());
  Vec3 high = -low;
  std::vector<double> extents;
  extents.reserve(triangles.size());
  for (const auto& [a, b, c] : triangles) {
    Prepared prepared;
    prepared.a = a;
    prepared.ab = b - a;
    prepared.ac = c - a;
    prepared.ab_ab = prepared.ab.dot(prepared.ab);
    prepared.ab_ac = prepared.ab.dot(prepared.ac);
    prepared.ac_ac = prepared.ac.dot(prepared.ac);
    triangles_.push_back(prepared);
    boxes.emplace_back(a.cwiseMin(b).cwiseMin(c), a.cwiseMax(b).cwiseMax(c));
    low = low.cwiseMin(boxes.back().first);
    high = high.cwiseMax(boxes.back().second);
    extents.push_back((boxes.back().second - boxes.back().first).maxCoeff());
  }
  origin_ = low;
  // Level 0 is sized for the median triangle. It is never so small that the surface's box needs
  // more than kAxisCells cells an axis.
  std::nth_element(extents.begin(), extents.begin() + extents.size() / 2, extents.end());
  const double span = (high - low).maxCoeff();
  cell_size_ = std::max(extents[extents.size() / 2], span / static_cast<double>(kAxisCells - 1));
  if (!(cell_size_ > 0.0) || !std::isfinite(cell_size_)) cell_size_ = 1.0;

  // Each triangle's level: the finest where its box touches at most kCellsATriangle cells.
  std::vector<int> levels(triangles_.size());
  std::array<bool, kLevels> used{};
  for (std::size_t t = 0; t < triangles_.size(); ++t) {
    int level = 0;
    while (level + 1 < kLevels &&
           CellCount(CellsOf(level, boxes[t].first, boxes[t].second)) > kCellsATriangle) {
      ++level;
    }
    levels[t] = level;
    used[static_cast<std::size_t>(level)] = true;
  }
  for (int level = 0; level < kLevels; ++level) {
    if (used[static_cast<std::size_t>(level)]) levels_.push_back(level);
  }

  // Every (cell, triangle) pair, in the order of the cells' keys (Key's comment), then each
  // cell's run of them as its list.
  std::vector<std::pair<CellKey, std::uint32_t>> entries;
  entries.reserve(triangles_.size() * 6);
  for (std::size_t t = 0; t < triangles_.size(); ++t) {
    const CellRange range = CellsOf(levels[t], boxes[t].first, boxes[t].second);
    for (std::int64_t i = range[0][0]; i <= range[1][0]; ++i) {
      for (std::int64_t j = range[0][1]; j <= range[1][1]; ++j) {
        for (std::int64_t k = range[0][2]; k <= range[1][2]; ++k) {
          entries.emplace_back(Key(levels[t], {i, j, k}), static_cast<std::uint32_t>(t));
        }
      }
    }
  }
  std::sort(entries.begin(), entries.end());
  std::size_t cell_count = 0;
  for (std::size_t e = 0; e < entries.size(); ++e) {
    cell_count += e == 0 || entries[e].first != entries[e - 1].first;
  }
  cells_.reserve(cell_count);
  members_.reserve(entries.size());
  for (std::size_t begin = 0; begin < entries.size();) {
    std::size_t end = begin;
    for (; end < entries.size() && entries[end].first == entries[begin].first; ++end) {
      const std::uint32_t t = entries[end].second;
      Member member;
      for (int axis = 0; axis < 3; ++axis) {
        member.low[static_cast<std::size_t>(axis)] = RoundedDown(boxes[t].first[axis]);
        member.high[static_cast<std::size_t>(axis)] = RoundedUp(boxes[t].second[axis]);
      }
      member.triangle = t;
      members_.push_back(member);
    }
    cells_.emplace(entries[begin].first,
                   std::pair(static_cast<std::uint32_t>(begin), static_cast<std::uint32_t>(end)));
    begin = end;
  }
}

std::array<std::int64_t, 3> TriangleGrid::CellOf(int level, const Vec3& point) const {
  const double size = std::ldexp(cell_size_, level);
  std::array<std::int64_t, 3> cell;
  for (int axis = 0; axis < 3; ++axis) {
    // Clamped as a double first, so that a point far outside cannot overflow the integer; cells
    // outside the box hold nothing, so clamping loses no triangle.
    const double index = std::clamp(std::floor((point[axis] - origin_[axis]) / size), 0.0,
                                    static_cast<double>(kAxisCells - 1));
    cell[static_cast<std::size_t>(axis)] = static_cast<std::int64_t>(index);
  }
  return cell;
}

TriangleGrid::CellRange TriangleGrid::CellsOf(int level, const Vec3& low, const Vec3& high) const {
  return {CellOf(level, low), CellOf(level, high)};
}

// The level in the top bits, then the position's bits interleaved (a Morton code): cells near
// each other in space get keys near each other, so members_, laid out in key order, keeps a
// query's few cells, and the queries of neighbouring nodes, in few cache lines.
TriangleGrid::CellKey TriangleGrid::Key(int level, const std::array<std::int64_t, 3>& cell) {
  return (static_cast<CellKey>(level) << (3 * kAxisBits)) |
         (SpreadBits(static_cast<CellKey>(cell[0])) << 2) |
         (SpreadBits(static_cast<CellKey>(cell[1])) << 1) |
         SpreadBits(static_cast<CellKey>(cell[2]));
}

// The closest point of a triangle, by the region of its plane the point projects into (Ericson,
// Real-Time Collision Detection, Sec. 5.1.5). The dot products with the corners b and c are
// those with a shifted by the triangle's own products, computed once.
Vec3 TriangleGrid::ClosestPoint(const Prepared& t, const Vec3& point) {
  const Vec3 ap = point - t.a;
  const double d1 = t.ab.dot(ap);
  const double d2 = t.ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) return t.a;
  const double d3 = d1 - t.ab_ab;  // ab · (p − b)
  const double d4 = d2 - t.ab_ac;  // ac · (p − b)
  if (d3 >= 0.0 && d4 <= d3) return t.a + t.ab;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return t.a + (d1 / (d1 - d3)) * t.ab;
  const double d5 = d1 - t.ab_ac;  // ab · (p − c)
  const double d6 = d2 - t.ac_ac;  // ac · (p − c)
  if (d6 >= 0.0 && d5 <= d6) return t.a + t.ac;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return t.a + (d2 / (d2 - d6)) * t.ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return t.a + t.ab + w * (t.ac - t.ab);
  }
  const double inverse = 1.0 / (va + vb + vc);
  return t.a + (vb * inverse) * t.ab + (vc * inverse) * t.ac;
}

std::optional<Vec3> TriangleGrid::NearestWithin(const Vec3& point, double bound) const {
  if (triangles_.empty() || !point.allFinite() || !(bound >= 0.0) || !std::isfinite(bound)) {
    return std::nullopt;
  }
  // The caller's own point lies on a triangle at `bound` exactly, which rounding may put a few
  // ulps farther: the search reaches a little beyond it so as not to miss that triangle.
  const double reach = bound * (1.0 + 1e-12) + 1e-12 * cell_size_;
  const Vec3 corner = Vec3::Constant(reach);
  std::array<CellRange, kLevels> ranges;
  for (std::size_t l = 0; l < levels_.size(); ++l) {
    ranges[l] = CellsOf(levels_[l], point - corner, point + corner);
    if (CellCount(ranges[l]) > kMaxCells) return std::nullopt;
  }
  const std::array<float, 3> at = {RoundedDown(point[0]), RoundedDown(point[1]),
                                   RoundedDown(point[2])};
  double best_squared = reach * reach;
  // The box test in floats only rejects: it must keep every triangle within the bound, so it
  // widens the bound by the rounding of the point and of the subtraction to floats.
  const float slack =
      4.0f * std::numeric_limits<float>::epsilon() *
      (std::max({std::abs(at[0]), std::abs(at[1]), std::abs(at[2])}) + RoundedUp(reach));
  float box_reach = RoundedUp(reach) + slack;
  std::optional<Vec3> best;
  for (std::size_t l = 0; l < levels_.size(); ++l) {
    const CellRange& range = ranges[l];
    for (std::int64_t i = range[0][0]; i <= range[1][0]; ++i) {
      for (std::int64_t j = range[0][1]; j <= range[1][1]; ++j) {
        for (std::int64_t k = range[0][2]; k <= range[1][2]; ++k) {
          const auto cell = cells_.find(Key(levels_[l], {i, j, k}));
          if (cell == cells_.end()) continue;
          for (std::uint32_t m = cell->second.first; m < cell->second.second; ++m) {
            const Member& member = members_[m];
            bool apart = false;
            for (std::size_t axis = 0; axis < 3; ++axis) {
              apart |= member.low[axis] - at[axis] > box_reach;
              apart |= at[axis] - member.high[axis] > box_reach;
            }
            if (apart) continue;
            const Vec3 candidate = ClosestPoint(triangles_[member.triangle], point);
            const double squared = (candidate - point).squaredNorm();
            // The first of equally near points wins: cells and members are visited in a fixed
            // order, so the answer does not depend on the thread asking.
            if (squared < best_squared || (!best && squared == best_squared)) {
              best_squared = squared;
              best = candidate;
              box_reach = std::min(box_reach, RoundedUp(std::sqrt(squared) * (1.0 + 1e-9)) + slack);
            }
          }
        }
      }
    }
  }
  return best;
}

bool TriangleGrid::TrianglesWithin(const Vec3& point, double radius, std::vector<Reach>& within,
                                   std::vector<std::uint32_t>& seen) const {
  within.clear();
  seen.clear();
  if (triangles_.empty() || !point.allFinite() || !(radius >= 0.0) || !std::isfinite(radius)) {
    return true;
  }
  const Vec3 corner = Vec3::Constant(radius);
  for (const int level : levels_) {
    const CellRange range = CellsOf(level, point - corner, point + corner);
    if (CellCount(range) > kMaxGatherCells) return false;
    for (std::int64_t i = range[0][0]; i <= range[1][0]; ++i) {
      for (std::int64_t j = range[0][1]; j <= range[1][1]; ++j) {
        for (std::int64_t k = range[0][2]; k <= range[1][2]; ++k) {
          const auto cell = cells_.find(Key(level, {i, j, k}));
          if (cell == cells_.end()) continue;
          for (std::uint32_t m = cell->second.first; m < cell->second.second; ++m) {
            // Only triangles whose box comes within the radius (the boxes are rounded outwards).
            const Member& member = members_[m];
            double outside = 0.0;
            for (std::size_t axis = 0; axis < 3; ++axis) {
              const double below = static_cast<double>(member.low[axis]) - point[axis];
              const double above = point[axis] - static_cast<double>(member.high[axis]);
              const double gap = std::max({below, above, 0.0});
              outside += gap * gap;
            }
            if (outside <= radius * radius) seen.push_back(member.triangle);
          }
        }
      }
    }
  }
  // A triangle is listed by every cell its box touches.
  std::sort(seen.begin(), seen.end());
  seen.erase(std::unique(seen.begin(), seen.end()), seen.end());
  for (const std::uint32_t t : seen) {
    const double distance = (ClosestPoint(triangles_[t], point) - point).norm();
    if (distance <= radius) within.push_back({distance, t});
  }
  std::sort(within.begin(), within.end(), [](const Reach& a, const Reach& b) {
    return a.distance != b.distance ? a.distance < b.distance : a.triangle < b.triangle;
  });
  return true;
}

}  // namespace getme::surface
