#include "cli/report_plot.h"

#include <cstddef>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "absl/strings/str_replace.h"

namespace getme::cli {
namespace {

// The x value of trace point `index`: seconds, or the event's position.
double TraceX(const ReportData& data, std::size_t index) {
  return data.by_iteration ? static_cast<double>(index) : data.trace[index].elapsed_seconds;
}

// A string for a gnuplot double-quoted literal.
std::string Quoted(const std::string& text) {
  return absl::StrCat(
      "\"", absl::StrReplaceAll(text, {{"\\", "\\\\"}, {"\"", "\\\""}, {"\n", " "}}), "\"");
}

}  // namespace

std::string ReportDataTable(const ReportData& data) {
  std::string table = "# histogram: bin_low\tbin_high\tbefore\tafter\n";
  const std::size_t bins = data.histogram_before.size();
  for (std::size_t bin = 0; bin < bins; ++bin) {
    absl::StrAppendFormat(&table, "%.6g\t%.6g\t%d\t%d\n", static_cast<double>(bin) / bins,
                          static_cast<double>(bin + 1) / bins, data.histogram_before[bin],
                          bin < data.histogram_after.size() ? data.histogram_after[bin] : 0);
  }
  if (data.trace.empty()) return table;
  absl::StrAppend(&table, "\n\n# trace: ", data.by_iteration ? "event" : "seconds",
                  "\tphase\titeration\tq_min\tq_mean\n");
  for (std::size_t i = 0; i < data.trace.size(); ++i) {
    const TracePoint& point = data.trace[i];
    absl::StrAppendFormat(&table, "%.17g\t%s\t%d\t%.17g\t%.17g\n", TraceX(data, i), point.phase,
                          point.iteration, point.q_min, point.q_mean);
  }
  return table;
}

std::string ReportGnuplotScript(const ReportData& data, const std::string& data_path,
                                const std::string& terminal, const std::string& picture_path) {
  const bool with_trace = !data.trace.empty();
  const int panels = with_trace ? 3 : 1;
  const int width = 520 * panels;
  const int height = data.title.empty() ? 420 : 460;
  std::string script;
  if (terminal == "png") {
    absl::StrAppend(&script, "set terminal pngcairo size ", width, ",", height,
                    " font 'sans,10' background rgb 'white'\n");
  } else {
    absl::StrAppend(&script, "set terminal svg size ", width, ",", height,
                    " font 'sans,11' background rgb 'white'\n");
  }
  absl::StrAppend(&script, "set output ", Quoted(picture_path), "\n",
                  "set datafile separator '\\t'\n", "set multiplot layout 1,", panels,
                  data.title.empty() ? "" : absl::StrCat(" title ", Quoted(data.title)), "\n");

  // Figs. 7, 11, 15: elements per mean-ratio interval, before and after.
  const double bin_width = 1.0 / static_cast<double>(data.histogram_before.size());
  absl::StrAppend(
      &script, "set title 'Element quality (mean ratio)'\n",
      "set xlabel 'mean ratio q'\nset ylabel 'elements'\nset xrange [0:1]\n",
      "set yrange [0:*]\nset key top left\nset style fill solid 0.6 border -1\n",
      absl::StrFormat("set boxwidth %.6g absolute\n", bin_width * 0.45),
      absl::StrFormat("plot %s index 0 using (($1+$2)/2-%.6g):3 with boxes lc rgb '#c0504d' "
                      "title %s, \\\n     '' index 0 using (($1+$2)/2+%.6g):4 with boxes lc rgb "
                      "'#4f81bd' title %s\n",
                      Quoted(data_path), bin_width * 0.225,
                      Quoted(absl::StrFormat("before: q_{min} %.4f, q_{mean} %.4f",
                                             data.q_min_before, data.q_mean_before)),
                      bin_width * 0.225,
                      Quoted(absl::StrFormat("after: q_{min} %.4f, q_{mean} %.4f", data.q_min_after,
                                             data.q_mean_after))));
  if (!with_trace) {
    absl::StrAppend(&script, "unset multiplot\n");
    return script;
  }

  // Figs. 8, 12, 16: q_min and q_mean against time; a dashed line where each phase starts.
  std::string phase_marks;
  for (std::size_t i = 0; i < data.trace.size(); ++i) {
    if (i > 0 && data.trace[i].phase == data.trace[i - 1].phase) continue;
    const double x = i > 0 ? TraceX(data, i - 1) : TraceX(data, 0);
    absl::StrAppend(&phase_marks,
                    absl::StrFormat("set arrow from %.17g, graph 0 to %.17g, graph 1 nohead dt 2 "
                                    "lc rgb 'gray40'\n",
                                    x, x),
                    absl::StrFormat("set label %s at %.17g, graph 0.04 rotate by 90 offset 1,0 "
                                    "font ',9' tc rgb 'gray30'\n",
                                    Quoted(data.trace[i].phase), x));
  }
  const std::string x_label = data.by_iteration ? "progress event" : "time [s]";
  for (const auto& [column, name] :
       {std::pair<int, const char*>{4, "q_{min}"}, std::pair<int, const char*>{5, "q_{mean}"}}) {
    absl::StrAppend(&script, "unset arrow\nunset label\nset autoscale\nset style fill empty\n",
                    "set title ", Quoted(absl::StrCat(name, " during smoothing")), "\n",
                    "set xlabel ", Quoted(x_label), "\nset ylabel ", Quoted(name), "\n",
                    "set key bottom right\n", phase_marks,
                    absl::StrFormat("plot %s index 1 using 1:%d with linespoints pt 7 ps 0.4 "
                                    "lw 1.5 lc rgb '#4f81bd' title %s\n",
                                    Quoted(data_path), column, Quoted(name)));
  }
  absl::StrAppend(&script, "unset multiplot\n");
  return script;
}

}  // namespace getme::cli
