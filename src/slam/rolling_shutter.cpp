#include "slam/rolling_shutter.hpp"

namespace dynanav {

namespace {
/// The share s of a motion given by its rotation vector and translation.
SE3 scaledMotion(const Vec3& omega, const Vec3& translation, double s) {
  SE3 T = SE3::Identity();
  T.linear() = expSO3(s * omega);
  T.translation() = s * translation;
  return T;
}
}  // namespace

SE3 motionOver(const CameraVelocity& velocity, double dt_s) {
  return scaledMotion(logSO3(velocity.T_current_last.linear()),
                      velocity.T_current_last.translation(), dt_s / velocity.interval_s);
}

void compensateRollingShutter(Features& f, const CameraVelocity& velocity, double readout_s) {
  if (readout_s <= 0.0 || velocity.interval_s <= 0.0 || f.size() == 0) return;
  const PinholeCamera& camera = *f.camera;
  const double bf = camera.bf();
  const Vec3 omega = logSO3(velocity.T_current_last.linear());  // once per frame, not per keypoint
  const Vec3& translation = velocity.T_current_last.translation();
  for (int i = 0; i < f.size(); ++i) {
    // The sensor row is the raw (distorted) one: that is the row the shutter read.
    const double dt = (f.keypoints[i].pt.y / camera.height - 0.5) * readout_s;
    const SE3 T_row_mid = scaledMotion(omega, translation, dt / velocity.interval_s);  // mid -> row
    if (f.hasDepth(i)) {
      const Vec3 p_mid = T_row_mid.inverse() * f.backproject(i);
      if (p_mid.z() <= 0.0) continue;
      const Eigen::Vector2d uv = camera.project(p_mid);
      f.points[i] = cv::Point2f(static_cast<float>(uv.x()), static_cast<float>(uv.y()));
      f.depth_m[i] = static_cast<float>(p_mid.z());
      f.u_right[i] = static_cast<float>(uv.x() - bf / p_mid.z());
    } else {
      const Vec3 ray_mid =
          T_row_mid.linear().transpose() * camera.backproject(f.points[i].x, f.points[i].y, 1.0);
      if (ray_mid.z() <= 0.0) continue;
      const Eigen::Vector2d uv = camera.project(ray_mid);
      f.points[i] = cv::Point2f(static_cast<float>(uv.x()), static_cast<float>(uv.y()));
    }
  }
  f.grid = FeatureGrid(f.points, f.bounds);
}

}  // namespace dynanav
