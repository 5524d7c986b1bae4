#pragma once
// Online estimate of the colour camera's rolling-shutter readout from the tracking residuals
// (issue 18). Bonn's Xtion, like most RGB-D cameras, has no published readout; fr1's 25 ms was
// found by a sweep over ATE, which needs ground truth. Here the readout is a parameter of the
// tracking residuals themselves: a keypoint in row v was seen s = v/H - 1/2 readouts after the
// middle row (slam/rolling_shutter), while the camera moved by its velocity, so its reprojection
// residual has a part J_pose * velocity * s * readout. A turn shears the image, which no rigid
// pose reproduces: that part of the residual is what measures the readout.
//
// The map is not free of the shutter either: a keyframe re-timed with readout R0 while the true one
// is R places its points off by (R - R0) * s_K * (its own motion), the same way as the current
// frame sees them when it moves alike; against such a map the shear cancels (this session's first
// version, which ignored it, read 4 ms for a true 25 ms in the simulated static room). So each map
// point's position is modelled as the mean over its observing keyframes of that shift (each
// keyframe keeps its motion and the readout it used), plus the shift of the keyframe's own pose,
// which a wrong readout biased as it biases the current frame's (each keyframe keeps that
// derivative); bundle adjustment mixes them much like that mean.
//
// The model is first order and bundle adjustment refines points and poses after it, so evidence
// gathered while re-timing with R0 reads R0 + g (R - R0) with a gain g < 1 (0.1-0.8 in the
// simulator: 3 ms in head turns, 20 ms in a static room for a true 25 ms; at R0 = R it is
// unbiased: 24.87-24.91 ms for a true 25 in the head turns, scripts/readout_results.sh). It is
// reported (stats.json rolling_shutter.estimate_ms: a check of the readout in use); the online mode
// estimates the readout in bundle adjustment instead, where the map is free to move with it
// (slam/readout_shear.hpp; session 8's staged iteration of this estimate needed most of a 10 s
// scene and missed a static room, docs/dynamics.md).
//
// Per frame: linearise the residuals of the matched inliers in (pose, readout) at the readout the
// pose was fitted with, weight them as pose optimisation does (pyramid level, Huber), and
// marginalise the pose (Schur complement), so whatever a pose change can explain is not counted
// as readout. Points seen by a keyframe whose motion is not known are left out. The frame gives a
// readout and its information; frames are pooled by information (a still camera gives ~none). The
// standard error comes from the frames' scatter, not from the pixel noise model, because the
// velocity and the matches carry errors of their own.
#include <cstdint>
#include <vector>

#include <opencv2/core.hpp>

#include "slam/frame.hpp"
#include "slam/rolling_shutter.hpp"

namespace dynanav {

/// One frame's measurement of the readout.
struct ReadoutEvidence {
  bool valid = false;
  double readout_s = 0.0;           ///< the frame's own estimate (any sign: noise may cross 0)
  double information_per_s2 = 0.0;  ///< 1 / variance under the pixel noise model (px^-2 s^-2)
  int points = 0;                   ///< inlier matches used
  /// How the frame's fitted pose moves per second of readout error (H_pose^-1 H_pose,readout):
  /// a keyframe keeps it, because the points it creates move with its pose.
  Eigen::Matrix<double, 6, 1> pose_shift_per_s = Eigen::Matrix<double, 6, 1>::Zero();
};

/// Evidence of `frame` (posed, matches and outlier flags set). `observed` are its keypoints'
/// measurements as read, before any re-timing (undistorted pixel and, with depth, the virtual
/// right coordinate: the residuals pose optimisation fits); `motion` the camera's own motion since
/// the last frame (interval <= 0: no evidence); `readout_used_s` the readout its keypoints were
/// re-timed with before the pose was fitted (0: not re-timed).
ReadoutEvidence readoutEvidence(const Frame& frame, const KeypointMeasurements& observed,
                                const CameraVelocity& motion, double readout_used_s);

/// Frames' evidence pooled by information.
class ReadoutEstimator {
 public:
  /// Frames with fewer inliers than this, or less information than `min_information_per_s2`
  /// (about 2 ms standard error each under the pixel model), are left out: a still or barely
  /// moving camera says nothing about the readout, and its estimate is all noise.
  static constexpr int kMinPoints = 30;
  static constexpr double kMinInformationPerS2 = 1.0 / (0.002 * 0.002);
  /// Frames before the standard error is trusted (the scatter of fewer is itself too noisy).
  static constexpr int kMinFrames = 20;

  void add(const ReadoutEvidence& evidence);
  /// Forgets the evidence (a new stage of the online iteration, see Tracker::readoutFor).
  void restart() { *this = ReadoutEstimator{}; }
  [[nodiscard]] int frames() const { return frames_; }
  /// Information-weighted mean of the frames' readouts (0 before any frame).
  [[nodiscard]] double readoutS() const;
  /// Standard error of readoutS() from the frames' weighted scatter and their effective number;
  /// infinite before kMinFrames frames.
  [[nodiscard]] double sigmaS() const;

 private:
  int frames_ = 0;
  double sum_w_ = 0.0, sum_w2_ = 0.0, sum_wx_ = 0.0, sum_wx2_ = 0.0;
};

}  // namespace dynanav
