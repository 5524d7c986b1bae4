#pragma once
// The noise of a keypoint's measurement (u, v, u_right), shared by the pose-only optimisation and
// bundle adjustment: the pyramid level's isotropic variance (ORB-SLAM2's) plus, while the camera
// moves during the exposure, the motion blur's spread along the keypoint's streak. A corner
// smeared over a streak is found somewhere along it, as sharply as ever across it; weighing the
// whole residual down would throw away the across-streak half of what it measures.
#include <Eigen/Core>

#include "slam/features.hpp"

namespace dynanav {

/// The standard deviation of keypoint i's position along its streak, as a vector along it (px);
/// zero where its blur was not measured.
inline Eigen::Vector2d blurSigmaPx(const Features& f, int i) {
  if (f.blur_sigma_px.empty()) return Eigen::Vector2d::Zero();
  const cv::Point2f& s = f.blur_sigma_px[size_t(i)];
  return {s.x, s.y};
}

/// The inverse square root of the measurement's covariance sigma^2 I + b b^T, with sigma^2 the
/// level's variance and b the blur's spread (u_right moves with u: b = (bx, by, bx) with depth).
/// Its third row and column are unused without depth.
inline Eigen::Matrix3d measurementSqrtInformation(double inv_sigma2, const Eigen::Vector2d& blur_px,
                                                  bool with_depth) {
  const double inv_sigma = std::sqrt(inv_sigma2);
  const Eigen::Vector3d b(blur_px.x(), blur_px.y(), with_depth ? blur_px.x() : 0.0);
  const double b2 = b.squaredNorm();
  if (!(b2 > 0.0)) return inv_sigma * Eigen::Matrix3d::Identity();
  // sigma^2 (I + beta^2 n n^T), n = b / |b|: its inverse square root is
  // (I + (1 / sqrt(1 + beta^2) - 1) n n^T) / sigma (n n^T is a projector).
  const Eigen::Vector3d n = b / std::sqrt(b2);
  const double beta2 = b2 * inv_sigma2;
  return inv_sigma *
         (Eigen::Matrix3d::Identity() + (1.0 / std::sqrt(1.0 + beta2) - 1.0) * n * n.transpose());
}

}  // namespace dynanav
