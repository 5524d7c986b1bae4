#include "dynamics/floor_plane.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace dynanav {

std::optional<CameraFloor> estimateFloorPlane(const cv::Mat& depth_m, const PinholeCamera& camera,
                                              const Vec3& up_camera,
                                              const CameraFloorOptions& options) {
  if (depth_m.empty() || depth_m.type() != CV_32F || up_camera.norm() < 1e-9 || options.step_px < 1)
    return std::nullopt;
  const Vec3 up = up_camera.normalized();
  std::vector<Vec3> points;
  const int first_row = int(std::lround((1.0 - options.lower_share) * depth_m.rows));
  for (int v = std::max(0, first_row) + options.step_px / 2; v < depth_m.rows; v += options.step_px)
    for (int u = options.step_px / 2; u < depth_m.cols; u += options.step_px) {
      const float z = depth_m.at<float>(v, u);
      if (std::isfinite(z) && z > 0.f) points.push_back(camera.backproject(u, v, z));
    }
  if (points.size() < 3) return std::nullopt;
  const double min_cos = std::cos(options.max_tilt_deg * M_PI / 180.0);
  std::mt19937_64 rng(options.seed);
  std::uniform_int_distribution<size_t> pick(0, points.size() - 1);
  int best_count = 0;
  Vec3 best_n = up;
  double best_offset = 0.0;
  for (int it = 0; it < options.iterations; ++it) {
    const Vec3 &a = points[pick(rng)], &b = points[pick(rng)], &c = points[pick(rng)];
    Vec3 n = (b - a).cross(c - a);
    if (n.norm() < 1e-9) continue;
    n.normalize();
    if (n.dot(up) < 0.0) n = -n;
    const double offset = n.dot(a);
    // Upward normal near the expected up, and the camera above the plane.
    if (n.dot(up) < min_cos || offset >= 0.0) continue;
    int count = 0;
    for (const Vec3& p : points) count += std::abs(n.dot(p) - offset) < options.inlier_band_m;
    if (count > best_count) best_count = count, best_n = n, best_offset = offset;
  }
  if (best_count < options.min_inlier_share * double(points.size())) return std::nullopt;
  // Least squares through the inliers: the normal is the direction of least spread.
  Vec3 mean = Vec3::Zero();
  std::vector<Vec3> inliers;
  for (const Vec3& p : points)
    if (std::abs(best_n.dot(p) - best_offset) < options.inlier_band_m) inliers.push_back(p);
  for (const Vec3& p : inliers) mean += p;
  mean /= double(inliers.size());
  Mat3 scatter = Mat3::Zero();
  for (const Vec3& p : inliers) scatter += (p - mean) * (p - mean).transpose();
  const Eigen::SelfAdjointEigenSolver<Mat3> eigen(scatter);
  Vec3 n = eigen.eigenvectors().col(0);
  if (n.dot(up) < 0.0) n = -n;
  CameraFloor plane;
  plane.normal_camera = n;
  plane.offset_m = n.dot(mean);
  if (plane.offset_m >= 0.0) return std::nullopt;
  return plane;
}

std::optional<CameraFloor> FloorAverage::update(const std::optional<CameraFloor>& fit_camera,
                                                const SE3& T_world_camera) {
  const Mat3 R = T_world_camera.linear();
  const Vec3 t = T_world_camera.translation();
  if (fit_camera) {
    // n_c . p_c = d_c with p_c = R^T (p_w - t): (R n_c) . p_w = d_c + (R n_c) . t.
    const Vec3 n_world = R * fit_camera->normal_camera;
    const double offset_world = fit_camera->offset_m + n_world.dot(t);
    const bool far = frames_ >= kSettledFrames &&
                     (std::acos(std::clamp(n_world.dot(normal_world_), -1.0, 1.0)) > kMaxTiltRad ||
                      std::abs(offset_world - offset_world_m_) > kMaxOffsetM);
    if (!far) {
      ++frames_;
      const double w = 1.0 / double(std::min(frames_, kMemoryFrames));
      normal_world_ = ((1.0 - w) * normal_world_ + w * n_world).normalized();
      offset_world_m_ = (1.0 - w) * offset_world_m_ + w * offset_world;
    }
  }
  if (frames_ == 0) return std::nullopt;
  CameraFloor out;
  out.normal_camera = R.transpose() * normal_world_;
  out.offset_m = offset_world_m_ - normal_world_.dot(t);
  if (out.offset_m >= 0.0) return std::nullopt;
  return out;
}

}  // namespace dynanav
