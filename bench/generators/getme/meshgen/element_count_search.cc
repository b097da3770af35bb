#include "getme/meshgen/element_count_search.h"

#include <algorithm>
#include <cstdlib>

namespace getme::meshgen {

double SizeParameterForCount(std::int64_t target, double lo, double max,
                             const std::function<std::int64_t(double)>& count) {
  const auto close_enough = [target](std::int64_t n) {
    return std::llabs(n - target) * 200 <= target;
  };
  std::int64_t lo_count = count(lo);
  if (lo_count >= target || close_enough(lo_count)) return lo;
  double hi = lo;
  std::int64_t hi_count = lo_count;
  while (hi_count <= target) {
    if (hi >= max) return max;
    lo = hi;
    lo_count = hi_count;
    hi = std::min(max, 1.25 * hi);
    hi_count = count(hi);
    if (close_enough(hi_count)) return hi;
  }
  // 60 halvings shrink any interval of doubles to adjacent values.
  for (int step = 0; step < 60 && !close_enough(lo_count) && !close_enough(hi_count); ++step) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;
    const std::int64_t mid_count = count(mid);
    if (mid_count <= target) {
      lo = mid;
      lo_count = mid_count;
    } else {
      hi = mid;
      hi_count = mid_count;
    }
  }
  return target - lo_count <= hi_count - target ? lo : hi;
}

}  // namespace getme::meshgen
