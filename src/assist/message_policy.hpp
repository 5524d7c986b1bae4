#pragma once
// The message policy (issue 14, DESIGN.md §5): which hazards become spoken messages, and when.
//  - priorities: urgent = user-related and time to collision <= urgent_ttc_s; advisory = time to
//    collision <= advisory_ttc_s while passing within advisory_pass_m, a person within
//    near_person_m, or a static obstacle in the corridor ahead within obstacle_ahead_m; info =
//    a moving person not announced before;
//  - an object the segmenter did not find this frame (carried by its flow) may stay urgent,
//    not become so (urgent_needs_sight);
//  - a condition must hold for confirm_frames frames in a row before it raises a message; news
//    of a new person waits info_hold_s more (a hazard found meanwhile is said instead);
//  - no repeat unless the situation changed: a higher priority than last said, the distance
//    class, the clock direction (by at least one hour), or the motion word;
//  - one message at a time (a message occupies the channel for its estimated spoken length);
//    at most one non-urgent message per min_gap_s; an urgent one interrupts a non-urgent one;
//  - a waiting message whose condition no longer holds, or that waited stale_s, is dropped.
// Values in (the frame's stamp and hazards), values out (the messages that start on this frame).
#include <map>
#include <optional>
#include <vector>

#include "assist/hazard.hpp"
#include "assist/templates.hpp"
#include "core/config/assist.hpp"
#include "core/feedback_event.hpp"

namespace dynanav {

/// What the policy wants to say about a hazard this frame, before confirmation, repeat
/// suppression and timing (exposed for tests).
struct MessageCandidate {
  FeedbackPriority priority = FeedbackPriority::kInfo;
  std::string kind;  ///< "approaching" | "nearby" | "obstacle" | "new_person"
};
/// `announced`: the object was spoken of before (then it is no longer "new"). `urgent_allowed`
/// false: the urgent condition is not checked (the hazard is judged as advisory at most).
std::optional<MessageCandidate> classifyHazard(const Hazard& hazard, bool announced,
                                               const AssistConfig& config,
                                               bool urgent_allowed = true);

class MessagePolicy {
 public:
  MessagePolicy(const AssistConfig& config, Language language);
  /// One frame: its hazards (all tracked objects) in, the messages starting now out.
  std::vector<FeedbackEvent> step(double stamp_s, const std::vector<Hazard>& hazards);
  /// Messages dropped so far because they waited too long or their condition ended.
  [[nodiscard]] int dropped() const { return dropped_; }

 private:
  struct Said {  // what was last said about an object
    FeedbackPriority priority = FeedbackPriority::kInfo;
    int clock = 12;
    double bearing_deg = 0.0;
    double distance_m = 0.0;
    MotionWord motion = MotionWord::kNone;
  };
  struct Pending {
    FeedbackEvent event;
    MotionWord motion = MotionWord::kNone;
    double raised_s = 0.0;
  };
  struct Streaks {  // consecutive frames each priority's condition held
    int info = 0, advisory = 0, urgent = 0;
    double info_since_s = 0.0;      // when the info streak began
    bool urgent_when_seen = false;  // the urgent condition held the last frame it was found
  };

  [[nodiscard]] bool changed(const Said& said, FeedbackPriority priority, const Hazard& hazard,
                             MotionWord motion) const;
  /// Counts the hazard's streaks; true when the candidate's own priority held confirm_frames.
  bool confirmed(double stamp_s, const Hazard& hazard,
                 const std::optional<MessageCandidate>& candidate);
  FeedbackEvent makeEvent(double stamp_s, const MessageCandidate& candidate, const Hazard& hazard,
                          MotionWord motion) const;
  void remember(const Pending& pending);
  std::optional<uint64_t> choose(double stamp_s) const;

  AssistConfig config_;
  Language language_;
  std::map<uint64_t, Said> said_;  // by object id (ordered: deterministic)
  std::map<uint64_t, Streaks> streaks_;
  std::map<uint64_t, Pending> pending_;
  double busy_until_s_ = -1e9;  // the message being spoken ends then (estimate)
  bool speaking_urgent_ = false;
  double last_non_urgent_s_ = -1e9;  // start of the last non-urgent message
  int dropped_ = 0;
};

}  // namespace dynanav
