#pragma once
// Small derivatives the SLAM's own linearisations share (the readout estimates, triangulation).
#include <Eigen/Core>

#include "core/se3.hpp"

namespace dynanav {

/// [a]x: skewSymmetric(a) * b = a x b.
inline Mat3 skewSymmetric(const Vec3& a) {
  Mat3 S;
  S << 0.0, -a.z(), a.y(), a.z(), 0.0, -a.x(), -a.y(), a.x(), 0.0;
  return S;
}

/// d(u, v, u_right) / d(point in the camera frame) of the RGB-D projection u = fx x/z + cx,
/// v = fy y/z + cy and the virtual right coordinate u_right = u - bf/z.
inline Eigen::Matrix3d rgbdProjectionJacobian(double fx, double fy, double bf, const Vec3& p) {
  const double inv_z = 1.0 / p.z();
  Eigen::Matrix3d J;
  J << fx * inv_z, 0.0, -fx * p.x() * inv_z * inv_z,  //
      0.0, fy * inv_z, -fy * p.y() * inv_z * inv_z,   //
      fx * inv_z, 0.0, -fx * p.x() * inv_z * inv_z + bf * inv_z * inv_z;
  return J;
}

}  // namespace dynanav
