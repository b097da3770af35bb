#pragma once

#include <cstdint>
#include <functional>
#include <string>

namespace getme::formats {

// Text of many numbers, formatted by several threads. ASCII output of a large mesh is mostly
// std::to_chars on each coordinate and cell value, one after another, and that work divides
// without changing a byte.

// Items per thread below which a run is not split: a thread costs tens of microseconds to
// start, 16k numbers about a millisecond to format.
inline constexpr std::int64_t kParallelTextItems = 16384;

// Appends to `out` what `format(text, begin, end)` appends for items [begin, end), over all
// items [0, count). With `threads` > 1 and enough items, [0, count) is cut into up to `threads`
// runs at multiples of `unit` (a line of `unit` values is never split), each run is formatted
// into its own string on its own thread (the first into `out` itself), and the strings are
// joined in order. The bytes are those of one format(out, 0, count) for every thread count;
// `format` must therefore depend on nothing but the items and their indices.
void AppendInParallel(std::string& out, std::int64_t count, std::int64_t unit, int threads,
                      const std::function<void(std::string&, std::int64_t, std::int64_t)>& format);

}  // namespace getme::formats
