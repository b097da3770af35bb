// The progress fan-out never blocks the publisher: a watcher that does not read loses
// intermediate events but gets every phase_done event and the final one, in order.
#include "getme_server/progress_fanout.h"

#include <vector>

#include "absl/time/clock.h"
#include "gtest/gtest.h"

namespace getme::server {
namespace {

v1::ProgressEvent Event(std::uint64_t sequence, bool phase_done = false, bool final = false) {
  v1::ProgressEvent event;
  event.set_sequence(sequence);
  event.set_phase_done(phase_done);
  event.set_final(final);
  return event;
}

std::vector<v1::ProgressEvent> Drain(ProgressFanout::Watcher& watcher) {
  std::vector<v1::ProgressEvent> events;
  v1::ProgressEvent event;
  while (watcher.Next(absl::Seconds(5), event) == ProgressFanout::NextResult::kEvent) {
    events.push_back(event);
  }
  return events;
}

TEST(ProgressFanoutTest, StalledWatcherNeitherBlocksThePublisherNorLosesPhaseEnds) {
  ProgressFanout fanout(absl::ZeroDuration());
  auto stalled = fanout.Watch();
  const absl::Time start = absl::Now();
  std::uint64_t sequence = 0;
  for (int phase = 0; phase < 3; ++phase) {
    for (int i = 0; i < 100'000; ++i) fanout.Publish(Event(++sequence));
    fanout.Publish(Event(++sequence, /*phase_done=*/true));
  }
  fanout.Publish(Event(++sequence, false, /*final=*/true));
  EXPECT_LT(absl::Now() - start, absl::Seconds(5));

  const std::vector<v1::ProgressEvent> events = Drain(*stalled);
  EXPECT_LT(events.size(), 5000u) << "the mailbox is bounded";
  int phase_done = 0;
  for (std::size_t i = 0; i < events.size(); ++i) {
    if (i > 0) {
      EXPECT_GT(events[i].sequence(), events[i - 1].sequence());
    }
    phase_done += events[i].phase_done();
  }
  EXPECT_EQ(phase_done, 3);
  ASSERT_FALSE(events.empty());
  EXPECT_TRUE(events.back().final());
  EXPECT_EQ(events.back().sequence(), sequence);
  v1::ProgressEvent after;
  EXPECT_EQ(stalled->Next(absl::Milliseconds(1), after), ProgressFanout::NextResult::kEnded);
}

TEST(ProgressFanoutTest, ThrottlingKeepsTheNewestEventOfAnInterval) {
  ProgressFanout fanout(absl::Hours(1));
  auto watcher = fanout.Watch();
  for (std::uint64_t s = 1; s <= 10; ++s) fanout.Publish(Event(s));
  fanout.Publish(Event(11, true));
  fanout.Publish(Event(12, false, true));
  const std::vector<v1::ProgressEvent> events = Drain(*watcher);
  // All ten fall into one interval and none was read yet: each replaces the waiting one, so the
  // newest (10) is delivered; the phase end and the final event always follow.
  ASSERT_EQ(events.size(), 3u);
  EXPECT_EQ(events[0].sequence(), 10u);
  EXPECT_EQ(events[1].sequence(), 11u);
  EXPECT_EQ(events[2].sequence(), 12u);
}

TEST(ProgressFanoutTest, LateWatcherStartsWithTheLatestEvent) {
  ProgressFanout fanout(absl::ZeroDuration());
  fanout.Publish(Event(1));
  fanout.Publish(Event(2));
  auto late = fanout.Watch();
  fanout.Publish(Event(3, false, true));
  const std::vector<v1::ProgressEvent> events = Drain(*late);
  ASSERT_EQ(events.size(), 2u);
  EXPECT_EQ(events[0].sequence(), 2u);
  EXPECT_EQ(events[1].sequence(), 3u);
  // After the job ended, a watcher gets just the final event.
  const std::vector<v1::ProgressEvent> after_end = Drain(*fanout.Watch());
  ASSERT_EQ(after_end.size(), 1u);
  EXPECT_TRUE(after_end[0].final());
}

}  // namespace
}  // namespace getme::server
