#pragma once
// Hazards (issue 14): what each tracked object means to the wearer, in the body frame
// (body_frame.hpp). For a moving object, the closest approach of its predicted path to the
// wearer's own path (both constant velocity on the ground plane, as the tracker's Kalman filter
// predicts; the velocity measured over the track's recent centres, object_motion_fit.hpp), its
// time and distance, the closing speed, and whether it is "user-related": the
// closest approach falls inside the wearer's corridor within the horizon. The tracker's
// uncertainty enters twice (docs/feedback.md): user-related asks that the miss distance, a
// Gaussian with the track's uncertainty, lies inside the corridor with at least
// corridor_min_probability (a wide sigma spreads that probability thin instead of widening the
// corridor for everyone), and urgency uses the time to closest approach at a closing speed
// ttc_sigmas standard deviations faster than estimated. Static obstacles and standing people get
// direction and distance only.
#include <vector>

#include "assist/body_frame.hpp"
#include "assist/object_motion_fit.hpp"
#include "core/config/assist.hpp"
#include "core/tracked_object.hpp"

namespace dynanav {

struct Hazard {
  uint64_t object_id = 0;
  std::string class_name;
  bool person = false;
  bool moving = false;  ///< tracked as dynamic and at least moving_speed_mps over ground
  bool seen = true;     ///< the segmenter found it this frame (not only carried by its flow)
  Vec3 p_world = Vec3::Zero();
  double distance_m = 0.0;   ///< on the ground plane, from the wearer
  double bearing_deg = 0.0;  ///< body frame, right of the walking direction positive
  int clock = 12;            ///< clock-face direction in the body frame (12 = ahead)
  double speed_mps = 0.0;    ///< over ground
  double closing_mps = 0.0;  ///< rate at which the distance shrinks (< 0: moving apart)
  // Closest approach (moving objects; relative constant-velocity motion on the ground):
  double t_closest_s = -1.0;     ///< time from now (< 0: none ahead, the distance only grows)
  double closest_m = -1.0;       ///< miss distance then
  double closest_sigma_m = 0.0;  ///< standard deviation of the miss distance (track covariance)
  double corridor_probability = 0.0;  ///< probability that the miss distance is inside the corridor
  double ttc_s = -1.0;                ///< time to closest approach when closing, else < 0
  double ttc_warn_s = -1.0;           ///< the same at the pessimistic closing speed (urgency)
  bool user_related = false;       ///< closest approach inside the corridor within user_horizon_s
  bool in_corridor_ahead = false;  ///< static object: ahead, inside the corridor
};

/// Probability that a miss distance ~ N(miss_m, sigma_m^2) (signed, across the relative path)
/// falls within +-corridor_m; sigma_m = 0 gives 1 inside, 0 outside.
double corridorProbability(double miss_m, double sigma_m, double corridor_m);

/// Clock position (1..12, 12 = ahead) of a bearing in degrees (right positive).
int clockOf(double bearing_deg);

/// The hazard of one tracked object moving as `motion` (object_motion_fit.hpp) for a wearer at
/// `body`.
Hazard assessHazard(const TrackedObject& object, const GroundMotion& motion, const BodyFrame& body,
                    const AssistConfig& config);
/// The same with the tracker's own velocity and covariance (filterMotion()).
Hazard assessHazard(const TrackedObject& object, const BodyFrame& body, const AssistConfig& config);

}  // namespace dynanav
