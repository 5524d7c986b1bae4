// MessageScheduler (issue 14): one message at a time, urgent interrupts non-urgent, stale and
// busy messages dropped, starts in order and final when decided.
#include <gtest/gtest.h>

#include "assist/message_scheduler.hpp"

namespace dynanav {
namespace {

using P = FeedbackPriority;
using V = ScheduleDecision::Verdict;

/// Offers a message raised and offered at `now_s` lasting `duration_s`; returns the decision.
ScheduleDecision offer(MessageScheduler& s, P priority, double now_s, double duration_s,
                       double raised_s = -1.0) {
  const ScheduleDecision d = s.decide(priority, raised_s < 0 ? now_s : raised_s, now_s);
  if (d.plays())
    s.commit(priority, d, d.start_s, duration_s);
  else
    s.drop(d);
  return d;
}

TEST(MessageScheduler, AFreeChannelStartsAMessageAtOnce) {
  MessageScheduler s({0.25, 1.0});
  const auto d = offer(s, P::kInfo, 3.0, 1.5);
  EXPECT_TRUE(d.plays());
  EXPECT_DOUBLE_EQ(d.start_s, 3.0);
  EXPECT_FALSE(d.interrupts);
  EXPECT_DOUBLE_EQ(s.busyUntilS(), 4.5);
}

TEST(MessageScheduler, UrgentInterruptsAPlayingNonUrgentMessage) {
  for (const P playing : {P::kInfo, P::kAdvisory}) {
    MessageScheduler s({0.25, 1.0});
    offer(s, playing, 0.0, 2.0);
    const auto d = offer(s, P::kUrgent, 0.8, 1.0);
    EXPECT_TRUE(d.plays());
    EXPECT_TRUE(d.interrupts);
    EXPECT_DOUBLE_EQ(d.start_s, 0.8);  // no gap: the earcon itself marks the change
    EXPECT_EQ(s.counts().interrupted, 1u);
    EXPECT_DOUBLE_EQ(s.busyUntilS(), 1.8);
  }
}

TEST(MessageScheduler, UrgentWaitsBehindUrgentInArrivalOrder) {
  MessageScheduler s({0.25, 2.0});
  offer(s, P::kUrgent, 0.0, 1.0);
  const auto second = offer(s, P::kUrgent, 0.2, 0.5);
  const auto third = offer(s, P::kUrgent, 0.3, 0.5);
  ASSERT_TRUE(second.plays());
  ASSERT_TRUE(third.plays());
  EXPECT_FALSE(second.interrupts);
  EXPECT_DOUBLE_EQ(second.start_s, 1.25);  // after the first one and the gap
  EXPECT_DOUBLE_EQ(third.start_s, 2.0);    // after the second one and the gap
  EXPECT_EQ(s.counts().interrupted, 0u);
}

TEST(MessageScheduler, AMessageWhoseTurnComesTooLateIsDroppedAsStale) {
  MessageScheduler s({0.25, 1.0});
  offer(s, P::kUrgent, 0.0, 3.0);
  const auto d = offer(s, P::kUrgent, 0.5, 1.0);  // its turn: 3.25, 2.75 s after its frame
  EXPECT_EQ(d.verdict, V::kStale);
  EXPECT_EQ(s.counts().dropped_stale, 1u);
  // A frame that reached the audio stage late is stale even on a free channel.
  const auto late = offer(s, P::kInfo, 10.0, 1.0, /*raised_s=*/8.5);
  EXPECT_EQ(late.verdict, V::kStale);
  EXPECT_EQ(s.counts().dropped_stale, 2u);
  EXPECT_EQ(s.counts().played, 1u);
}

TEST(MessageScheduler, NonUrgentNeverWaitsSoNoStartIsEverRevised) {
  MessageScheduler s({0.25, 1.0});
  offer(s, P::kAdvisory, 0.0, 1.0);
  EXPECT_EQ(offer(s, P::kInfo, 0.5, 1.0).verdict, V::kBusy);      // while it plays
  EXPECT_EQ(offer(s, P::kAdvisory, 1.1, 1.0).verdict, V::kBusy);  // in the gap after it
  EXPECT_TRUE(offer(s, P::kInfo, 1.25, 1.0).plays());             // the gap is over
  offer(s, P::kUrgent, 3.0, 1.0);
  EXPECT_EQ(offer(s, P::kAdvisory, 3.5, 1.0).verdict, V::kBusy);  // urgent is not interrupted
  EXPECT_EQ(s.counts().dropped_busy, 3u);
  EXPECT_EQ(s.counts().offered, 6u);
}

TEST(MessageScheduler, StartsNeverGoBackwards) {
  MessageScheduler s({0.25, 1.0});
  const P pattern[] = {P::kInfo, P::kUrgent, P::kAdvisory, P::kUrgent, P::kUrgent, P::kInfo};
  double last_start = -1.0;
  for (int i = 0; i < 60; ++i) {
    const double now = 0.3 * i;
    const auto d = offer(s, pattern[i % 6], now, 0.4 + 0.1 * (i % 7));
    if (!d.plays()) continue;
    EXPECT_GE(d.start_s, last_start);
    EXPECT_GE(d.start_s, now);
    last_start = d.start_s;
  }
  EXPECT_GT(s.counts().played, 10u);
}

TEST(MessageScheduler, AStartMovedLaterByTheStreamCountsFromWhereItPlays) {
  MessageScheduler s({0.25, 1.0});
  const auto d = s.decide(P::kInfo, 1.0, 1.0);
  s.commit(P::kInfo, d, 1.05, 1.0);  // the audio thread had rendered up to 1.05 s
  EXPECT_DOUBLE_EQ(s.busyUntilS(), 2.05);
}

}  // namespace
}  // namespace dynanav
