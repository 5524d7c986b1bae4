#pragma once
// SE(3) helpers on Eigen. Names carry frames: T_world_camera maps camera coordinates to world
// coordinates (p_world = T_world_camera * p_camera).
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace dynanav {

using SE3 = Eigen::Isometry3d;
using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
using Quat = Eigen::Quaterniond;

/// Pose from a translation and a (not necessarily normalised) quaternion.
inline SE3 makeSE3(const Quat& q, const Vec3& t) {
  SE3 T = SE3::Identity();
  T.linear() = q.normalized().toRotationMatrix();
  T.translation() = t;
  return T;
}

/// Rotation from an axis-angle vector (SO(3) exponential map).
inline Mat3 expSO3(const Vec3& omega) {
  const double angle = omega.norm();
  if (angle < 1e-12) return Mat3::Identity();
  return Eigen::AngleAxisd(angle, omega / angle).toRotationMatrix();
}

/// Axis-angle vector of a rotation (SO(3) logarithm).
inline Vec3 logSO3(const Mat3& R) {
  const Eigen::AngleAxisd aa(R);
  return aa.angle() * aa.axis();
}

/// Rotation angle of a rotation matrix in radians, robust near 0 and pi.
inline double rotationAngle(const Mat3& R) {
  const double c = std::clamp((R.trace() - 1.0) * 0.5, -1.0, 1.0);
  return std::acos(c);
}

/// The part of v in the plane whose unit normal is given (the floor's plane, with the floor's up:
/// people walk in it; a body's rise and sink is the rest).
inline Vec3 projectOntoPlane(const Vec3& v, const Vec3& unit_normal) {
  return v - unit_normal.dot(v) * unit_normal;
}

/// Pose update by a 6-vector (rho, omega) applied on the left: exp(xi) * T.
inline SE3 leftPerturb(const Eigen::Matrix<double, 6, 1>& xi, const SE3& T) {
  SE3 D = SE3::Identity();
  D.linear() = expSO3(xi.tail<3>());
  D.translation() = xi.head<3>();
  return D * T;
}

}  // namespace dynanav
