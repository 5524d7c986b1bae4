#pragma once
// A moving (or static) person or object as the wearer's assistant sees it (DESIGN.md §2,
// objects.jsonl). Filled by dynamics' object tracker; carried by FrameResult to the feedback
// stage and the writers. Frames: world = first tracked camera; camera x right, y down, z forward.
#include <Eigen/Core>
#include <cstdint>
#include <string>

#include "core/se3.hpp"

namespace dynanav {

struct TrackedObject {
  uint64_t id = 0;               ///< stable for the run, never reused
  std::string class_name;        ///< COCO name ("person", "chair", ...)
  bool dynamic = false;          ///< moving now (scene flow / depth test / measured speed)
  Vec3 p_world = Vec3::Zero();   ///< centroid of the object's points (m)
  Vec3 p_camera = Vec3::Zero();  ///< the same in this frame's camera (m)
  Vec3 v_world_mps = Vec3::Zero();
  double speed_mps = 0.0;
  double heading_deg = 0.0;  ///< direction of motion in the world's x-z plane
  double distance_m = 0.0;   ///< from the camera centre
  double bearing_deg = 0.0;  ///< right of the optical axis positive
  int clock = 12;            ///< clock-face direction (12 = straight ahead)
  int points = 0;            ///< tracked points supporting the estimate
  Eigen::Matrix<double, 6, 6> covariance = Eigen::Matrix<double, 6, 6>::Zero();  ///< [p, v], world
};

}  // namespace dynanav
