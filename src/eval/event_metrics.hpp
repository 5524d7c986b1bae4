#pragma once
// Scoring the messages of a run (events.jsonl) against the simulator's ground truth for
// `dynanav eval-events` (issue 14): for each person, the time of its closest approach to the
// wearer (the camera: objects_gt.jsonl positions against groundtruth.txt poses, on the ground
// plane = the world x-z plane, as assist/ measures) and the lead time of the first urgent
// warning before it; counts per priority; the most non-urgent messages in any window; messages
// repeated unchanged (the same text about the same object as its previous message). A message
// belongs to the person nearest (within match_m) to its position_world at its time.
#include <cstdint>
#include <vector>

#include "core/feedback_event.hpp"
#include "io/objects_jsonl.hpp"
#include "io/trajectory.hpp"

namespace dynanav {

struct EventMetricsOptions {
  double window_s = 3.0;    ///< the rate window of "at most one non-urgent message per 3 s"
  double match_m = 1.0;     ///< message-to-person distance for the match
  double corridor_m = 0.8;  ///< a closest approach within this is "in the corridor"
  double max_dt_s = 0.02;   ///< pose / frame pairing tolerance
};

struct PersonEncounter {
  uint64_t gt_id = 0;
  double t_closest_s = 0.0;  ///< ground truth, time of the closest approach
  double closest_m = 0.0;    ///< ground-plane distance then
  bool in_corridor = false;
  int urgent = 0, advisory = 0, info = 0;  ///< messages matched to this person
  double first_urgent_s = -1.0;            ///< first urgent message up to t_closest_s (< 0: none)
  double lead_s = -1.0;                    ///< t_closest_s - its stamp
  double lead_audio_s = -1.0;              ///< t_closest_s - its audio_start (< 0: not rendered)
  double first_advisory_s = -1.0;          ///< first advisory message up to t_closest_s (< 0: none)
};

struct EventMetrics {
  int events = 0, urgent = 0, advisory = 0, info = 0;
  int max_non_urgent_in_window = 0;
  int unchanged_repeats = 0;
  int unmatched = 0;                    ///< messages with no person within match_m
  std::vector<PersonEncounter> people;  ///< by ground-truth id
};

/// InputError when the poses do not cover the ground-truth frames.
EventMetrics scoreEvents(const std::vector<ObjectsFrame>& gt,
                         const std::vector<StampedPose>& gt_poses,
                         const std::vector<FeedbackEvent>& events,
                         const EventMetricsOptions& options = {});

/// The largest number of stamps (sorted or not) in any half-open window [t, t + window_s).
int maxInWindow(std::vector<double> stamps_s, double window_s);

}  // namespace dynanav
