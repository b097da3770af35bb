#include "formats/parallel_text.h"

#include <algorithm>
#include <thread>
#include <vector>

namespace getme::formats {

void AppendInParallel(std::string& out, std::int64_t count, std::int64_t unit, int threads,
                      const std::function<void(std::string&, std::int64_t, std::int64_t)>& format) {
  unit = std::max<std::int64_t>(unit, 1);
  const std::int64_t units = (count + unit - 1) / unit;
  const std::int64_t runs =
      std::clamp<std::int64_t>(std::min<std::int64_t>(threads, count / kParallelTextItems), 1,
                               std::max<std::int64_t>(units, 1));
  if (runs <= 1) {
    format(out, 0, count);
    return;
  }
  // Run r covers units [units·r/runs, units·(r+1)/runs): whole lines, about equal in size.
  const auto boundary = [&](std::int64_t run) {
    return std::min(count, units * run / runs * unit);
  };
  std::vector<std::string> later(static_cast<std::size_t>(runs - 1));
  {
    std::vector<std::jthread> workers;
    workers.reserve(later.size());
    for (std::int64_t run = 1; run < runs; ++run) {
      workers.emplace_back([&, run] {
        format(later[static_cast<std::size_t>(run - 1)], boundary(run), boundary(run + 1));
      });
    }
    format(out, 0, boundary(1));
  }  // the workers join here
  std::size_t size = out.size();
  for (const std::string& text : later) size += text.size();
  out.reserve(size);
  for (const std::string& text : later) out += text;
}

}  // namespace getme::formats
