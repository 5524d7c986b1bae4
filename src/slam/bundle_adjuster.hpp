#pragma once
// Local bundle adjustment (ORB-SLAM2 Optimizer::LocalBundleAdjustment) in Ceres on a plain
// snapshot of the map, so it is testable alone and can be solved without holding the map lock.
// Fixed keyframes (those seeing local points from outside the window) anchor the gauge.
// Residuals as in pose optimisation: (u, v, u_right) with depth, (u, v) without, weighted by the
// level's inverse variance, Huber loss; after the first pass chi2 outliers are dropped and the
// rest is refined without the robust loss.
#include <cstdint>
#include <string>
#include <vector>

#include "core/se3.hpp"
#include "slam/pose_optimizer.hpp"

namespace dynanav {

struct BaKeyFrame {
  uint64_t id = 0;
  SE3 T_camera_world = SE3::Identity();
  bool fixed = false;
};

struct BaPoint {
  uint64_t id = 0;
  Vec3 p_world = Vec3::Zero();
};

struct BaObservation {
  int keyframe = 0;  ///< index into BaProblem::keyframes
  int point = 0;     ///< index into BaProblem::points
  int keypoint = 0;  ///< keypoint index in that keyframe (for writing results back)
  double u = 0.0, v = 0.0, u_right = -1.0, inv_sigma2 = 1.0;
  /// The motion blur's spread along the keypoint's streak (slam/observation_noise.hpp).
  Eigen::Vector2d blur_sigma_px = Eigen::Vector2d::Zero();
  /// Issue 18, a readout estimated jointly (BaProblem::estimate_readout): the keypoint was re-timed
  /// to its image's middle row with `readout_used_s`; a true readout R moves where the re-timed
  /// keypoint should be seen by (R - readout_used_s) * readout_px_per_s in (u, v, u_right): its
  /// row's time offset times the image motion of the point under its keyframe's own motion.
  double readout_used_s = 0.0;
  Vec3 readout_px_per_s = Vec3::Zero();
};

struct BaProblem {
  PoseCamera camera{};
  std::vector<BaKeyFrame> keyframes;
  std::vector<BaPoint> points;
  std::vector<BaObservation> observations;
  /// Issue 18: the colour camera's rolling-shutter readout as one more unknown shared by every
  /// observation (keypoints re-timed with a wrong readout shear the keyframes and the points they
  /// create alike; only the joint fit separates the shear from the map). `readout_s` is the
  /// starting value in and the estimate out.
  bool estimate_readout = false;
  double readout_s = 0.0;
};

struct BaOptions {
  int iterations_first = 5;
  int iterations_second = 10;
  std::string linear_solver = "sparse_schur";  ///< or "dense_schur"
};

struct BaResult {
  std::vector<uint8_t> outlier;  ///< per observation, after the final pass (chi2 or behind camera)
  double initial_rms_px = 0.0;   ///< RMS of the unweighted reprojection error before / after
  double final_rms_px = 0.0;
};

/// Optimises the non-fixed keyframe poses and all points in place.
BaResult bundleAdjust(BaProblem& problem, const BaOptions& options);

/// RMS reprojection error in pixels over (u, v) of the given observations (all when mask empty).
double reprojectionRms(const BaProblem& problem, const std::vector<uint8_t>& skip = {});

}  // namespace dynanav
