#pragma once
// One message to the wearer (DESIGN.md §2, events.jsonl): made by assist's message policy,
// carried by FrameResult to the audio stage and the writers.
#include <cstdint>
#include <string>

#include "core/se3.hpp"

namespace dynanav {

enum class FeedbackPriority { kInfo, kAdvisory, kUrgent };

struct FeedbackEvent {
  double stamp_s = 0.0;  ///< frame time that raised it
  FeedbackPriority priority = FeedbackPriority::kInfo;
  std::string kind;  ///< e.g. "approaching", "nearby", "new_person", "obstacle"
  std::string text;  ///< the spoken message
  uint64_t object_id = 0;
  double bearing_deg = 0.0;
  double distance_m = 0.0;
  double ttc_s = -1.0;          ///< time to collision (< 0: none)
  double audio_start_s = -1.0;  ///< where it starts in the audio stream (< 0: not rendered)
  // Issue 14, assist's message policy (events.jsonl keys beyond DESIGN.md's):
  int clock = 12;               ///< clock-face direction in the wearer's body frame
  double closest_m = -1.0;      ///< predicted closest-approach distance (< 0: not approaching)
  bool user_related = false;    ///< closest approach inside the wearer's corridor soon
  bool interrupts = false;      ///< urgent: cuts off the message being spoken
  double spoken_s = 0.0;        ///< estimated length of earcon + speech (s)
  Vec3 p_world = Vec3::Zero();  ///< the object's centre when the message was raised
  std::string language = "en";  ///< "en" | "de"
};

}  // namespace dynanav
