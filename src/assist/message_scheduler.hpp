#pragma once
// When each message starts in the audio stream (issue 14; docs/audio.md): one message at a time,
// urgent messages interrupt a playing non-urgent one, stale ones are dropped. Every decision is
// final when it is made — a message's start is known (and written to events.jsonl) on the frame
// that raised it, and the stream plays it exactly then. That is why only urgent messages ever
// wait, and only behind urgent ones (which nothing interrupts): a waiting non-urgent message
// could later be pushed aside by an urgent one, and its published start would be false.
// Pure logic on stream times (seconds), no audio.
#include <cstddef>
#include <deque>

#include "core/feedback_event.hpp"

namespace dynanav {

struct SchedulerOptions {
  double gap_s = 0.25;         ///< silence between messages (an interruption skips it)
  double stale_after_s = 1.0;  ///< longest wait from the raising frame to the start
};

/// What happens to one offered message.
struct ScheduleDecision {
  enum class Verdict {
    kPlay,   ///< starts at start_s
    kStale,  ///< its turn would come more than stale_after_s after its frame
    kBusy,   ///< non-urgent and the channel is taken (or in its gap)
  };
  Verdict verdict = Verdict::kPlay;
  double start_s = 0.0;
  bool interrupts = false;  ///< cuts the playing non-urgent message at start_s
  [[nodiscard]] bool plays() const { return verdict == Verdict::kPlay; }
};

struct SchedulerCounts {
  size_t offered = 0;
  size_t played = 0;
  size_t dropped_stale = 0;
  size_t dropped_busy = 0;
  size_t interrupted = 0;  ///< played messages cut short by an urgent one
};

class MessageScheduler {
 public:
  explicit MessageScheduler(SchedulerOptions options) : options_(options) {}

  /// The decision for a message of `priority` raised at `raised_s`, offered at `now_s` (both
  /// stream time, now_s >= every earlier now_s). Does not change the state: commit() does.
  [[nodiscard]] ScheduleDecision decide(FeedbackPriority priority, double raised_s,
                                        double now_s) const;
  /// Records a message that plays: `decision` from decide(), its start possibly moved later by
  /// the stream (start_s >= decision.start_s), its length. Messages that do not play are
  /// recorded by drop().
  void commit(FeedbackPriority priority, const ScheduleDecision& decision, double start_s,
              double duration_s);
  void drop(const ScheduleDecision& decision);

  /// When the channel is free again (end of the last committed message; -inf when none).
  [[nodiscard]] double busyUntilS() const;
  [[nodiscard]] const SchedulerCounts& counts() const { return counts_; }

 private:
  struct Slot {
    FeedbackPriority priority;
    double start_s;
    double end_s;
  };
  SchedulerOptions options_;
  std::deque<Slot> slots_;  // committed messages in start order; older ones forgotten lazily
  SchedulerCounts counts_;
};

}  // namespace dynanav
