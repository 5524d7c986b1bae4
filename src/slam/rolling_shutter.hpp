#pragma once
// Rolling-shutter compensation for RGB-D keypoints. A rolling-shutter colour camera (the Kinect's
// and the Asus Xtion's) exposes its rows one after another over the readout time, so a keypoint
// in row v was seen (v/H - 1/2) * readout later than the image's middle row. While the camera
// turns or moves, the image is sheared; fitting one rigid pose to it biases the pose (on TUM
// fr1_xyz by up to 2-3 cm where the camera moves fast, docs/slam.md). ORB-SLAM2 ignores this.
//
// We move every keypoint's measurement (undistorted pixel, depth, virtual right coordinate) to
// where the camera would have seen it at the middle row's time, using the constant-velocity
// motion model the tracker already keeps. The pose then describes the whole image at one instant.
#include "core/se3.hpp"
#include "slam/features.hpp"

namespace dynanav {

/// Motion of the camera over one frame interval `interval_s`, as a rotation vector and a
/// translation: those of T_current_last, which maps the last frame's camera coordinates to the
/// current one's (the tracker's velocity).
struct CameraVelocity {
  Vec3 omega = Vec3::Zero();
  Vec3 translation = Vec3::Zero();
  double interval_s = 0.0;
  static CameraVelocity of(const SE3& T_current_last, double interval_s) {
    return {logSO3(T_current_last.linear()), T_current_last.translation(), interval_s};
  }
};

/// Camera motion from the middle row's time to `dt_s` seconds later, by scaling the velocity's
/// rotation vector and translation (first order; frame-to-frame motion is small).
SE3 motionOver(const CameraVelocity& velocity, double dt_s);

/// The keypoint measurements compensation changes, kept to re-time them again with a better
/// velocity (the tracker first uses the last pair's motion, then the current frame's own).
struct KeypointMeasurements {
  std::vector<cv::Point2f> points;
  std::vector<float> depth_m, u_right;
  static KeypointMeasurements of(const Features& f) { return {f.points, f.depth_m, f.u_right}; }
  void restoreInto(Features& f) const {
    f.points = points;
    f.depth_m = depth_m;
    f.u_right = u_right;
  }
};

/// Re-times f's keypoints to the middle row (see above) for a readout of `readout_s` seconds.
/// Keypoints with depth move with the full motion; those without are treated as far away
/// (rotation only). Rebuilds the feature grid. No-op for readout_s <= 0 or interval_s <= 0.
void compensateRollingShutter(Features& f, const CameraVelocity& velocity, double readout_s);

/// Each keypoint's motion blur: its streak is where the camera's motion carries its point over an
/// exposure of `exposure_s` centred on the keypoint's own time (end minus start, undistorted px),
/// and f.blur_sigma_px gets `share` of it. Keypoints without depth are treated as far away
/// (rotation only). Clears f.blur_sigma_px for exposure_s <= 0, share <= 0 or interval_s <= 0.
void measureMotionBlur(Features& f, const CameraVelocity& velocity, double exposure_s,
                       double share);

}  // namespace dynanav
