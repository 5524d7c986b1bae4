#pragma once
// Config section `assist`: hazards in the wearer's body frame and the message policy (issue 14;
// assist/ and docs/feedback.md). See core/config.hpp for how sections are loaded and echoed.
// To add a tunable: the member with its default, and one v("key", member, "doc", valid) line in
// visit(); `valid` (core/config/range.hpp) is the documented range the loader enforces.
#include <string>

#include "core/config/range.hpp"

namespace dynanav {

struct AssistConfig {
  bool enabled = true;
  std::string language = "en";
  // Body frame: the wearer's heading is the smoothed walking direction.
  double heading_smoothing_s = 0.8;
  double walking_speed_mps = 0.25;
  // Object motion from the track's recent centres.
  double velocity_window_s = 0.6;
  double velocity_min_span_s = 0.2;
  double position_noise_m = 0.05;
  // Hazards.
  double corridor_m = 0.8;
  double user_horizon_s = 4.0;
  double corridor_min_probability = 0.5;
  double ttc_sigmas = 1.0;
  double closing_min_mps = 0.2;
  // Message policy.
  double urgent_ttc_s = 2.5;
  double advisory_ttc_s = 4.0;
  double advisory_pass_m = 2.0;
  double near_person_m = 1.5;
  double obstacle_ahead_m = 1.5;
  double moving_speed_mps = 0.3;
  double fast_closing_mps = 1.2;
  int confirm_frames = 2;
  bool urgent_needs_sight = true;
  double info_hold_s = 0.5;
  double min_gap_s = 3.0;
  double stale_s = 4.0;
  double repeat_distance_m = 0.5;
  double repeat_bearing_deg = 20.0;
  double earcon_s = 0.25;
  double speech_chars_per_s = 14.0;

  template <class V>
  void visit(V&& v) {
    v("enabled", enabled,
      "hazards and spoken messages (events.jsonl) while object tracking is on (objects.enabled)");
    v("language", language, "language of the messages (--language)", OneOf{"en", "de"});
    v("heading_smoothing_s", heading_smoothing_s,
      "time constant (s) of the exponential smoothing of the camera's velocity that gives the "
      "walking direction (head turns and gait sway average out)",
      Range{0, 10, Range::kOpenLow});
    v("walking_speed_mps", walking_speed_mps,
      "below this smoothed speed (m/s) the wearer stands: the heading is the camera's forward "
      "axis on the ground",
      Range{0, 5});
    v("velocity_window_s", velocity_window_s,
      "an object's velocity is the least-squares line through its centres of this long (s); its "
      "residuals give the velocity's uncertainty (assist/object_motion_fit.hpp)",
      Range{0, 10, Range::kOpenLow});
    v("velocity_min_span_s", velocity_min_span_s,
      "a younger track uses the tracker's filter velocity and covariance instead (s)",
      Range{0, 10});
    v("position_noise_m", position_noise_m,
      "least noise (m) assumed for a track centre in that fit (a perfect line is not certain)",
      Range{0, 1, Range::kOpenLow});
    v("corridor_m", corridor_m,
      "an object whose closest approach passes within this distance (m) of the wearer is "
      "user-related",
      Range{0, 10});
    v("user_horizon_s", user_horizon_s,
      "user-related only when the closest approach comes within this time (s)", Range{0, 30});
    v("corridor_min_probability", corridor_min_probability,
      "user-related when the miss distance, a Gaussian with the track's uncertainty at the time "
      "of closest approach, lies inside the corridor with at least this probability (0.5: more "
      "likely inside than not; a sigma small against the corridor gives the plain corridor, a "
      "large one, a path not known yet, raises no urgency)",
      Range{0, 1, Range::kOpenLow});
    v("ttc_sigmas", ttc_sigmas,
      "urgency uses the time to closest approach at a closing speed this many velocity standard "
      "deviations faster than estimated (warn by the earliest plausible time)",
      Range{0, 10});
    v("closing_min_mps", closing_min_mps,
      "an object closing slower than this (m/s) has no time to collision", Range{0, 10});
    v("urgent_ttc_s", urgent_ttc_s, "urgent: user-related and time to collision at most this (s)",
      Range{0, 30});
    v("advisory_ttc_s", advisory_ttc_s,
      "advisory: time to collision at most this (s) and passing within advisory_pass_m",
      Range{0, 30});
    v("advisory_pass_m", advisory_pass_m,
      "advisory by time to collision only for objects whose closest approach is within this (m) "
      "(a walker passing 3 m aside is no hazard)",
      Range{0, 20});
    v("near_person_m", near_person_m, "advisory: a person (moving or not) within this distance (m)",
      Range{0, 10});
    v("obstacle_ahead_m", obstacle_ahead_m,
      "advisory: a static object inside the corridor ahead within this distance (m)", Range{0, 10});
    v("moving_speed_mps", moving_speed_mps,
      "an object slower than this (m/s) is spoken of as standing; also the closing speed that "
      "makes 'approaching' or 'moving away'",
      Range{0, 10});
    v("fast_closing_mps", fast_closing_mps, "closing at least this fast (m/s): 'approaching fast'",
      Range{0, 20});
    v("confirm_frames", confirm_frames,
      "a message's condition must hold on this many consecutive frames before it is raised "
      "(a one-frame velocity spike of a track raises nothing)",
      Range{1, 100});
    v("urgent_needs_sight", urgent_needs_sight,
      "an object the segmenter did not find this frame (carried by its flow points alone) may "
      "stay urgent if it was when last found, but not become urgent: its motion then is the "
      "flow's, which no mask confirms (static fr1_xyz in real time: a false 'person' on the desk, "
      "carried 5-6 frames while its points read nearer, was warned as approaching; off: "
      "carried objects are judged as found ones)");
    v("info_hold_s", info_hold_s,
      "news of a new moving person waits this long (s): if the person turns out to be a hazard "
      "meanwhile, the advisory is the one message said about them",
      Range{0, 10});
    v("min_gap_s", min_gap_s,
      "at most one non-urgent message per this many seconds (urgent ones are not limited)",
      Range{0, 60});
    v("stale_s", stale_s,
      "a message that waited this long (s) for its turn is dropped (it carries each frame's "
      "values while it waits); the object is announced again when its situation changes",
      Range{0, 60, Range::kOpenLow});
    v("repeat_distance_m", repeat_distance_m,
      "a spoken distance class counts as changed only when the distance also moved this much (m) "
      "since the last message about the object (no flicker at class edges)",
      Range{0, 10});
    v("repeat_bearing_deg", repeat_bearing_deg,
      "a clock direction counts as changed only when the bearing also moved this much (deg)",
      Range{0, 180});
    v("earcon_s", earcon_s,
      "estimated length (s) of the tone before each message (the audio stage times it exactly)",
      Range{0, 5});
    v("speech_chars_per_s", speech_chars_per_s,
      "estimated speaking rate (characters/s) for a message's duration (espeak-ng's default 175 "
      "words/min is about 14)",
      Range{1, 100});
  }
};

}  // namespace dynanav
