#pragma once
// Rigid transform between two sets of matched 3D points (loop closing with RGB-D, where depth
// fixes the scale: ORB-SLAM2's Sim3Solver with scale fixed to 1). Minimal samples of 3 matches are
// solved in closed form (Horn 1987 / Umeyama 1991, via Eigen::umeyama without scale); the model
// with most inliers is refitted on all of them.
#include <cstdint>
#include <vector>

#include "core/se3.hpp"

namespace dynanav {

struct RigidRansacOptions {
  int iterations = 300;
  /// Inlier when |T * a - b| is below this fraction of b's depth (stereo-like: errors grow
  /// with distance) or `min_error_m`, whichever is larger.
  double relative_error = 0.03;
  double min_error_m = 0.02;
  int min_inliers = 20;
  uint64_t seed = 1;
};

struct RigidRansacResult {
  bool ok = false;
  SE3 T_b_a = SE3::Identity();  ///< maps a-points onto b-points
  std::vector<uint8_t> inlier;
  int inliers = 0;
};

/// `b_depth_m` is each b point's distance along its camera axis (for the error threshold); if
/// empty, |b| is used.
RigidRansacResult estimateRigidRansac(const std::vector<Vec3>& a, const std::vector<Vec3>& b,
                                      const RigidRansacOptions& options = {},
                                      const std::vector<double>& b_depth_m = {});

/// Least-squares rigid transform mapping a onto b (at least 3 non-collinear points).
SE3 fitRigid(const std::vector<Vec3>& a, const std::vector<Vec3>& b);

}  // namespace dynanav
