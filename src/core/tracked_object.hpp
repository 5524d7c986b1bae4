#pragma once
// A moving (or static) person or object as the wearer's assistant sees it (DESIGN.md §2,
// objects.jsonl). Filled by dynamics' object tracker; carried by FrameResult to the feedback
// stage and the writers; the simulator's ground truth uses the same type (io/objects_jsonl).
// Frames: world = first tracked camera; camera x right, y down, z forward.
#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

#include "core/se3.hpp"

namespace dynanav {

/// Where a track is expected to be `ahead_s` seconds from now (constant-velocity prediction).
struct PathPoint {
  double ahead_s = 0.0;
  Vec3 p_world = Vec3::Zero();
  double sigma_m = 0.0;  ///< sqrt of the largest eigenvalue of the position covariance
};

struct TrackedObject {
  uint64_t id = 0;               ///< stable for the run, never reused
  std::string class_name;        ///< COCO name ("person", "chair", ...)
  bool dynamic = false;          ///< moving now (scene flow / depth test / measured speed)
  Vec3 p_world = Vec3::Zero();   ///< centre of the object (m)
  Vec3 p_camera = Vec3::Zero();  ///< the same in this frame's camera (m)
  Vec3 v_world_mps = Vec3::Zero();
  double speed_mps = 0.0;
  /// The velocity is a measurement (its standard deviation is below the tracker's
  /// objects.velocity_known_sigma_mps), not the prior of a track too young to have one: a new
  /// track reports velocity zero with its prior covariance until then. Ground truth: always.
  bool velocity_known = true;
  double heading_deg = 0.0;  ///< direction of motion in the world's x-z plane (atan2(vx, vz))
  double distance_m = 0.0;   ///< from the camera centre
  double bearing_deg = 0.0;  ///< right of the optical axis positive
  int clock = 12;            ///< clock-face direction (12 = straight ahead)
  int points = 0;            ///< tracked points supporting the estimate (GT: visible pixels)
  Eigen::Matrix<double, 6, 6> covariance = Eigen::Matrix<double, 6, 6>::Zero();  ///< [p, v], world
  int missed_frames = 0;   ///< consecutive frames the segmenter did not see it (carried by flow)
  int motion_inliers = 0;  ///< inliers of this frame's rigid-motion estimate (0: none)
  /// The tracker's estimate started afresh this frame at a centre the object could not have
  /// reached from the last one (another extent of it was matched): motion measured over earlier
  /// centres of this id is void.
  bool restarted = false;
  /// This frame's centre was measured on another part of the object than the last one (cut by
  /// the image's side or not, a person's trunk found or not, most of it beyond the depth's
  /// range or not): it placed the estimate without entering its velocity, and earlier centres
  /// of this id are not comparable with it either.
  bool reanchored = false;
  std::vector<PathPoint> predicted_path;  ///< empty for static objects
  double visible_share = -1.0;  ///< ground truth only: share of the object in view (< 0: unknown)
};

/// Bearing (deg, right positive), distance and clock position from p_camera; heading and speed
/// from v_world_mps.
void fillViewGeometry(TrackedObject& object);

}  // namespace dynanav
