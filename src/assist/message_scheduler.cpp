#include "assist/message_scheduler.hpp"

#include <algorithm>
#include <limits>

namespace dynanav {

ScheduleDecision MessageScheduler::decide(FeedbackPriority priority, double raised_s,
                                          double now_s) const {
  ScheduleDecision d;
  d.start_s = now_s;
  const bool urgent = priority == FeedbackPriority::kUrgent;
  if (!slots_.empty()) {
    const Slot& last = slots_.back();
    const double free_at_s = last.end_s + options_.gap_s;
    if (free_at_s > now_s) {  // playing, or in the silence after it
      if (!urgent) {
        d.verdict = ScheduleDecision::Verdict::kBusy;
        return d;
      }
      if (last.priority != FeedbackPriority::kUrgent) {
        // Only the last slot can be non-urgent (nothing waits behind a non-urgent message).
        d.interrupts = last.end_s > now_s;
      } else {
        d.start_s = free_at_s;  // behind the urgent one(s), in arrival order
      }
    }
  }
  if (d.start_s - raised_s > options_.stale_after_s) d.verdict = ScheduleDecision::Verdict::kStale;
  return d;
}

void MessageScheduler::commit(FeedbackPriority priority, const ScheduleDecision& decision,
                              double start_s, double duration_s) {
  ++counts_.offered;
  ++counts_.played;
  if (decision.interrupts && !slots_.empty()) {
    ++counts_.interrupted;
    slots_.back().end_s = std::min(slots_.back().end_s, start_s);
  }
  // Slots that ended before this start can no longer matter.
  while (!slots_.empty() && slots_.front().end_s + options_.gap_s <= start_s) slots_.pop_front();
  slots_.push_back({priority, start_s, start_s + std::max(0.0, duration_s)});
}

void MessageScheduler::drop(const ScheduleDecision& decision) {
  ++counts_.offered;
  if (decision.verdict == ScheduleDecision::Verdict::kStale) ++counts_.dropped_stale;
  if (decision.verdict == ScheduleDecision::Verdict::kBusy) ++counts_.dropped_busy;
}

double MessageScheduler::busyUntilS() const {
  return slots_.empty() ? -std::numeric_limits<double>::infinity() : slots_.back().end_s;
}

}  // namespace dynanav
