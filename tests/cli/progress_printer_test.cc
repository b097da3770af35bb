#include "cli/progress_printer.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

namespace getme::cli {
namespace {

// Captures what the printer writes.
class Capture {
 public:
  Capture() : file_(std::tmpfile()) {}
  ~Capture() { std::fclose(file_); }
  std::FILE* file() { return file_; }
  std::string Text() {
    std::fflush(file_);
    std::rewind(file_);
    std::string text;
    for (int c = std::fgetc(file_); c != EOF; c = std::fgetc(file_))
      text.push_back(static_cast<char>(c));
    return text;
  }

 private:
  std::FILE* file_;
};

ProgressEvent Event(Phase phase, std::int64_t iteration, bool done) {
  ProgressEvent event;
  event.phase = phase;
  event.iteration = iteration;
  event.q_min = 0.25;
  event.q_mean = 0.75;
  event.phase_done = done;
  return event;
}

TEST(ProgressPrinter, WithoutTerminalPrintsOnlyPhaseEnds) {
  Capture capture;
  ProgressPrinter printer(capture.file(), /*is_terminal=*/false);
  for (int i = 1; i <= 50; ++i) printer.OnEvent(Event(Phase::kSimultaneous, i, i == 50));
  for (int i = 1; i <= 20; ++i) printer.OnEvent(Event(Phase::kSequential, i * 1000, i == 20));
  printer.Finish();
  const std::string text = capture.Text();
  EXPECT_EQ(text.find('\r'), std::string::npos);
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 2);
  EXPECT_EQ(text.rfind("simultaneous  iteration 50 ", 0), 0u) << text;
  EXPECT_NE(text.find("\nsequential    iteration 20000 "), std::string::npos) << text;
}

TEST(ProgressPrinter, OnATerminalRedrawsAtMostTenTimesASecond) {
  Capture capture;
  ProgressPrinter printer(capture.file(), /*is_terminal=*/true);
  // A burst far faster than 100 ms: only the first event and the phase end are drawn.
  for (int i = 1; i <= 500; ++i) printer.OnEvent(Event(Phase::kSimultaneous, i, i == 500));
  const std::string text = capture.Text();
  EXPECT_EQ(std::count(text.begin(), text.end(), '\r'), 2) << text;
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 1);
  EXPECT_NE(text.find("iteration 500 "), std::string::npos);
  EXPECT_EQ(text.back(), '\n');
}

TEST(ProgressPrinter, FinishEndsAnOpenLine) {
  Capture capture;
  ProgressPrinter printer(capture.file(), /*is_terminal=*/true);
  printer.OnEvent(Event(Phase::kSequential, 1000, false));
  printer.Finish();
  const std::string text = capture.Text();
  EXPECT_EQ(text.front(), '\r');
  EXPECT_EQ(text.back(), '\n');
}

}  // namespace
}  // namespace getme::cli
