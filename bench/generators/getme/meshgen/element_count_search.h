#pragma once

#include <cstdint>
#include <functional>

namespace getme::meshgen {

// The value of a size parameter in [lo, max] whose element count is closest to `target`, for a
// count that does not decrease as the parameter grows (grid dimensions are rounded, so the count
// moves in steps). Grows the parameter from lo by 25 % steps until the count passes the target
// (so no count is taken of a mesh much larger than the target), then bisects to the step that
// straddles it and takes the nearer side, stopping early at a count within 0.5 % of the target.
// Returns lo or max when the target lies outside their counts.
double SizeParameterForCount(std::int64_t target, double lo, double max,
                             const std::function<std::int64_t(double)>& count);

}  // namespace getme::meshgen
