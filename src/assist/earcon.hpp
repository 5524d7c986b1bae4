#pragma once
// Earcons (issue 14; DESIGN.md §5): the short distinct sound before each spoken message. Pitch
// and rhythm encode urgency — urgent: three fast high beeps; advisory: two medium beeps; info:
// one low tone — so the wearer knows how much it matters before the first word.
#include <vector>

#include "core/feedback_event.hpp"

namespace dynanav {

/// The rhythm and pitch of one priority's earcon.
struct EarconPattern {
  int beeps = 1;
  double pitch_hz = 0.0;  ///< fundamental; harmonics 2 and 3 are added for localisation
  double beep_s = 0.0;    ///< length of one beep
  double pause_s = 0.0;   ///< silence between beeps
  [[nodiscard]] double durationS() const { return beeps * beep_s + (beeps - 1) * pause_s; }
};

[[nodiscard]] EarconPattern earconPattern(FeedbackPriority priority);

/// The earcon as mono float samples at `rate_hz`, peak `gain` (full scale = 1).
[[nodiscard]] std::vector<float> synthesiseEarcon(FeedbackPriority priority, int rate_hz,
                                                  double gain);

}  // namespace dynanav
