#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "cli/trace_reader.h"

namespace getme::cli {

// What `getme report` draws.
struct ReportData {
  std::string before_name;  // file names for the legend
  std::string after_name;
  std::vector<std::int64_t> histogram_before;  // equal bins over [0, 1]
  std::vector<std::int64_t> histogram_after;
  double q_min_before = 0, q_mean_before = 0, q_min_after = 0, q_mean_after = 0;
  std::vector<TracePoint> trace;  // empty: no trace panels
  bool by_iteration = false;
  std::string title;
};

// The plotted numbers as tab-separated blocks: "# histogram" (bin_low bin_high before after),
// then, with a trace, "# trace" (x phase iteration q_min q_mean). gnuplot reads the same file,
// one block per `index`.
std::string ReportDataTable(const ReportData& data);

// A gnuplot script that reads `data_path` (ReportDataTable) and draws the histogram panel and,
// with a trace, q_min and q_mean against time or iteration with the phase starts marked.
// `terminal` is "svg" or "png".
std::string ReportGnuplotScript(const ReportData& data, const std::string& data_path,
                                const std::string& terminal, const std::string& picture_path);

}  // namespace getme::cli
