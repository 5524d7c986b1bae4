#pragma once
// Test helpers for rolling-shutter scenes: a camera velocity per 30 Hz frame, and where a camera
// whose rows are read out over `readout_s` sees a point.
#include "slam/rolling_shutter.hpp"

namespace dynanav::testing {

constexpr double kFrameInterval = 1.0 / 30.0;

inline CameraVelocity makeVelocity(const Vec3& omega_per_frame, const Vec3& t_per_frame) {
  SE3 T_current_last = SE3::Identity();
  T_current_last.linear() = expSO3(omega_per_frame);
  T_current_last.translation() = t_per_frame;
  return CameraVelocity::of(T_current_last, kFrameInterval);
}

/// Where a camera with readout `readout_s` sees p_mid (a point in the middle-row camera frame):
/// the row and the pose depend on each other, so iterate to the fixed point.
inline Vec3 seenByRow(const PinholeCamera& camera, const CameraVelocity& velocity, double readout_s,
                      const Vec3& p_mid) {
  Vec3 p_row = p_mid;
  for (int k = 0; k < 20; ++k) {
    const double row = camera.project(p_row).y();
    p_row = motionOver(velocity, (row / camera.height - 0.5) * readout_s) * p_mid;
  }
  return p_row;
}

}  // namespace dynanav::testing
