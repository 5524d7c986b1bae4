#pragma once
// Pose-only optimisation (ORB-SLAM2 Optimizer::PoseOptimization) with Ceres' TinySolver: the
// frame's pose is refined against its matched map points, fixed. Keypoints with depth give a
// 3-vector residual (u, v, u_right), the others a 2-vector; each is weighted by the inverse
// variance of its pyramid level, with a Huber loss. After each round every match is re-classified
// by chi2 (95 %: 5.991 for 2 dof, 7.815 for 3 dof); outliers are left out of the next round but can
// come back. The robust loss is dropped for the last rounds, as in ORB-SLAM2.
#include <vector>

#include "core/se3.hpp"
#include "slam/depth_surface.hpp"

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
  /// Spread of the keypoint's position along its motion-blur streak (px, a standard deviation
  /// as a vector along the streak; zero: no blur). It adds to the level's variance along the
  /// streak only: a blurred corner is found somewhere along it, but across it as sharply as ever.
  Eigen::Vector2d blur_sigma_px = Eigen::Vector2d::Zero();
};

/// The whitening of an observation's residual (u, v, u_right): the inverse square root of its
/// covariance, the level's isotropic variance plus the blur's along the streak (u_right moves with
/// u). Its third row and column are unused without depth.
Eigen::Matrix3d sqrtInformation(const PoseObservation& obs);

struct PoseCamera {
  double fx, fy, cx, cy, bf;
};

struct PoseOptimizerOptions {
  int rounds = 4;
  int iterations_per_round = 10;
};

/// Static depth as evidence beside the keypoints (slam/depth_surface.hpp): the last frame's static
/// samples, placed in the world by its pose, against this frame's surface. Each enters as its
/// point-to-plane distance over the depth noise at its range, with the same robust loss and
/// per-round outlier classification as the keypoints (chi2, 1 dof, 95 %). The samples' noise is
/// not independent (a structured-light sensor's errors span patches of pixels, and the reference
/// keyframe's own pose error is shared by all of them), so together they weigh as
/// `effective_samples` independent ones at most. The depth joins only where the keypoints alone
/// leave the camera's position loose: more than `min_sigma_m` along some direction.
struct DepthAlignment {
  const DepthSurface* surface = nullptr;
  const std::vector<Vec3>* points_world = nullptr;
  double effective_samples = 0.0;
  double min_sigma_m = 0.0;
  double max_distance_m = 0.2;  ///< a sample further from the surface is not associated

  [[nodiscard]] bool active() const {
    return surface && !surface->empty() && points_world && !points_world->empty() &&
           effective_samples > 0.0;
  }
};

/// chi2 = e^T Omega e of an observation at pose T_cw: its squared reprojection error over the
/// level's variance, (u, v) and with depth u_right (infinity behind the camera).
double reprojectionChi2(const PoseObservation& obs, const PoseCamera& camera, const SE3& T_cw);

/// The largest standard deviation (m) of the camera's position that the inlier observations
/// leave at T_camera_world (from their information matrix at the levels' sigmas; infinity when
/// they do not fix it).
double loosestTranslationSigmaM(const std::vector<PoseObservation>& observations,
                                const std::vector<uint8_t>& outlier, const PoseCamera& camera,
                                const SE3& T_camera_world);

/// Refines T_camera_world in place; `outlier` (resized to observations) gets the final
/// classification. Returns the number of inliers (keypoints; depth samples are not counted).
int optimizePose(const std::vector<PoseObservation>& observations, const PoseCamera& camera,
                 const PoseOptimizerOptions& options, SE3& T_camera_world,
                 std::vector<uint8_t>& outlier, const DepthAlignment& depth = {});

}  // namespace dynanav
