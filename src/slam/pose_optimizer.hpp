#pragma once
// Pose-only optimisation (ORB-SLAM2 Optimizer::PoseOptimization) with Ceres' TinySolver: the
// frame's pose is refined against its matched map points, fixed. Keypoints with depth give a
// 3-vector residual (u, v, u_right), the others a 2-vector; each is weighted by the inverse
// variance of its pyramid level, with a Huber loss. After each round every match is re-classified
// by chi2 (95 %: 5.991 for 2 dof, 7.815 for 3 dof); outliers are left out of the next round but can
// come back. The robust loss is dropped for the last rounds, as in ORB-SLAM2.
#include <vector>

#include "core/se3.hpp"

namespace dynanav {

/// The pose with its rotation re-projected onto SO(3). Poses are chained every frame (velocity
/// times last pose); without this, rounding makes the rotation part drift off orthonormal and the
/// chain amplifies it (Isometry3d::inverse() assumes R^-1 = R^T).
inline SE3 orthonormalized(const SE3& T) {
  return makeSE3(Quat(T.linear()).normalized(), T.translation());
}

struct PoseObservation {
  Vec3 p_world;
  double u = 0.0, v = 0.0;
  double u_right = -1.0;  ///< < 0: no depth (monocular residual)
  double inv_sigma2 = 1.0;
};

struct PoseCamera {
  double fx, fy, cx, cy, bf;
};

struct PoseOptimizerOptions {
  int rounds = 4;
  int iterations_per_round = 10;
};

/// chi2 = e^T Omega e of an observation at pose T_cw: its squared reprojection error over the
/// level's variance, (u, v) and with depth u_right (infinity behind the camera).
double reprojectionChi2(const PoseObservation& obs, const PoseCamera& camera, const SE3& T_cw);

/// Refines T_camera_world in place; `outlier` (resized to observations) gets the final
/// classification. Returns the number of inliers.
int optimizePose(const std::vector<PoseObservation>& observations, const PoseCamera& camera,
                 const PoseOptimizerOptions& options, SE3& T_camera_world,
                 std::vector<uint8_t>& outlier);

}  // namespace dynanav
