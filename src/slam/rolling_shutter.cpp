#include "slam/rolling_shutter.hpp"

namespace dynanav {

SE3 motionOver(const CameraVelocity& velocity, double dt_s) {
  const double s = dt_s / velocity.interval_s;
  SE3 T = SE3::Identity();
  T.linear() = expSO3(s * velocity.omega);
  T.translation() = s * velocity.translation;
  return T;
}

void compensateRollingShutter(Features& f, const CameraVelocity& velocity, double readout_s) {
  if (readout_s <= 0.0 || velocity.interval_s <= 0.0 || f.size() == 0) return;
  const PinholeCamera& camera = *f.camera;
  const double bf = camera.bf();
  for (int i = 0; i < f.size(); ++i) {
    // The sensor row is the raw (distorted) one: that is the row the shutter read.
    const double dt = (f.keypoints[i].pt.y / camera.height - 0.5) * readout_s;
    const SE3 T_row_mid = motionOver(velocity, dt);  // mid-row camera -> row camera
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

void measureMotionBlur(Features& f, const CameraVelocity& velocity, double exposure_s,
                       double share) {
  f.blur_sigma_px.clear();
  if (exposure_s <= 0.0 || share <= 0.0 || velocity.interval_s <= 0.0 || f.size() == 0) return;
  const PinholeCamera& camera = *f.camera;
  // The camera at the exposure's start and end, relative to the keypoint's (re-timed) instant.
  const SE3 T_start_mid = motionOver(velocity, -0.5 * exposure_s);
  const SE3 T_end_mid = motionOver(velocity, 0.5 * exposure_s);
  f.blur_sigma_px.assign(f.points.size(), cv::Point2f(0.f, 0.f));
  for (int i = 0; i < f.size(); ++i) {
    const bool with_depth = f.hasDepth(i);
    const Vec3 p_mid =
        with_depth ? f.backproject(i) : camera.backproject(f.points[i].x, f.points[i].y, 1.0);
    // Without depth the point is taken as far away: only the rotation moves it.
    const auto seen_by = [&](const SE3& T) {
      return with_depth ? Vec3(T * p_mid) : Vec3(T.linear() * p_mid);
    };
    const Vec3 a = seen_by(T_start_mid), b = seen_by(T_end_mid);
    if (a.z() <= 0.0 || b.z() <= 0.0) continue;
    const Eigen::Vector2d sigma = share * (camera.project(b) - camera.project(a));
    f.blur_sigma_px[size_t(i)] = cv::Point2f(float(sigma.x()), float(sigma.y()));
  }
}

}  // namespace dynanav
