#include "cli/progress_printer.h"

#include "cli/text_reports.h"

namespace getme::cli {

void ProgressPrinter::OnEvent(const ProgressEvent& event) {
  const std::string line = FormatProgressLine(event);
  if (!terminal_) {
    if (event.phase_done) std::fprintf(stream_, "%s\n", line.c_str());
    std::fflush(stream_);
    return;
  }
  const auto now = std::chrono::steady_clock::now();
  if (!event.phase_done && line_open_ && now - last_redraw_ < kRedrawInterval) return;
  last_redraw_ = now;
  // Pad with spaces over the rest of a longer previous line instead of an ANSI erase, which
  // some terminals and CI log viewers show literally.
  const std::size_t padding = last_length_ > line.size() ? last_length_ - line.size() : 0;
  std::fprintf(stream_, "\r%s%*s", line.c_str(), static_cast<int>(padding), "");
  last_length_ = line.size();
  if (event.phase_done) {
    std::fputc('\n', stream_);
    line_open_ = false;
    last_length_ = 0;
  } else {
    line_open_ = true;
  }
  std::fflush(stream_);
}

void ProgressPrinter::Finish() {
  if (line_open_) std::fputc('\n', stream_);
  line_open_ = false;
  last_length_ = 0;
  std::fflush(stream_);
}

}  // namespace getme::cli
