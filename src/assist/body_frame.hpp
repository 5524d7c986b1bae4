#pragma once
// The wearer's body frame (issue 14): where the wearer is and which way they walk. A head-worn
// camera turns with the head, but a warning about "2 o'clock" must be relative to where the
// wearer is going, so the heading is the smoothed walking direction from the camera trajectory,
// not the head's yaw. While the wearer stands still there is no walking direction; the heading
// is then the camera's forward axis projected on the ground (where the wearer faces).
// Frames: world = first camera (x right, y down, z forward); the ground plane is taken as the
// world x-z plane (the first camera roughly level, as a head-worn camera starts).
#include "core/config/assist.hpp"
#include "core/se3.hpp"

namespace dynanav {

struct BodyFrame {
  Vec3 origin_world = Vec3::Zero();        ///< the camera centre
  Vec3 forward_world = Vec3::UnitZ();      ///< unit, horizontal: the walking direction
  Vec3 right_world = Vec3::UnitX();        ///< unit, horizontal: forward turned 90 deg right
  Vec3 velocity_world_mps = Vec3::Zero();  ///< smoothed horizontal velocity of the wearer
  bool walking = false;                    ///< smoothed speed at least walking_speed_mps
  bool valid = false;                      ///< at least one tracked pose seen

  /// World point -> body frame (x right, z forward; y dropped: the ground plane).
  [[nodiscard]] Eigen::Vector2d toBody(const Vec3& p_world) const {
    const Vec3 d = p_world - origin_world;
    return {d.dot(right_world), d.dot(forward_world)};
  }
};

/// The world's vertical axis (y down) removed: a vector on the ground plane.
inline Vec3 horizontal(const Vec3& v) {
  return {v.x(), 0.0, v.z()};
}

/// Follows the camera trajectory frame by frame and keeps the smoothed walking velocity.
class BodyFrameTracker {
 public:
  explicit BodyFrameTracker(const AssistConfig& config) : config_(config) {}
  /// One frame: its stamp and camera pose; untracked frames keep the last body frame.
  const BodyFrame& update(double stamp_s, const SE3& T_world_camera, bool tracked);
  [[nodiscard]] const BodyFrame& current() const { return body_; }

 private:
  AssistConfig config_;
  BodyFrame body_;
  double last_stamp_s_ = 0.0;
  Vec3 last_origin_world_ = Vec3::Zero();
};

}  // namespace dynanav
