#pragma once

#include <chrono>
#include <cstdio>
#include <string>

#include "getme/smoothing/progress.h"

namespace getme::cli {

// Human-readable progress on stderr. On a terminal, one line redrawn in place with '\r', at most
// ten redraws a second (a sequential phase sends an event per thousand picks, far more often
// than anyone reads), and left standing at every phase end. Elsewhere (a log file, a CI job),
// where '\r' would pile up, only one line per phase end.
class ProgressPrinter {
 public:
  ProgressPrinter(std::FILE* stream, bool is_terminal) : stream_(stream), terminal_(is_terminal) {}

  void OnEvent(const ProgressEvent& event);
  // Ends a line left open by a redraw (e.g. when smoothing fails mid-phase).
  void Finish();

 private:
  static constexpr std::chrono::milliseconds kRedrawInterval{100};

  std::FILE* stream_;
  bool terminal_;
  bool line_open_ = false;
  std::size_t last_length_ = 0;
  std::chrono::steady_clock::time_point last_redraw_{};
};

}  // namespace getme::cli
